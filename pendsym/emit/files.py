"""Lay out generated files with Jinja; every file is headed by its sources and a content hash."""
from __future__ import annotations

from typing import Sequence

import jinja2

from ..io import content_hash
from . import kernels as kn

ENV = jinja2.Environment(loader=jinja2.PackageLoader("pendsym", "templates"), autoescape=False,
                         keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True,
                         undefined=jinja2.StrictUndefined)


def render(template: str, **ctx) -> str:
    """Render twice: the second time with the hash of the first (hash of the body, placeholder in)."""
    body = ENV.get_template(template).render(hash="<hash>", **ctx)
    return ENV.get_template(template).render(hash=content_hash(body), **ctx)


def _sources(ks: Sequence[kn.Kernel]) -> str:
    mods = sorted({k.result_id.rsplit(".", 1)[0] for k in ks})
    return ", ".join(mods)


def python_module(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.py.j2", memoir=memoir, sources=_sources(ks), names=[k.name for k in ks],
                  functions=[kn.py_function(k) for k in ks])


def c_source(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.c.j2", memoir=memoir, sources=_sources(ks), functions=[kn.c_function(k)[1] for k in ks])


def c_header(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.h.j2", memoir=memoir, sources=_sources(ks), protos=[(k, kn.c_function(k)[0]) for k in ks])


def c_standalone(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    """One translation unit (header inlined) for compiling in a scratch directory."""
    src = c_source(memoir, ks).replace(f'#include "{memoir}.h"\n', "")
    return src
