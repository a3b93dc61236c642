"""The text of a solution: answers, each with its evidence beside it."""
from __future__ import annotations

import sympy as sp


def _evidence(ans) -> list[str]:
    ev = ans.evidence
    if ev is None:
        return []
    verdict = ("passed, exact: the residual is at the rounding level at every point" if ev.passed and
               "| exact:" in (ev.note or "") else "passed" if ev.passed else "passed, above the band: the error falls faster than claimed"
               if ans.holds else "FAILED")
    out = [f"    check: {verdict} — fitted order {ev.order} in {ev.param} "
           f"(expected {ev.expected_order:g}, band {ev.band[0]:g}…{ev.band[1]:g}); truth confirmed to "
           f"{ev.confirm_digits:g} digits",
           f"    truth: {ev.truth}",
           f"    compared: {ev.note}"]
    if ev.params:
        out.append("    parameters: " + ", ".join(f"{k} = {v}" for k, v in ev.params))
    for p, r in ev.series:
        out.append(f"      {ev.param} = {p:<10g} |truth − answer| = {r:.4g}")
    return out


def text(sol) -> str:
    pr = sol.problem
    lines = [f"{pr.name}: {pr.theta.name}'' + ({sp.sstr(pr.k**2)})*{pr.theta.name} + "
             f"({sp.sstr(pr.phi)}) = 0,  {pr.theta.name}(0) = {sp.sstr(pr.theta_i)}, "
             f"{pr.theta.name}'(0) = {sp.sstr(pr.omega_i)}  [{pr.dtheta.name} = {pr.theta.name}']",
             f"method: {sol.method}"]
    if sol.finding:
        lines.append(sol.finding)
    lines += [f"note: {n}" for n in sol.notes]
    for ans in sol.answers:
        lines.append(f"  {ans.name} = {sp.sstr(ans.expr)}")
        lines += _evidence(ans)
        if sol.verified is not None and ans.evidence is None:
            lines.append("    not checked on its own (only the answers followed by a check are verified)")
    lines += [f"not verified: {u}" for u in sol.unverified]
    if sol.verified is None and sol.unverified:
        lines.append("NOT VERIFIED: no answer of this problem could be checked (said above)")
    elif sol.verified is None:
        lines.append("NOT VERIFIED: --no-verify (verification skipped)")
    elif sol.verified:
        lines.append("verified: every checked answer has at least its expected fitted order against the "
                     "integrated equation")
    else:
        lines.append("VERIFICATION FAILED: see the checks above")
    return "\n".join(lines)
