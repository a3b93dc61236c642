"""``python -m pendsym.solve.bench``: speed of ``pendsym solve`` and its answers beside a peer's.

Times the Duffing frequency to order 3 (derivation only, then with the verification), and
judges each frequency answer (pendsym's, and the ``asymptotics`` package's when it is
installed: it is never a dependency) by the same fitted-order check against the equation
integrated by mpmath.  Timings are CPU seconds of this process on this machine; they are
not reproducible to the byte, so nothing here is written under generated/ by make derive.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import time
from pathlib import Path

import sympy as sp

from . import frequency, solve
from . import verify as truth
from .problem import from_dict

DUFFING = {"variable": "u", "small": "eps", "phi": "eps*u**3", "order": 3,
           "initial": {"value": "A"}, "parameters": {"A": 0.5}}
CASES = [  # (label, pendsym problem, the peer's equation and conditions)
    ("Duffing, order 3", DUFFING, ("u'' + u + eps*u**3", ["u(0) = A", "u'(0) = 0"])),
    ("u'' + 4u + εu³, order 2", {**DUFFING, "k": "2", "order": 2}, ("u'' + 4*u + eps*u**3", ["u(0) = A", "u'(0) = 0"])),
    ("Duffing, u'(0) = B, order 2", {**DUFFING, "order": 2, "initial": {"value": "A", "velocity": "B"},
                                     "parameters": {"A": 0.5, "B": 0.3}},
     ("u'' + u + eps*u**3", ["u(0) = A", "u'(0) = B"])),
]


def _peer(eq: str, conds: list, order: int):
    """The peer's ω, or None when it is not installed; (ω, CPU s) otherwise."""
    try:
        from asymptotics import ODE       # optional: only the bench runs it
    except ImportError:
        return None
    t0 = time.process_time()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        sol = ODE(eq, small_param="eps", conditions=conds).expand_lindstedt(order=order)
    omega = sol.omega_expansion
    if not isinstance(omega, sp.Basic):           # never parse a string here either
        raise TypeError(f"the peer's ω is a {type(omega).__name__}, not a SymPy expression")
    return omega, time.process_time() - t0


def _judge(problem, omega: sp.Expr, expected: int):
    names = {s.name: s for s in problem.parameters} | {problem.small.name: problem.small}
    omega = omega.xreplace({f: names[f.name] for f in omega.free_symbols if f.name in names})
    f = sp.lambdify(problem.small, omega.subs(problem.values()), modules="mpmath")
    return truth.fitted(problem, truth=truth.frequency_truth(problem), answer=f, expected=expected, what="ω")


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None, help="write solve.json there")
    args = ap.parse_args(argv)
    rows = []
    t0, w0 = time.process_time(), time.perf_counter()
    frequency.solve(from_dict(DUFFING))
    derive_s, derive_w = time.process_time() - t0, time.perf_counter() - w0
    t0, w0 = time.process_time(), time.perf_counter()
    sol = solve(DUFFING)
    verify_s, verify_w = time.process_time() - t0, time.perf_counter() - w0
    print(f"Duffing ω to order 3: derivation {derive_s:.2f} CPU s ({derive_w:.2f} s wall); solve with "
          f"verification {verify_s:.1f} CPU s ({verify_w:.1f} s wall) (verified: {sol.verified})")
    for label, data, (eq, conds) in CASES:
        pr = from_dict(data)
        ans = frequency.solve(pr)
        mine = _judge(pr, ans.omega, ans.expected)
        row = {"problem": label, "pendsym_order": mine.order, "pendsym_passed": mine.passed,
               "expected_order": ans.expected}
        peer = _peer(eq, conds, pr.order)
        if peer is not None:
            ev = _judge(pr, peer[0], ans.expected)
            row.update(peer_omega=sp.sstr(peer[0]), peer_order=ev.order, peer_passed=ev.passed,
                       peer_cpu_s=round(peer[1], 2))
        rows.append(row)
        peer_txt = (f"asymptotics: fitted order {row['peer_order']} ({'right' if row['peer_passed'] else 'WRONG'}, "
                    f"{row['peer_cpu_s']} CPU s)" if peer is not None else "asymptotics: not installed")
        print(f"  {label:<30} pendsym: fitted order {mine.order} of {ans.expected} "
              f"({'right' if mine.passed else 'WRONG'});  {peer_txt}")
    if args.out:
        Path(args.out).mkdir(parents=True, exist_ok=True)
        (Path(args.out) / "solve.json").write_text(json.dumps(
            {"duffing_derive_cpu_s": round(derive_s, 2), "duffing_verified_cpu_s": round(verify_s, 1),
             "rows": rows}, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
