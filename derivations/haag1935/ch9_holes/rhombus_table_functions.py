"""Haag 1935, chapter IX, n°107–108, eqs. (334)–(342): the rhombus hole, Bessel's equation and the constants."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import rid, src
from . import rhombus_derivation as derivation, rhombus_printed as printed
from .rhombus_printed import READ_EPS_337, READ_MIDDLE, READ_Y

ENDS = (rid(343, "v0"), rid(343, "w0"), rid(343, "wl"))
# test functions for V(x), under which the printed and derived (335) are compared numerically
INSTANCES = tuple(((derivation.V, sp.Lambda(derivation.x, e)),) for e in (sp.exp(derivation.x / 3), derivation.x**3 - 1))


def exact(statement: str, transcription) -> checks.Proof:
    return checks.Proof(statement, holds=lambda derived: sp.simplify(derived - transcription()) == 0,
                        truth="exact algebra")


def solves_335(expr) -> bool:
    """The form satisfies (335) identically (SymPy's Bessel derivatives)."""
    x = derivation.x
    return sp.simplify(expr.diff(x, 2) - expr.diff(x) / x + expr) == 0


def wronskian_check() -> checks.All:
    """x·W is constant by (335) (exact), and W = 1/x at points by mpmath's Bessel functions."""
    def points(level, dps):
        for value in ("0.3", "2.5", "17", "140"):
            yield checks.Point(f"x = {value}", {"x": value}, 1 / sp.Float(value, 60))
    return checks.All((
        checks.Proof("d/dx[x(J_1 Y_0 − Y_1 J_0)] = 0 by Bessel's equations",
                     holds=lambda d: sp.simplify(sp.diff(derivation.x * d, derivation.x)) == 0),
        checks.Values(truth="1/x, with J_n, Y_n(today) of mpmath and Neumann's Y_n = (π/2)Y_n + (ln 2 − γ)J_n",
                      points=points, kind="value")))


def today_fails() -> checks.Values:
    def points(level, dps):
        for value in ("0.3", "2.5", "17"):
            yield checks.Point(f"x = {value}", {"x": value}, 1 / sp.Float(value, 60), denom=1 / sp.Float(value, 60))
    return checks.Values(truth="1/x against today's J_1 Y_0 − Y_1 J_0 = 2/(πx) (mpmath)", points=points,
                         fails_by="0.3", kind="value")


def specs() -> tuple[Spec, ...]:
    n107, n108 = "n°107", "n°108"
    definition = {"definition": True, "check": checks.Definition()}
    return (
        Spec(rid(334, "M"), "M = M0(1 + k|s|) (rhombus hole, origin at the middle)", src(n107, None), "M",
             lambda deps: derivation.stiffness(), printed=printed.stiffness, **definition),
        Spec(rid(334, "omega2"), "ω² = 1/M0", src(n107, "334"), r"\omega^2", lambda deps: derivation.omega_squared(),
             printed=printed.omega_squared, **definition),
        Spec(rid(334, "x"), "x = (2ω/k)√(1 + k|s|)", src(n107, "334"), "x",
             lambda deps: derivation.x_of(derivation.sigma), printed=printed.x_of_s, **definition),
        Spec(rid(335, "bessel"), "(9) for the inverted blade becomes v'' − v'/x + v = 0", src(n107, "335"),
             r"v'' - \frac{v'}{x} + v", lambda deps: derivation.bessel_equation(), deps=(rid(334, "x"),),
             printed=printed.bessel_equation, instances=INSTANCES,
             check=checks.Proof("the half s < 0 gives the same equation as s > 0",
                                holds=lambda d: sp.simplify(d - derivation.transformed_equation(-1)) == 0),
             note="M v'' + v = 0 (footnote (2) of n°107: M in absolute value, g → −g), with x of (334) on each half."),
        Spec(rid(336, "v"), "v = x[AJ_1(x) + BY_1(x)]", src(n107, "336"), "v",
             lambda deps: derivation.general_solution(), deps=(rid(335, "bessel"),), printed=printed.general_solution,
             readings=(READ_Y,), check=checks.Proof("the form satisfies (335) identically", holds=solves_335),
             note="dsolve gives x[C_1 J_1 + C_2 Y_1 (today)]; in Neumann's basis the constants are renamed linearly."),
        Spec(rid(336, "dvdx"), "dv/dx = x[AJ_0(x) + BY_0(x)]", src(n107, None), r"\frac{dv}{dx}",
             lambda deps: derivation.slope_in_x(), deps=(rid(336, "v"),), printed=printed.slope_in_x,
             check=exact("d/dx of (336) by SymPy's Bessel derivatives", printed.slope_in_x)),
        Spec(rid(336, "dxds"), "dv/ds = ε(dv/dx)·2ω²/(kx)", src(n107, None), r"\frac{dx}{ds}",
             lambda deps: derivation.ds_factor(), deps=(rid(334, "x"),), printed=printed.ds_factor,
             check=exact("d/ds of (334), 1 + k|s| = (kx/2ω)²", printed.ds_factor)),
        Spec(rid(339, "wronskian"), "J_1(x)Y_0(x) − Y_1(x)J_0(x) = 1/x (Neumann's Y_n)", src("n°108, footnote of (339)", None),
             r"J_1Y_0 - Y_1J_0", lambda deps: derivation.wronskian(), printed=printed.wronskian, readings=(READ_Y,),
             check=wronskian_check(),
             note="Haag's Y_n is Neumann's, (π/2)Y_n(today) + (ln 2 − γ)J_n; only the scale π/2 matters below."),
        Spec(rid(339, "wronskian_today"), "with today's Y_n the quoted Wronskian fails (2/(πx))",
             src("n°108, footnote of (339)", None), r"J_1Y_0 - Y_1J_0\ \text{(today's } Y)",
             lambda deps: derivation.wronskian(second=sp.bessely), check=today_fails(),
             note="A counterexample: it fixes the convention (today's Y_n is off by the factor 2/π)."),
        Spec(rid(337, "A"), "A of v", src(n107, "337"), "A",
             lambda deps: derivation.v_constant_haag("A"), deps=(rid(336, "v"),),
             printed=printed.v_constant_A, defs=printed.DEFS, readings=(READ_EPS_337, READ_Y),
             check=checks.Chain(ENDS[:1])),
        Spec(rid(337, "B"), "B of v", src(n107, "337"), "B",
             lambda deps: derivation.v_constant_haag("B"), deps=(rid(336, "v"),),
             printed=printed.v_constant_B, defs=printed.DEFS, readings=(READ_EPS_337, READ_Y),
             check=checks.Chain(ENDS[:1])),
        Spec(rid(338, "D"), "D = Y_1(x_0)J_0(x_1) − Y_0(x_1)J_1(x_0)", src(n107, "338"), "D",
             lambda deps: derivation.D_definition(), printed=printed.D_definition, **definition),
        Spec(rid(339, "middle"), "w continuous at the middle: A''J_0(x_0) + B''Y_0(x_0)", src(n108, None),
             r"A''J_0(x_0) + B''Y_0(x_0)",
             lambda deps: derivation.middle_slope(), deps=(rid(336, "dxds"),),
             printed=printed.middle_slope, readings=(READ_MIDDLE, READ_Y), check=checks.Chain(ENDS[1:])),
        Spec(rid(339, "A2"), "A'' from A', B' at the middle", src(n108, "339"), "A''",
             lambda deps: derivation.as_functions(derivation.continuation()[derivation.A2]), deps=(rid(339, "wronskian"),),
             printed=printed.continuation_A2, readings=(READ_Y,), check=checks.Chain(ENDS[1:])),
        Spec(rid(339, "B2"), "B'' from A', B' at the middle", src(n108, "339"), "B''",
             lambda deps: derivation.as_functions(derivation.continuation()[derivation.B2]), deps=(rid(339, "wronskian"),),
             printed=printed.continuation_B2, readings=(READ_Y,), check=checks.Chain(ENDS[1:])),
        Spec(rid(340, "A1"), "A' of w (s < 0)", src(n108, "340"), "A'", lambda deps: derivation.w_constant("A'"),
             deps=(rid(339, "A2"), rid(339, "B2")), printed=printed.w_constant_A1, defs=printed.DEFS,
             check=checks.Chain(ENDS[1:2])),
        Spec(rid(340, "B1"), "B' of w (s < 0)", src(n108, "340"), "B'", lambda deps: derivation.w_constant("B'"),
             deps=(rid(339, "A2"), rid(339, "B2")), printed=printed.w_constant_B1, defs=printed.DEFS,
             check=checks.Chain(ENDS[1:2])),
        Spec(rid(341, "Dp"), "D' = Y_0(x_0)J_0(x_1) − Y_0(x_1)J_0(x_0)", src(n108, "341"), "D'",
             lambda deps: derivation.D_prime_definition(), printed=printed.D_prime_definition, **definition),
        Spec(rid(342, "A2"), "A'' of w (s > 0)", src(n108, "342"), "A''", lambda deps: derivation.w_constant("A''"),
             deps=(rid(340, "A1"), rid(340, "B1")), printed=printed.w_constant_A2, defs=printed.DEFS,
             check=checks.Chain(ENDS[2:])),
        Spec(rid(342, "B2"), "B'' of w (s > 0)", src(n108, "342"), "B''", lambda deps: derivation.w_constant("B''"),
             deps=(rid(340, "A1"), rid(340, "B1")), printed=printed.w_constant_B2, defs=printed.DEFS,
             check=checks.Chain(ENDS[2:])),
    )
