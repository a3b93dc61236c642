"""Compilation: the printed code made callable, so that what is measured is what is emitted.

C through the system compiler (``cc -std=c99 -O2``, libm only) into a shared library loaded
with ctypes; Python by compiling the printed function in a namespace holding only ``math``.
"""
from __future__ import annotations

import ctypes
import math
import subprocess
from pathlib import Path
from typing import Callable, Sequence

import sympy as sp

from ...result import KernelArg, Result
from .measure import Accuracy, measure
from .printing import definition, kernel_function
from .sampling import kernel_sample
from .supplied import helper_definitions

CC = ("cc", "-std=c99", "-O2", "-fPIC", "-shared")


def compile_c(c_text: str, workdir: Path) -> ctypes.CDLL:
    """Compile one C file into a shared library with the system compiler and load it."""
    src = workdir / "k.c"
    lib = workdir / "k.so"
    src.write_text(c_text)
    done = subprocess.run([*CC, "-o", str(lib), str(src), "-lm"], capture_output=True, text=True)
    if done.returncode:
        raise RuntimeError(f"cc failed: {done.stderr.strip()[:2000]}")
    return ctypes.CDLL(str(lib))


def c_callable(lib: ctypes.CDLL, name: str, nargs: int) -> Callable[..., float]:
    """The function `name` of nargs doubles in a loaded library."""
    fn = getattr(lib, name)
    fn.restype = ctypes.c_double
    fn.argtypes = [ctypes.c_double] * nargs
    return fn


def c_accuracy(lib: ctypes.CDLL, k, result: Result) -> Accuracy:
    """The accuracy of one compiled C kernel on its sample."""
    return measure(c_callable(lib, k.name, len(k.args)), result.derived, k.args,
                   kernel_sample(result.derived, k.args, k.name), k.reference or None)


def emitted_py(name: str, args: Sequence[KernelArg], expr: sp.Expr, domain: tuple = ()) -> Callable[..., float]:
    """The kernel's Python function exactly as emitted (templates/function.py.j2), with the definitions of
    the supplied helpers it calls (none for most forms), compiled here: the accuracy reported is that of
    the generated code, whose subexpressions and branches may round differently from the single
    expression the forms were ranked with."""
    namespace = {"math": math}
    text = "\n\n\n".join([*helper_definitions([expr], "py"), definition(kernel_function(name, args, expr, domain), "py")])
    exec(compile(text, f"<kernel {name}>", "exec"), namespace)   # our own generated code
    return namespace[name]
