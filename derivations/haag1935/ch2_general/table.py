"""Haag 1935, chapter II, n°26–30, eqs. (88)–(114): the Results, joining derivation, print and truth."""
from __future__ import annotations

from pendsym import checks
from pendsym.result import Spec
from ..ch2_common import eps1, eps_bar, eps_blade, dX
from ..common import READ_VW, rid, src, step
from ..symbols import s, varphi
from . import derivation, printed, truth
from .printed import (READ_101, READ_107, READ_108, READ_94, READ_EPS1_AS_4, READ_EPS_LAMBDA, READ_EPS_PRIME, READ_H4,
                      READ_SIGMA, READ_ZP)

PERIOD = (rid(111, "dT"), rid(112, "Qp"))
THROUGH_PERIOD = checks.Chain(PERIOD)
EXACT = "symbolic proof (SymPy)"


def specs() -> tuple[Spec, ...]:
    """The Results of n°26–30 in the order of their equation numbers ((95)–(101) by the variation of constants,
    (113), (115) and the remarks of n°30–31 from :mod:`.table_variation`)."""
    from .table_variation import specs as more
    both = _specs() + more()
    return tuple(sorted(both, key=lambda spec: int(spec.id.split(".")[1][2:])))


def _specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°26
        Spec(rid(88, "X"), "1 − X + ε1 = 0", src(26, "88"), "0", step(derivation.eq88), printed=printed.eq88,
             check=checks.Definition(), definition=True,
             note="Defines ε1: (4) is 1 − X − ẍ_G/g = 0 (ε1 = −ẍ_G/g with no perturbing force, (106))."),
        Spec(rid(89, "accel"), "β'' + aθ'' = g(−Y + ε2)", src(26, "89"), r"\beta'' + a\theta''", step(derivation.eq89),
             printed=printed.eq89, check=checks.Definition(), definition=True,
             note="Defines ε2: the linearised (5) plus the perturbation."),
        Spec(rid(90, "accel"), "R²θ'' = g(−N + aY − aθX + ε3)", src(26, "90"), r"R^2\theta''", step(derivation.eq90),
             printed=printed.eq90, check=checks.Definition(), definition=True,
             note="Defines ε3: (6) to the first order in θ, X kept, plus the perturbation."),
        Spec(rid(91, "first_order"), "the first-order terms of f vanish when z, n² are those of chapter I",
             src(26, None), r"f_1", step(derivation.first_order_vanishes), printed=None,
             check=checks.Proof("the first-order part of f = y'' + n²y, with n² of (28), is a multiple of the "
                                "quadratic (30) in z: its remainder is 0", truth=EXACT)),
        Spec(rid(91, "f"), "f = g[−ΔY + ε2 + (ΔN − aΔY + aθΔX − ε3)/z']", src(26, "91"), "f", step(derivation.eq91),
             printed=printed.eq91, check=THROUGH_PERIOD,
             note="Derived: y'' + n²y with (89), (90), the loads of (23), (24) plus ΔX, ΔY, ΔN; z/R² = −1/z' (31)."),
        # ---------------------------------------------------------------- n°27
        Spec(rid(92, "dX"), "ΔX = ε1", src(27, "92"), r"\Delta X", step(derivation.eq92), printed=printed.eq92,
             check=THROUGH_PERIOD),
        Spec(rid(93, "x"), "d(Mx')/ds − x = ε − ΔY", src(27, "93"), r"\frac{d}{ds}(Mx') - x", step(derivation.eq93),
             printed=printed.eq93, readings=(READ_94,), check=THROUGH_PERIOD,
             defs=((eps_bar, varphi(s) * eps1 + eps_blade), (dX, eps1)),
             note="(7) at the second order minus the first; ε of (94) (ε_bar here) and ΔX = ε1 (92) applied."),
        Spec(rid(94, "eps"), "ε = φε1 + ε'", src(27, "94"), r"\bar\varepsilon", step(derivation.eq94),
             printed=printed.eq94, readings=(READ_94,), check=checks.Definition(), definition=True),
        Spec(rid(101, "dY"), "β1ΔY = ∫εφ1 ds", src(27, "101"), r"\Delta Y", step(derivation.Delta_Y),
             printed=printed.eq101, readings=(READ_101,), check=THROUGH_PERIOD,
             note="Derived by the Green identity of (93) with φ1 = 1 + v' ((Mφ1')' − φ1 = −1, φ1 = 0 at both ends), "
                  "not by Haag's variation of constants (95)–(100); I_1 = ∫ε_barφ1 ds."),
        Spec(rid(102, "dN"), "ΔN = ∫εφ2 ds + vλΔY − ε_λ", src(27, "102"), r"\Delta N", step(derivation.Delta_N),
             printed=printed.eq102, readings=(READ_EPS_LAMBDA, READ_VW), check=THROUGH_PERIOD,
             note="Derived by the Green identity of (93) with φ2 = w' ((Mφ2')' = φ2; φ2(0) = 0, φ2(λ) = 1); "
                  "I_2 = ∫ε_barφ2 ds."),
        Spec(rid(103, "H"), "H_n = ∫(Yφ1 + θφ2)^n ds", src(27, "103"), "H_n", step(derivation.H_103),
             printed=printed.eq103, check=checks.Definition(), definition=True),
        # ---------------------------------------------------------------- n°28
        Spec(rid(104, "f"), "f = −(n²/K)[ε2z' + aθε1 − ε3 + ½ε1(K∂H2/∂Y + ∂H2/∂θ) + ∫ε'(Kφ1 + φ2) ds − ε_λ]",
             src(28, "104"), r"-\frac{K}{n^2} f", step(derivation.eq104), printed=printed.eq104,
             readings=(READ_ZP, READ_EPS1_AS_4, READ_EPS_PRIME, READ_EPS_LAMBDA, READ_SIGMA), check=THROUGH_PERIOD,
             note="The bracket; (91) with (92), (101), (102), (35) and g/z' = −n²/K (34); E_i = ∫ε'φ_i ds; "
                  "H2 in moments J(i, j) = ∫φ1^iφ2^j ds."),
        Spec(rid(105, "parts"), "the last two terms of (104) = −∫ε(Kv + w)/M ds", src(28, "105"),
             r"\int\varepsilon'(K\varphi_1 + \varphi_2)ds - \varepsilon_\lambda", step(derivation.eq105),
             printed=printed.eq105, readings=(READ_VW, READ_EPS_PRIME), check=truth.parts_on_blades(),
             note="Integration by parts with (9), (10); ε(s) the moment increment, ε' = dε/ds."),
        # ---------------------------------------------------------------- n°29
        Spec(rid(106, "eps"), "gε1, gε2, ε3, ε' of the isochronism error", src(29, "106"),
             r"(g\varepsilon_1, g\varepsilon_2, \varepsilon_3, \varepsilon')", step(derivation.eq106),
             printed=printed.eq106, readings=(READ_EPS_PRIME,),
             check=checks.All(tuple(truth.neglected_terms(i) for i in range(4)),
                              truth="the exact (4)–(7) with mpmath's sin and cos at a point scaled by p"),
             note="Third-order parts of the exact equations (α'' of the second order)."),
        Spec(rid(106, "alpha"), "α = λ − ½H2", src(29, None), r"\alpha", step(derivation.alpha_of_H2),
             printed=printed.alpha_H2, check=truth.alpha_order(),
             note="From x' = cos φ (3); H2 in moments."),
        Spec(rid(107, "alpha_dd"), "−2α'' = (Y''∂_Y + θ''∂_θ)H2 + (Y'∂_Y + θ'∂_θ)²H2", src(29, "107"), r"-2\alpha''",
             step(derivation.eq107), printed=printed.eq107, readings=(READ_107,), check=THROUGH_PERIOD),
        Spec(rid(108, "H"), "H = 4YH3 − H4", src(29, "108"), "H", step(derivation.H_108), printed=printed.eq108,
             check=checks.Definition(), definition=True),
        Spec(rid(108, "identity"), "(K/6)H3 + ∫ε'(Kφ1 + φ2) ds = (1/24)(K∂H/∂Y + ∂H/∂θ)", src(29, None),
             r"\frac{K}{6}H_3 + \int\varepsilon'(K\varphi_1+\varphi_2)ds - \frac{1}{24}(K\partial_Y + \partial_\theta)H",
             step(derivation.identity_108), printed=printed.identity_108, readings=(READ_108,),
             check=checks.Proof("the difference, in moments, is 0", truth=EXACT)),
        Spec(rid(109, "f"), "f = −(n²/K)[…] with the neglected terms (109)", src(29, "109"), r"-\frac{K}{n^2} f",
             step(derivation.eq109_bracket), printed=printed.eq109, readings=(READ_H4, READ_ZP),
             defs=printed.DEF_EPS1, check=THROUGH_PERIOD,
             note="ε1 of (106) applied to both forms; (K/6)H3 of the third-order term of β included."),
        Spec(rid(110, "F"), "F = H(K, 1) = 4KF3 − F4", src(29, "110"), "F", step(derivation.F_110_derived),
             printed=printed.eq110, check=checks.Definition(), definition=True),
        Spec(rid(110, "euler_H2"), "K∂H2/∂Y + ∂H2/∂θ = 2θF2 at Y = Kθ", src(29, None),
             r"(K\partial_Y + \partial_\theta)H_2", step(derivation.euler_H2), printed=printed.euler_H2,
             check=checks.Proof("in moments at Y = Kθ it is 2θF2", holds=_is(printed.euler_H2()), truth=EXACT)),
        Spec(rid(110, "euler_H"), "K∂H/∂Y + ∂H/∂θ = 4θ³F at Y = Kθ", src(29, None),
             r"(K\partial_Y + \partial_\theta)H", step(derivation.euler_H), printed=printed.euler_H,
             defs=printed.DEFS_112,
             check=checks.Proof("in moments at Y = Kθ it is 4θ³(4KF3 − F4)",
                                holds=_is(printed.euler_H().subs(dict(printed.DEFS_112))), truth=EXACT)),
        Spec(rid(111, "dT"), "ΔT/T = (Q'/Q)θ0²/16", src(29, "111"), r"\frac{\Delta T}{T}", step(derivation.eq111),
             printed=printed.eq111, defs=printed.DEFS_111, check=truth.period_order("dT"), show_values=True,
             note="Derived: f of (109) in the principal oscillation (Y = Kθ, θ'' = −n²θ), perturbation of θ'' "
                  "f/(z − z'), averaged by (114); Q = K(z − z') (45), Q' (112) applied to the printed form."),
        Spec(rid(112, "Qp"), "Q' = a(1 − 4K) − (4K/z')(a + F2)² − F", src(29, "112"), "Q'", step(derivation.eq112),
             printed=printed.eq112, defs=printed.DEFS_112, check=truth.period_order("Qp"),
             note="Q' = 16Q(ΔT/T)/θ0² from the derived ΔT/T; F of (110) applied to the printed form."),
        # ---------------------------------------------------------------- n°30
        Spec(rid(114, "classical"), "ΔT = (1/(n³θ0))∫F cos φ dφ", src(30, "114"), r"\frac{\Delta T}{T}",
             step(derivation.eq114_relative), printed=printed.eq114_relative, check=truth.classical_order(),
             note="Divided by T = 2π/n; C = ∫F cos φ dφ. Derived by Lindstedt (the cos φ component)."),
    )


def _is(target):
    import sympy as sp
    return lambda expr: sp.simplify(sp.expand(expr - target)) == 0
