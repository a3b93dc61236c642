"""Haag 1935, chapter VI, n°68–70: the foci, the period, Δl, Q and the temperature of the short blade, (212)–(223)."""
from __future__ import annotations

import sympy as sp

from pendsym import checks
from pendsym.result import Spec

from ..common import READ_VW, rid, src
from ..symbols import lam
from . import derivation, kernels, printed, truth, truth_dynamics
from .printed import DEFINITIONS, L_DEFINITION

FOCI = (rid(214, "z"), rid(215, "zp"))


def specs() -> tuple[Spec, ...]:
    both = ("tapered", "uniform")
    return (
        Spec(rid(213, "l"), "l = a + R²/a, the length of the synchronous pendulum about A", src(68, "213"), "l",
             derivation.length_213, printed=printed.length_213, definition=True, check=checks.Definition()),
        Spec(rid(212, "rhs"), "(30) written (z + a)(z − R²/a) = right member", src(68, "212"),
             r"(z + a)\left(z - \frac{R^2}{a}\right)", derivation.rhs_212, deps=(rid(30, "quadratic"),),
             printed=printed.rhs_212, defs=DEFINITIONS, readings=(READ_VW,), check=truth.foci_identity(),
             note="An exact rewriting of (30): both foci of the eigenproblem satisfy it."),
        Spec(rid(212, "reduced"), "right member of (212) over z to the first order, −β1 + (l/a)v_λ", src(68, "212–213"),
             r"\frac{1}{z}\times\text{(212)}", derivation.reduced_212, deps=(rid(212, "rhs"),),
             printed=printed.reduced_212, defs=DEFINITIONS, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.reduced_member, scale=truth.by_lambda, expected=1,
                                what="(z + a)(z − R²/a)/z at the lower focus z of the modes, over λ"),
             note="Unnumbered (\"d'après (18)\"); derived as the series in λ/a of the right member of (212)."),
        Spec(rid(214, "z"), "lower focus z to the first order in λ/a", src(68, "214"), "z", derivation.z_214,
             deps=(rid(30, "quadratic"),), printed=printed.z_214, defs=DEFINITIONS, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.relative("z"), scale=truth.by_a, expected=2,
                                what="z/a, z the node of the parasitic mode")),
        Spec(rid(215, "zp"), "upper focus z' to the first order in λ/a", src(68, "215"), "z'", derivation.zp_215,
             deps=(rid(30, "quadratic"),), printed=printed.zp_215, defs=DEFINITIONS, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.relative("z'"), scale=truth.by_a, expected=2,
                                what="z'/a, z' the node of the principal mode")),
        Spec(rid(216, "K"), "K to the first order in λ/a", src(69, "216"), "K", derivation.K_216,
             deps=(rid(36, "K"), rid(214, "z")), printed=printed.K_216, defs=DEFINITIONS, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.relative("K"), scale=truth.one, expected=2,
                                what="K = −n²z'/g of the principal mode")),
        Spec(rid(217, "n2"), "n² of the principal oscillation to the first order in λ/a", src(69, "217"), "n^2",
             derivation.n2_217, deps=(rid(216, "K"), rid(215, "zp")), printed=printed.n2_217, defs=DEFINITIONS,
             readings=(READ_VW, printed.READ_OMEGA_LAMBDA),
             check=truth.orders(*both, quantity=truth.relative("n^2"), scale=lambda env: env["g"] / env["l"],
                                expected=2, what="n² of the principal mode over g/l"),
             note="(34) n² = −Kg/z' with K of (216) and z' of (215)."),
        Spec(rid(218, "dl"), "Δl, the lengthening of the synchronous pendulum due to the blade", src(69, "218"),
             r"\Delta l", derivation.dl_218, deps=(rid(217, "n2"),), printed=printed.dl_218, defs=DEFINITIONS,
             readings=(READ_VW, printed.READ_OMEGA_LAMBDA),
             check=truth.orders(*both, quantity=truth.length_increase, scale=truth.by_lambda, expected=1,
                                what="Δl = g/n² − l of the principal mode, over λ"),
             note="Δl = g/n² − l with n² of (217), to the first order: its residual over λ is O(λ/a)."),
        Spec(rid(219, "dl"), "Δl = λ − v_0 − w_0 when R² ≪ a²", src(69, "219"), r"\Delta l", derivation.dl_219,
             deps=(rid(218, "dl"), rid(22, "beta1"), rid(16, "w0")), printed=printed.dl_219, readings=(READ_VW,),
             check=truth.orders(*both, quantity=truth.length_increase, scale=truth.by_lambda, expected=1,
                                family=truth.FIXED, what="Δl = g/n² − l of the principal mode, over λ")),
        Spec(rid(220, "dl"), "Δl = λ(1 − U_2/u) for the uniform blade", src(69, "220"), r"\Delta l",
             derivation.dl_220, deps=(rid(219, "dl"), rid(159, "v0"), rid(159, "w0")), printed=printed.dl_220,
             defs=DEFINITIONS,
             check=truth.orders("uniform", "uniform_half", quantity=truth.length_increase, scale=truth.by_lambda,
                                expected=1, family=truth.FIXED, what="Δl = g/n² − l of the principal mode, over λ"),
             kernel=kernels.DL_KERNEL,
             note="U + U_1 = U_2 (161) turns λ − v_0 − w_0 into the printed form.  Checked at u = 2 and 1/2: the "
                  "coefficient of λ/a in the error of Δl/λ falls fast with u (14.7 at u = 1/2, 0.72 at u = 1, "
                  "0.019 at u = 2, ≈ 0 near u = 4, −5e−4 at u = 5), so that at u = 5 the residual is of the "
                  "second order over the sequence."),
        Spec(rid(220, "thread"), "Δl = λ for u = ∞", src(69, None), r"\Delta l", derivation.dl_thread_220,
             deps=(rid(220, "dl"),), printed=printed.dl_thread,
             check=checks.Proof("the limit of (220) as u → ∞ is λ (SymPy limit)",
                                holds=lambda expr: sp.simplify(expr - lam) == 0),
             note="Unnumbered (\"Pour u = ∞, on retrouve bien Δl = λ\"): the pendulum hung from a thread of length λ."),
        Spec(rid(220, "u_root"), "the u where Δl of (220) vanishes (\"u > 1,2 environ\")", src(69, None), "u",
             derivation.u_root_220, deps=(rid(220, "dl"),), printed=printed.u_root_220, printed_decimals=1,
             check=truth.number_check(truth.dl_zero_truth, "the zero of λ − v_0 − w_0 in u, v_0, w_0 of the shot "
                                      "uniform blade λ = 0.1 (pendsym.blade, no closed form), mpmath findroot"),
             note="The root of u th u = 1 is 1.19968: the printed \"1,2 environ\" is it correctly rounded to one "
                  "decimal."),
        Spec(rid(221, "Q"), "Q = a + w_λ + β1 when λ², R² ≪ a²", src(70, "221"), "Q", derivation.Q_221,
             deps=(rid(45, "Q"), rid(214, "z"), rid(215, "zp"), rid(216, "K")), printed=printed.Q_221,
             defs=L_DEFINITION, readings=(READ_VW,),
             check=truth.orders(*both, quantity=lambda env: env["K"] * (env["z"] - env["z'"]), scale=truth.by_lambda,
                                expected=1, family=truth.FIXED, what="Q = K(z − z') (45) of the modes, over λ"),
             note="Derived from (45) Q = K(z − z') with (214)–(216), R = 0."),
        Spec(rid(221, "Q_ends"), "Q = a + λ + w_0 − v_0", src(70, "221"), "Q", derivation.Q_221_ends,
             deps=(rid(221, "Q"), rid(22, "beta1"), rid(16, "w0")), printed=printed.Q_221_ends, readings=(READ_VW,),
             check=truth.orders(*both, quantity=lambda env: env["K"] * (env["z"] - env["z'"]), scale=truth.by_lambda,
                                expected=1, family=truth.FIXED, what="Q = K(z − z') (45) of the modes, over λ")),
        Spec(rid(221, "P_bound"), "P_λ = w_0²/M_λ < μw_0/λ (\"d'après (19)\")", src(70, None),
             r"\mu\frac{w_0}{\lambda} - P_\lambda", derivation.P_bound_70, deps=(rid(59, "P"), rid(16, "w0")),
             printed=printed.P_bound_70, readings=(READ_VW,),
             check=truth_dynamics.blade_bound("μw_0/λ − w_0²/M_λ")),
        Spec(rid(221, "G2_bound"), "G_2 < μ(v_0 + w_λ)²/w_0", src(70, None),
             r"\mu\frac{(v_0 + w_\lambda)^2}{w_0} - G_2", derivation.G2_bound_70, printed=printed.G2_bound_70,
             readings=(READ_VW,), check=truth_dynamics.blade_bound("μ(v_0 + w_λ)²/w_0 − G_2")),
        Spec(rid(222, "dT"), "dT/T per degree when λ², R² ≪ a²", src(70, "222"), r"\frac{dT}{T}", derivation.dT_222,
             deps=(rid(60, "dT"), rid(216, "K"), rid(22, "beta1"), rid(16, "w0")), printed=printed.dT_222,
             readings=(READ_VW, printed.READ_BETA_T, printed.READ_222),
             check=checks.All((truth_dynamics.temperature_order("uniform"), truth_dynamics.temperature_order("tapered"))),
             note="(60) with K of (216), to the first order in λ/a (M_λ = O(λ²), G_2 = O(λ): Haag's footnotes), "
                  "R = 0.  The printed form is twice the derived one: its leading term α' should be α'/2, as in "
                  "(223) which Haag derives from it (and as T ∝ √(l/g) gives)."),
        Spec(rid(223, "dT"), "dT/T per degree for the uniform blade", src(70, "223"), r"\frac{dT}{T}",
             derivation.dT_223, deps=(rid(222, "dT"), rid(159, "v0"), rid(159, "w0"), rid(166, "Gamma2")),
             printed=printed.dT_223, defs=DEFINITIONS, readings=(printed.READ_BETA_T, printed.READ_223),
             check=truth_dynamics.temperature_order("uniform"),
             note="The α' and α terms agree with the text; the β term prints U_1 where G_2 = λ(U_1² + U_2/u)/2 "
                  "gives U_1²."),
    )
