"""``python -m pendsym.solve.bench``: speed of ``pendsym solve`` and its answers beside a peer's.

Times the Duffing frequency to order 3 (derivation only, then with the verification), then for
every problem of issue #16 and the session-8 problems solves it with pendsym (verified: its
checks) and, when the ``asymptotics`` package is installed (it is never a dependency), runs
the peer's method that applies (Lindstedt–Poincaré for a frequency, multiple scales for a
slow flow, the regular expansion for one swing) and judges its answer by the same fitted-order
check against the problem's own equation integrated by mpmath:

- a frequency ω: 2π/(time between the 1st and 3rd turning points), expected order as pendsym's;
- a slow flow: the peer's amplitude (A(T₁)² + B(T₁)²)^½ at the times of pendsym's slow-flow
  check (:func:`pendsym.solve.api.slow_checks`, given the amplitude): expected order 1;
- one swing: the first zero of the peer's θ'(t) after the start and |θ| there: expected order 2.

Where the peer has no applicable method or returns something that cannot be evaluated (an
unsolved function, an unevaluated integral), the row says so in one line.  Timings are CPU
seconds of this process on this machine; nothing here is written under generated/ by make derive.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import json
import signal
import time
from dataclasses import replace
from pathlib import Path

import mpmath as mp
import sympy as sp
from sympy.core.function import AppliedUndef

from . import frequency, solve
from . import verify as truth
from .api import slow_checks
from .problem import from_dict, load

PEER_SECONDS = 600       # the peer's time limit on one problem
DUFFING = {"variable": "u", "small": "eps", "phi": "eps*u**3", "order": 3,
           "initial": {"value": "A"}, "parameters": {"A": 0.5}}
PROBLEMS = Path(__file__).resolve().parents[2] / "problems"
# (label, pendsym problem (dict or file name), the peer's method, its equation and conditions, its order,
#  the peer's small parameter in pendsym's: None, or "square" when the peer expands in ε = α²)
CASES = [
    ("Duffing, order 3", DUFFING, "lindstedt", ("u'' + u + eps*u**3", ["u(0) = A", "u'(0) = 0"]), 3, None),
    ("u'' + 4u + εu³, order 2", {**DUFFING, "k": "2", "order": 2}, "lindstedt",
     ("u'' + 4*u + eps*u**3", ["u(0) = A", "u'(0) = 0"]), 2, None),
    ("Duffing, u'(0) = B, order 2", {**DUFFING, "order": 2, "initial": {"value": "A", "velocity": "B"},
                                     "parameters": {"A": 0.5, "B": 0.3}}, "lindstedt",
     ("u'' + u + eps*u**3", ["u(0) = A", "u'(0) = B"]), 2, None),
    # the pendulum θ = αx: x'' + x + Σ (−1)^j α^{2j} x^{2j+1}/(2j+1)! = 0, the peer's ε = α², order 5 = α¹⁰
    ("pendulum θ'' + sin θ = 0, period to α¹⁰", "pendulum.toml", "lindstedt",
     ("x'' + x - eps*x**3/6 + eps**2*x**5/120 - eps**3*x**7/5040 + eps**4*x**9/362880 - eps**5*x**11/39916800",
      ["x(0) = 1", "x'(0) = 0"]), 5, "square"),
    ("linear damping θ'' + 2εθ' + 4θ = 0", "damped.toml", "multiple_scales",
     ("u'' + 4*u + 2*eps*u'", ["u(0) = A", "u'(0) = 0"]), 1, None),
    ("linear damping, second order", "damped.toml", "multiple_scales",
     ("u'' + 4*u + 2*eps*u'", ["u(0) = A", "u'(0) = 0"]), 2, None),
    ("quadratic drag θ'' + εθ'|θ'| + 4θ = 0", "drag.toml", "multiple_scales",
     ("u'' + 4*u + eps*u'*Abs(u')", ["u(0) = A", "u'(0) = 0"]), 1, None),
    ("Coulomb friction θ'' + ε sign θ' + 4θ = 0", "coulomb.toml", "multiple_scales",
     ("u'' + 4*u + eps*sign(u')", ["u(0) = A", "u'(0) = 0"]), 1, None),
    ("van der Pol u'' + ε(u² − 1)u' + u = 0", "vanderpol.toml", "multiple_scales",
     ("u'' + u + eps*(u**2 - 1)*u'", ["u(0) = 1", "u'(0) = 0"]), 1, None),
    ("parametric resonance θ'' + 4θ + εθ cos 4t", "parametric.toml", "multiple_scales",
     ("u'' + 4*u + eps*u*cos(4*t)", ["u(0) = 1/10", "u'(0) = 0"]), 1, None),
    ("forcing at resonance θ'' + 4θ = ε cos 2t", "forced.toml", "multiple_scales",
     ("u'' + 4*u - eps*cos(2*t)", ["u(0) = 1/10", "u'(0) = 0"]), 1, None),
    ("θ'' + θ + ε sin θ = 0", {"small": "eps", "phi": "eps*sin(theta)", "initial": {"value": "A"},
                              "parameters": {"A": 1}}, "lindstedt",
     ("u'' + u + eps*sin(u)", ["u(0) = A", "u'(0) = 0"]), 1, None),
    ("lengthening pendulum l = l0(1 + at), one swing", "lengthening.toml", "regular",
     ("u'' + 2*a/(1 + a*t)*u' + 4/(1 + a*t)*u", ["u(0) = alpha", "u'(0) = 0"]), 1, None),
]


class PeerError(Exception):
    """The peer's answer cannot be judged; the message says why in one line."""


def _problem(data):
    return load(PROBLEMS / data) if isinstance(data, str) else from_dict(data)


def _alarm(signum, frame):
    raise TimeoutError


def _peer(method: str, eq: str, conds: list, order: int, small: str):
    """The peer's hierarchy and its CPU seconds; None when it is not installed."""
    try:
        from asymptotics import ODE       # optional: only the bench runs it
    except ImportError:
        return None
    t0 = time.process_time()
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(PEER_SECONDS)
    try:
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            ode = ODE(eq, small_param=small, conditions=conds)
            sol = getattr(ode, f"expand_{method}")(order=order)
    except TimeoutError:
        raise PeerError(f"expand_{method}(order={order}) did not finish in {PEER_SECONDS} s") from None
    except Exception as exc:  # the peer's own refusal, said as it is
        raise PeerError(f"expand_{method}(order={order}) raised {type(exc).__name__}: "
                        f"{str(exc).splitlines()[0][:160] if str(exc) else ''}") from None
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
    return sol, time.process_time() - t0


def _ours(problem, expr: sp.Expr, extra: dict) -> sp.Expr:
    """The peer's expression in pendsym's symbols (by name), the parameters given their values."""
    if not isinstance(expr, sp.Basic):            # never parse a string here either
        raise PeerError(f"the peer's answer is a {type(expr).__name__}, not a SymPy expression")
    expr = expr.doit() if expr.has(sp.Integral) else expr
    if expr.has(sp.Integral):
        raise PeerError("its answer keeps an unevaluated Integral: " + sp.sstr(expr)[:120])
    if expr.atoms(AppliedUndef):
        raise PeerError(f"its answer keeps an unsolved function {sorted(map(sp.sstr, expr.atoms(AppliedUndef)))[0]}"
                        f" (no law to evaluate)")
    names = {s.name: s for s in problem.parameters} | {problem.small.name: problem.small} | extra
    expr = expr.xreplace({f: names[f.name] for f in expr.free_symbols if f.name in names})
    return expr.subs(problem.values())


def _judge_omega(problem, omega, expected, square):
    omega = _ours(problem, omega, {"eps": problem.small ** 2} if square else {})
    if omega.free_symbols - {problem.small}:
        raise PeerError(f"its ω keeps {sorted(map(str, omega.free_symbols - {problem.small}))}")
    f = sp.lambdify(problem.small, omega, modules="mpmath")
    return truth.fitted(problem, truth=truth.frequency_truth(problem), answer=f, expected=expected, what="ω"), \
        sp.sstr(omega)


def _judge_slow(problem, sol):
    t = problem.t
    amp = sp.sqrt(sp.sympify(sol.amplitude_A) ** 2 + sp.sympify(sol.amplitude_B) ** 2)
    fast = "T_0" in {s.name for s in amp.free_symbols}
    try:
        amp = _ours(problem, amp, {"T_0": t, "T_1": problem.small * t, "t": t})
    except PeerError as exc:
        raise PeerError(("its slow amplitude depends on the fast time T_0 (not averaged over it); " if fast else "")
                        + str(exc)) from None
    if amp.free_symbols - {problem.small, t}:
        raise PeerError(f"its amplitude keeps {sorted(map(str, amp.free_symbols - {problem.small, t}))}")
    f = sp.lambdify((problem.small, t), amp, modules="mpmath")
    ((_, ev),) = slow_checks(problem, None, None, amplitude_of=lambda eps, at: [f(mp.mpf(eps), s) for s in at])
    return ev, sp.sstr(amp)


def _judge_swing(problem, sol):
    t = problem.t
    theta = _ours(problem, sol.expansion, {"t": t})
    th = sp.lambdify((problem.small, t), theta, modules="mpmath")
    dth = sp.lambdify((problem.small, t), sp.diff(theta, t), modules="mpmath")
    half = truth.unperturbed_period(problem) / 2

    def turn(eps):
        return mp.findroot(lambda s: dth(mp.mpf(eps), s), half)

    out = []
    for which, answer in (("duration", turn),
                          ("amplitude", lambda eps: abs(th(mp.mpf(eps), turn(eps))) - abs(th(mp.mpf(eps), 0)))):
        out.append([truth.fitted(problem, truth=truth.swing_truth(problem, which), answer=answer, expected=2,
                                 what=f"one swing: {which} from the first zero of the peer's θ'(t)")])
        if not out[-1][0].passed:      # the asymptotic regime may begin lower: the same check ten times lower
            low = replace(problem, small_range=tuple(repr(float(v) / 10) for v in problem.small_range))
            out[-1].append(truth.fitted(low, truth=truth.swing_truth(low, which), answer=answer, expected=2,
                                        what=f"one swing: {which} from the first zero of the peer's θ'(t)"))
    return out, sp.sstr(theta)


def _mine(sol) -> str:
    parts = []
    for a in sol.answers:
        ev = a.evidence
        if ev is None:
            continue
        got = "exact" if "| exact:" in (ev.note or "") else f"{ev.order} of {ev.expected_order:g}"
        parts.append(f"{a.name}: {got}" + ("" if a.holds else " FAILED"))
    return "; ".join(parts) or "no check"


def _verdict(ev) -> str:
    ok = ev.passed or (ev.order is not None and ev.order > ev.band[1])
    return f"{'right' if ok else 'WRONG'} (fitted order {ev.order} of {ev.expected_order:g})"


def row(label, data, method, peer_eq, order, square) -> dict:
    pr = _problem(data)
    t0 = time.process_time()
    sol = solve(pr)
    out = {"problem": label, "pendsym": _mine(sol), "pendsym_verified": sol.verified,
           "pendsym_cpu_s": round(time.process_time() - t0, 1)}
    small = "eps" if square else pr.small.name
    try:
        got = _peer(method, *peer_eq, order, small)
        if got is None:
            out["asymptotics"] = "not installed"
            return out
        peer, cpu = got
        out["asymptotics_cpu_s"] = round(cpu, 2)
        if method == "lindstedt":
            expected = next(a.evidence.expected_order for a in sol.answers if a.evidence is not None
                            and a.name.startswith("omega"))
            ev, form = _judge_omega(pr, peer.omega_expansion, expected, square)
            out["asymptotics"] = f"ω = {form}: {_verdict(ev)}"
        elif method == "multiple_scales":
            ev, form = _judge_slow(pr, peer)
            out["asymptotics"] = f"amplitude {form}: {_verdict(ev)}"
        else:
            evs, form = _judge_swing(pr, peer)
            out["asymptotics"] = f"θ = {form}: " + "; ".join(
                f"{w} {_verdict(e[0])}" + (f", on {pr.small.name} ∈ [{e[1].values[0][0]:g}, {e[1].values[-1][0]:g}] "
                                           f"{_verdict(e[1])}" if len(e) > 1 else "")
                for w, e in zip(("duration", "Δα"), evs))
    except PeerError as exc:
        out["asymptotics"] = f"cannot be judged: {exc}"
    except (ValueError, ZeroDivisionError, TypeError, mp.libmp.NoConvergence) as exc:
        out["asymptotics"] = f"cannot be judged: evaluating its answer raised {type(exc).__name__}: {str(exc)[:120]}"
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=None, help="write solve.json there")
    ap.add_argument("--only", nargs="*", default=(), help="labels (a prefix) of the problems to run")
    args = ap.parse_args(argv)
    t0, w0 = time.process_time(), time.perf_counter()
    frequency.solve(from_dict(DUFFING))
    derive_s, derive_w = time.process_time() - t0, time.perf_counter() - w0
    t0, w0 = time.process_time(), time.perf_counter()
    sol = solve(DUFFING)
    verify_s, verify_w = time.process_time() - t0, time.perf_counter() - w0
    print(f"Duffing ω to order 3: derivation {derive_s:.2f} CPU s ({derive_w:.2f} s wall); solve with "
          f"verification {verify_s:.1f} CPU s ({verify_w:.1f} s wall) (verified: {sol.verified})")
    rows = []
    for case in CASES:
        if args.only and not any(case[0].startswith(p) for p in args.only):
            continue
        r = row(*case)
        rows.append(r)
        print(f"{r['problem']}\n  pendsym ({r['pendsym_cpu_s']} CPU s): {r['pendsym']}\n  asymptotics"
              f"{' (' + str(r['asymptotics_cpu_s']) + ' CPU s)' if 'asymptotics_cpu_s' in r else ''}: "
              f"{r['asymptotics']}", flush=True)
    if args.out:
        Path(args.out).mkdir(parents=True, exist_ok=True)
        (Path(args.out) / "solve.json").write_text(json.dumps(
            {"duffing_derive_cpu_s": round(derive_s, 2), "duffing_verified_cpu_s": round(verify_s, 1),
             "rows": rows}, indent=1, ensure_ascii=False))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
