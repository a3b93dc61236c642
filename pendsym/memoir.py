"""What a memoir plug-in exports: one :class:`Memoir` describing it.

A memoir is a package (``derivations/<key>/``) whose ``__init__`` defines
``MEMOIR = Memoir(...)``.  The registry finds it by scanning the memoir
packages (see :mod:`pendsym.registry`); nothing under ``pendsym/`` names it.
See ``docs/adding-a-memoir.md``.
"""
from __future__ import annotations

from dataclasses import dataclass
from types import ModuleType
from typing import Callable

from .result import Spec


@dataclass(frozen=True)
class Section:
    """One section of a memoir: the module (or package) that builds its Specs.

    The section's source, and the engine and memoir modules it imports, are
    what its Results' cache keys cover (see :mod:`pendsym.keys`).  ``shared``: its
    checks compute the same costly truths (kept in the section's in-process caches),
    so they are scheduled in one worker, which computes each truth once.
    """

    module: str                  # dotted name of the module whose ``specs()`` gives the Specs
    title: str
    specs: tuple[Spec, ...]
    shared: bool = False

    @classmethod
    def of(cls, module: ModuleType, title: str, shared: bool = False) -> "Section":
        """The section built by ``module.specs()``."""
        return cls(module.__name__, title, tuple(module.specs()), shared)

    @property
    def ids(self) -> tuple[str, ...]:
        return tuple(s.id for s in self.specs)


@dataclass(frozen=True)
class Heading:
    """A heading of the report and the Results under it (by default, one per section)."""

    title: str
    ids: tuple[str, ...]


@dataclass(frozen=True)
class Memoir:
    """A memoir plug-in.

    ``affinity``: groups of Result ids whose checks share computations (run in one worker);
    ``cost``: relative time of the memoir's checks (the scheduler starts the costliest first);
    ``kernels``: whether its kernel declarations are ready to be emitted;
    ``headings``: the report's structure, when it differs from the sections;
    ``swing_correction``: the name of a generated kernel f(alpha, k) giving the memoir's correction to
    one swing's duration, which ``make bench`` sets beside the exact swing time;
    ``figures``: the report's figures (:class:`pendsym.figure.Figure`, not imported here so that the
    figures' module stays out of every Result's key), sampled by derive, each set after its Result.
    """

    key: str
    title: str
    sections: tuple[Section, ...]
    headings: tuple[Heading, ...] = ()
    affinity: tuple[tuple[str, ...], ...] = ()
    cost: float = 1.0
    kernels: bool = True
    swing_correction: str | None = None
    figures: tuple = ()

    @property
    def specs(self) -> tuple[Spec, ...]:
        return tuple(s for sec in self.sections for s in sec.specs)

    def check_groups(self) -> tuple[tuple[str, ...], ...]:
        """The groups of Results whose checks run in one worker: the affinity groups and the
        shared sections."""
        return self.affinity + tuple(sec.ids for sec in self.sections if sec.shared)

    def report_headings(self) -> tuple[Heading, ...]:
        return self.headings or tuple(Heading(sec.title, sec.ids) for sec in self.sections)

    def section_of(self, result_id: str) -> Section:
        for sec in self.sections:
            if result_id in sec.ids:
                return sec
        raise KeyError(result_id)


def headings_by(specs: tuple[Spec, ...], rules: tuple[tuple[str, Callable[[Spec], bool]], ...]) -> tuple[Heading, ...]:
    """Headings from (title, predicate) rules; a Spec goes under the first heading that takes it."""
    placed: set[str] = set()
    out = []
    for title, takes in rules:
        ids = tuple(s.id for s in specs if s.id not in placed and takes(s))
        placed |= set(ids)
        if ids:
            out.append(Heading(title, ids))
    return tuple(out)
