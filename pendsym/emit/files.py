"""Lay out generated files with Jinja; every file is headed by its sources and a content hash.

The functions of a memoir's file are its kernels, and the parts that several of them share
(:func:`.kernels.share`), each printed once; docstrings and comments give each kernel's own
figures, and the accuracy contract is docs/kernel-accuracy.md.
"""
from __future__ import annotations

import functools
from typing import Sequence

from ..io import content_hash
from . import kernels as kn
from .kernels import supplied
from .kernels.arrays import numpy_definition
from .layout import ENV


def render(template: str, **ctx) -> str:
    """Render twice: the second time with the hash of the first (hash of the body, placeholder in)."""
    body = ENV.get_template(template).render(hash="<hash>", **ctx)
    return ENV.get_template(template).render(hash=content_hash(body), **ctx)


def _sources(ks: Sequence[kn.Kernel]) -> str:
    mods = sorted({k.result_id.rsplit(".", 1)[0] for k in ks})
    return ", ".join(mods)


def _functions(ks: Sequence[kn.Kernel]) -> tuple[kn.Function, ...]:
    """The file's functions in order: the kernels, each after the shared parts it calls."""
    return kn.share(tuple(kn.kernel_function(k.name, k.args, k.expr, k.domain) for k in ks))


def _definitions(ks: Sequence[kn.Kernel], lang: str, docs: bool) -> list[str]:
    """Every function of the file printed in lang; with `docs`, the kernels' docstrings (the
    parts always carry theirs)."""
    doc = {k.name: k.docstring() for k in ks} if docs else {}
    emit = numpy_definition if lang == "py" else functools.partial(kn.definition, lang=lang)   # Python: numpy arrays too
    return [*supplied.helper_definitions([k.expr for k in ks], lang),     # helpers of supplied forms, once
            *[emit(f, doc=kn.part_doc(f) if f.callers else doc.get(f.name, "")) for f in _functions(ks)]]


def python_module(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.py.j2", memoir=memoir, sources=_sources(ks), names=[k.name for k in ks],
                  functions=_definitions(ks, "py", docs=True), contract=kn.CONTRACT)


def c_source(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.c.j2", memoir=memoir, sources=_sources(ks), functions=_definitions(ks, "c", docs=False),
                  contract=kn.CONTRACT, preamble=supplied.c_preamble([k.expr for k in ks]))


def c_header(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    return render("kernels.h.j2", memoir=memoir, sources=_sources(ks), contract=kn.CONTRACT,
                  protos=[(k.docstring(), kn.prototype(kn.kernel_function(k.name, k.args, k.expr, k.domain), "c")) for k in ks])


def c_standalone(memoir: str, ks: Sequence[kn.Kernel]) -> str:
    """One translation unit (header inlined) for compiling in a scratch directory."""
    src = c_source(memoir, ks).replace(f'#include "{memoir}.h"\n', "")
    return src
