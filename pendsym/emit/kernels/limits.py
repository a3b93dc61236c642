"""The accepted domain of a kernel: its declared box, and down to 0 for the hard argument where
the form as emitted gives the limit there.

A geometric argument (``log=True``, lo > 0) such as u is declared from lo = 1e-6, but many
kernels have a finite limit as u → 0 (v_0 → λ/2, β_1 → 0) and a caller may pass u = 1e-300
or u = 0.  The emitted code is tried there (:data:`TINY`) at seeded values of the other
arguments, against the derived form at enough digits for its cancellation (:func:`ref_dps`);
where it holds the bound at every such point, the accepted domain of that argument reaches
down to 0 (the deep audit then samples (0, lo) as well); elsewhere below lo is a domain error.
"""
from __future__ import annotations

import math
import random
from typing import Sequence

import mpmath as mp
import sympy as sp

from ...result import KernelArg
from .leaves import hard_argument
from .measure import BOUND, ref_dps

# 0, subnormals, then every third decade and a seeded point inside each (a sparser list let through
# F at u = 2.8e-65 and F_max at α = 1.2e-157: the accepted domain must be measured as densely as the audit)
TINY = (0.0, 5e-324, 1e-320, 1e-310) + tuple(m * 10.0 ** -k for k in range(306, 6, -3) for m in (1.0, 2.8))
TRIES = 4             # seeded values of the other arguments at each tiny value
LIMIT_AT = (1e-40, 1e-80)   # the limit at 0: the derived form at 1e-80, or 0 where it falls by 1e-30 from 1e-40


def accepted_domain(expr: sp.Expr, args: Sequence[KernelArg], seed: str, form: sp.Expr) -> tuple:
    """((lo, hi), …) of each argument: the declared range, with lo = 0 for the hard argument where
    the emitted form holds the bound at every tiny value (0 included: there the reference is the
    derived form at LIMIT_AT, where the even or finite limit is reached)."""
    dom = [(a.lo, a.hi) for a in args]
    hard = hard_argument(expr, args)
    if hard is None:
        return tuple(dom)
    from .compile import emitted_py          # (compile imports this module's users)
    i = list(args).index(hard)
    dom[i] = (0.0, hard.hi)
    fn = emitted_py(seed, args, form, tuple(dom))
    syms = [next(s for s in expr.free_symbols if s.name == a.name) for a in args]
    f = sp.lambdify(syms, expr, modules="mpmath", cse=True)
    rng = random.Random(seed + ":limits")
    for x in TINY:
        for _ in range(TRIES):
            p = [rng.uniform(a.lo, a.hi) if not a.log else math.exp(rng.uniform(math.log(a.lo), math.log(a.hi)))
                 for a in args]
            p[i] = x
            at = list(p)
            at[i] = x if x > 0 else LIMIT_AT[1]
            if not _holds(fn, f, p, at, zero=x == 0 and _vanishes(f, p, i)):
                return tuple((a.lo, a.hi) for a in args)
    return tuple(dom)


def _vanishes(f, p: list, i: int) -> bool:
    """The derived form tends to 0 as argument i → 0 (it falls by 1e-30 from 1e-40 to 1e-80)."""
    values = []
    for x in LIMIT_AT:
        at = list(p)
        at[i] = x
        with mp.workdps(ref_dps(at)):
            values.append(abs(f(*[mp.mpf(v) for v in at])))
    return values[1] <= mp.mpf(10) ** -30 * values[0]


def _holds(fn, f, p: list, at: list, zero: bool = False) -> bool:
    """The kernel at p holds the bound against the derived form at `at` (with `zero`: the limit
    is 0, and the kernel must give below 1e-300 in magnitude)."""
    try:
        got = float(fn(*p))
    except (ValueError, OverflowError, ZeroDivisionError):
        return False
    if zero:
        return math.isfinite(got) and abs(got) < 1e-300
    with mp.workdps(ref_dps(at)):
        xs = [mp.mpf(v) for v in at]
        true = f(*xs)
        if not math.isfinite(got) or not mp.isfinite(true):
            return False
        if true == 0:
            return abs(got) < 1e-300
        # in ulp of the true value, a subnormal one included (ulp 5e-324, as make audit measures it):
        # "below 1e-300 passes" let through F_max at α = 1e-156, 1.5e4 ulp (the subnormal sin²(α/2)
        # times 4ghm/l); no κ here: its forward differences are taken at fewer digits than such points need
        return abs(mp.mpf(got) - true) <= BOUND * mp.mpf(math.ulp(float(true)))
