"""Shared fixtures: the repository root and the generated directory."""
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def generated() -> Path:
    return ROOT / "generated"
