"""Haag 1935, chapter IX, n°109–110, eqs. (343)–(346): the rhombus hole's end values, (345) and G_2."""
from __future__ import annotations

import mpmath as mp
import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import limits, rhombus_derivation as derivation, rhombus_printed as printed, rhombus_truth as truth
from .rhombus_printed import READ_346_X, READ_OMEGA_W, READ_VK, READ_W0, READ_WK, READ_Y, READ_Y0

CONSTANTS = (rid(340, "A1"), rid(340, "B1"), rid(342, "A2"), rid(342, "B2"))
G2_NOTE = ("Haag takes dz/dx = 1 at x_1 where w'(λ/2) = 1 gives dz/dx = kx_1/(2ω²) (dx/ds = 2ω²/(kx), n°107): his "
           "G_2 has ω²/k − ½(D_1/D + D'_1/D') where the derivation has 1/k + λ/2 − (kx_1/4ω²)(D_1/D + D'_1/D'); "
           "the printed terms ω²/k (1/length) and ½(…) (a pure number) are not lengths, G_2 is.")


def identity_check() -> checks.Values:
    """D_1 D' − D D'_1 of the definitions, each Bessel value by mpmath, against the derived 1/(x_0 x_1)."""
    D, Dp, D1, D1p = derivation.D_symbols()
    lhs = (D1 * Dp - D * D1p).subs(dict(derivation.D_definitions()))

    def points(level, dps):
        for case in truth.CASES[level]:
            env = truth.environment(*case)
            from pendsym import verify
            with mp.workdps(dps + 10):
                yield checks.Point(f"(M0, k, λ) = ({', '.join(case)})", env, verify.value_at(lhs, env))
    return checks.Values(truth="D_1 D' − D D'_1 from its definitions (338), (341), (344), mpmath Bessel functions",
                         points=points, kind="value")


def specs() -> tuple[Spec, ...]:
    n109, n110 = "n°109", "n°110"
    definition = {"definition": True, "check": checks.Definition()}
    d = printed.DEFS
    return (
        Spec(rid(343, "v0"), "v_0 = −v_λ of the rhombus blade", src(n109, "343"), "v_0",
             lambda deps: derivation.v_end(), deps=(rid(337, "A"), rid(337, "B")), printed=printed.v0, defs=d,
             readings=(READ_Y,), check=truth.on_rhombus("v0")),
        Spec(rid(343, "vl"), "v_λ = −v_0", src(n109, "343"), r"v_\lambda", lambda deps: derivation.v_end_bottom(),
             deps=(rid(337, "A"), rid(337, "B")), printed=printed.vl, defs=d, readings=(READ_VK, READ_Y),
             check=truth.on_rhombus("vl")),
        Spec(rid(343, "w0"), "w_0 of the rhombus blade", src(n109, "343"), "w_0",
             lambda deps: derivation.w_end("0"), deps=CONSTANTS[:2], printed=printed.w0_end, defs=d,
             readings=(READ_W0, READ_Y), check=truth.on_rhombus("w0")),
        Spec(rid(343, "wl"), "w_λ of the rhombus blade", src(n109, "343"), r"w_\lambda",
             lambda deps: derivation.w_end("l"), deps=CONSTANTS[2:], printed=printed.wl_end, defs=d,
             readings=(READ_WK, READ_Y), check=truth.on_rhombus("wl")),
        Spec(rid(344, "D1"), "D_1 = Y_1(x_0)J_1(x_1) − J_1(x_0)Y_1(x_1)", src(n109, "344"), "D_1",
             lambda deps: derivation.D1_definition(), printed=printed.D1_definition, **definition),
        Spec(rid(344, "D1p"), "D'_1 = Y_0(x_0)J_1(x_1) − Y_1(x_1)J_0(x_0)", src(n109, "344"), "D'_1",
             lambda deps: derivation.D1_prime_definition(), printed=printed.D1_prime_definition, **definition),
        Spec(rid(345, "identity"), "D_1 D' − D D'_1 = 1/(x_0 x_1) ((16) for the rhombus blade)", src(n109, "345"),
             r"D_1D' - DD'_1", lambda deps: derivation.identity_345(), deps=(rid(339, "wronskian"),),
             printed=printed.identity_345, check=identity_check(),
             note="Derived by expanding D_1 D' − D D'_1: it is the product of the Wronskians at x_0 and x_1."),
        # ---------------------------------------------------------------- n°110
        Spec(rid(346, "G2_definition"), "G_2 = ∫ w²/M ds over −λ/2 ≤ s ≤ λ/2 (gravity pendulum)", src(n110, None),
             "G_2", lambda deps: sp.Symbol("G_2"), printed=lambda: sp.Symbol("G_2"), readings=(READ_OMEGA_W,),
             note="The sensitivity integral G_2 of (79) with K = 0, M in absolute value (footnote (2) of n°107).",
             **definition),
        Spec(rid(346, "jacobian"), "w²/M ds = (2ω²/k) w²/x dx", src(n110, None), r"\frac{1}{M}\frac{ds}{dx}",
             lambda deps: derivation.jacobian_in_x(), deps=(rid(334, "x"),), printed=printed.jacobian_in_x,
             check=checks.Proof("(1/M)(ds/dx) = 2ω²/(kx) exactly",
                                holds=lambda e: sp.simplify(e - printed.jacobian_in_x()) == 0)),
        Spec(rid(346, "primitive"), "∫ v²/x dx = (v² + v'²)/2 − vv'/x for every solution of (335)", src(n110, None),
             r"\int \frac{v^2}{x}dx", lambda deps: derivation.integral_identity(), deps=(rid(335, "bessel"),),
             printed=printed.integral_identity,
             check=checks.Proof("d/dx of the primitive is v²/x when v'' = v'/x − v",
                                holds=lambda F: _primitive_holds(F)),
             note="Derived by the ansatz av² + bv'² + cvv'/x; Haag says “on vérifie facilement”."),
        Spec(rid(346, "y_half"), "∫_{x_0}^{x_1} y²/x dx", src(n110, None), r"\int_{x_0}^{x_1}\frac{y^2}{x}dx",
             lambda deps: derivation.half_integral("y"), deps=(rid(346, "primitive"),), printed=printed.half_integral_y,
             readings=(READ_OMEGA_W,), check=checks.Chain((rid(346, "G2_intermediate"),))),
        Spec(rid(346, "z_half"), "∫_{x_0}^{x_1} z²/x dx", src(n110, None), r"\int_{x_0}^{x_1}\frac{z^2}{x}dx",
             lambda deps: derivation.half_integral("z"), deps=(rid(346, "primitive"),), printed=printed.half_integral_z,
             readings=(READ_OMEGA_W,), check=checks.Chain((rid(346, "G2_intermediate"),)), note=G2_NOTE),
        Spec(rid(346, "y0"), "y_0 = z_0 at the middle", src(n110, None), "y_0",
             lambda deps: derivation.middle_value("y0"), deps=CONSTANTS[:2],
             printed=printed.middle_value, defs=d, readings=(READ_Y0,),
             check=checks.Chain((rid(346, "G2_intermediate"),))),
        Spec(rid(346, "y0p"), "y'_0 = −z'_0 at the middle", src(n110, None), "y'_0",
             lambda deps: derivation.middle_value("y0p"), deps=CONSTANTS[:2],
             printed=printed.middle_slope_value, defs=d, check=checks.Chain((rid(346, "G2_intermediate"),))),
        Spec(rid(346, "G2_intermediate"), "G_2 with w_0, w_λ (before (346))", src(n110, None), "G_2",
             lambda deps: derivation.G2_intermediate(), deps=(rid(346, "y_half"), rid(346, "z_half"), rid(346, "y0")),
             printed=printed.G2_intermediate, defs=d, readings=(READ_OMEGA_W,),
             check=truth.on_rhombus("G2", with_ends=True), note=G2_NOTE),
        Spec(rid(346, "G2"), "G_2 of the rhombus blade", src(n110, "346"), "G_2", lambda deps: derivation.G2_final(),
             deps=(rid(346, "G2_intermediate"), rid(343, "w0"), rid(343, "wl"), rid(345, "identity")),
             printed=printed.G2_346, defs=d, readings=(READ_346_X, READ_Y), check=truth.on_rhombus("G2"),
             note=G2_NOTE),
        # ---------------------------------------------------------------- the hole vanishing
        *(Spec(rid(343 if name != "G2" else 346, f"{name}_no_hole"), f"{name} of the rhombus blade → uniform as k → 0",
               src("n°107–110 (limit k → 0)", None), {"v0": "v_0", "w0": "w_0", "wl": r"w_\lambda", "G2": "G_2"}[name],
               lambda deps, name=name: limits.uniform(name), check=truth.uniform_limit(name), show_values=name == "G2",
               note="The formula is the inverted uniform blade (dsolve, cf. (313)); the truth the rhombus blade at k.")
          for name in ("v0", "w0", "wl", "G2")),
    )


def _primitive_holds(F) -> bool:
    val, der = sp.symbols("v v'", real=True)
    x = derivation.x
    dF = sp.diff(F, val) * der + sp.diff(F, der) * (der / x - val) + sp.diff(F, x)
    return sp.simplify(dF - val**2 / x) == 0
