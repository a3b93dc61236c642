"""Haag 1935, chapter I, n°21–25, eqs. (77)–(87): the Results, joining derivation, print and truth."""
from __future__ import annotations

from pendsym.result import Spec
from ..common import READ_VW, rid, src
from ..ch1_launch import printed as launch_printed
from . import derivation, printed, truth
from .printed import READ_81, READ_85, READ_86

F_AND_G = (rid(79, "F"), rid(79, "G"))
FORK_STEPS = (rid(84, "geometry"), rid(64, "beta"), rid(85, "alpha"))
# checked on chapter II's nonlinear orbits (run in the worker of (111)–(112))
ORBIT_RESULTS = (rid(64, "third_order"), rid(85, "fourth_order"))


def specs() -> tuple[Spec, ...]:
    return (
        # ---------------------------------------------------------------- n°21–22
        Spec(rid(77, "y"), "shape of the blade y = Y(x + v − v0) + θ(w − w0), x = s", src(21, "77"), "y",
             derivation.shape_77, printed=printed.eq77, readings=(READ_VW,), check=truth.shape(),
             note="x replaced by s (first order), as the text says."),
        Spec(rid(78, "T_M"), "tension of flexion T' = E(e/2)(Yv + θw)/M", src(22, "78"), "T'", derivation.tension_78_M,
             printed=printed.eq78_M, readings=(READ_VW,), check=truth.tension()),
        Spec(rid(78, "T_I"), "tension of flexion T' = (mge/2I)(Yv + θw)", src(22, "78"), "T'", derivation.tension_78_I,
             deps=(rid(78, "T_M"),), printed=printed.eq78_I, readings=(READ_VW,), check=truth.tension()),
        # ---------------------------------------------------------------- n°23
        Spec(rid(79, "F"), "F_n = ∫(Kφ1 + φ2)^n ds", src(23, "79"), "F_n", derivation.F_79, definition=True,
             printed=printed.eq79_F),
        Spec(rid(79, "G"), "G_n = ∫(Kv + w)^n/M^{n−1} ds", src(23, "79"), "G_n", derivation.G_79, definition=True,
             printed=printed.eq79_G, readings=(READ_VW,)),
        Spec(rid(80, "Wp"), "energy of the pendulum W' = (mgθ²/2)(a + F2)", src(23, "80"), "W'",
             derivation.pendulum_energy_80, deps=(rid(66, "phi"),) + F_AND_G, printed=printed.eq80_Wp,
             check=truth.pendulum_energy()),
        Spec(rid(80, "W"), "energy of the blade W = (mgθ²/2)G2", src(23, "80"), "W", derivation.blade_energy_80,
             deps=(rid(66, "dphi"),) + F_AND_G, printed=printed.eq80_W, check=truth.blade_energy()),
        Spec(rid(80, "S"), "suppleness S = W'/W = (a + F2)/G2", src(23, "80"), "S", derivation.suppleness_80,
             deps=(rid(80, "Wp"), rid(80, "W")), printed=printed.eq80_S, check=truth.suppleness()),
        Spec(rid(81, "F2G2"), "F2 + G2 = K²β1 + wλ", src(23, "81"), "F_2 + G_2", derivation.F2_plus_G2_81, deps=F_AND_G,
             printed=printed.eq81, readings=(READ_81,), check=truth.F2_plus_G2()),
        Spec(rid(82, "S"), "S = (a + wλ + K²β1)/G2 − 1", src(23, "82"), "S", derivation.suppleness_82,
             deps=(rid(80, "S"), rid(81, "F2G2")), printed=printed.eq82, readings=(READ_81,), check=truth.suppleness()),
        # ---------------------------------------------------------------- n°24–25
        Spec(rid(83, "OFp"), "centre of flexion OF' = λ + a + z'", src(24, "83"), r"\overline{OF'}",
             derivation.centre_of_flexion_83, deps=(rid(85, "alpha"),), printed=printed.eq83,
             check=truth.centre_of_flexion()),
        Spec(rid(84, "geometry"), "the fork: r² + 2r[(α − c)cos θ + β sin θ] + (α − c)² + β² − L² = 0",
             src(25, "84"), r"r^2 + \dots - L^2", derivation.fork_84, printed=printed.eq84, check=truth.geometry()),
        Spec(rid(85, "alpha"), "α = λ − (F2/2)θ² in the principal oscillation", src(25, "85"), r"\alpha",
             derivation.alpha_85, deps=(rid(66, "phi"),) + F_AND_G, printed=printed.eq85, readings=(READ_85,),
             check=truth.alpha_second_order()),
        Spec(rid(64, "third_order"), "(64) β = −(a + z')θ is exact to the third order in θ (β odd in θ)",
             src(25, None), r"\beta", lambda deps: deps[rid(64, "beta")].derived, deps=(rid(64, "beta"),),
             printed=launch_printed.eq64, check=truth.end_order("beta"),
             note="The claim after (85), with its footnote (2). The residual of the end's exact β falls like θ³."),
        Spec(rid(85, "fourth_order"), "(85) α = λ − (F2/2)θ² is exact to the fourth order in θ (α even in θ)",
             src(25, None), r"\alpha", lambda deps: deps[rid(85, "alpha")].derived, deps=(rid(85, "alpha"),),
             printed=printed.eq85, readings=(READ_85,), check=truth.end_order("alpha"),
             note="The claim after (85), with its footnote (2): the θ³ term vanishes, so the residual of the end's "
                  "exact α falls like θ⁴."),
        Spec(rid(86, "A"), "A of the fork: (84) with (64), (85) to the order θ²", src(25, "86"), "A",
             derivation.A_fork_86, deps=FORK_STEPS, printed=printed.eq86_A, readings=(READ_86,), check=truth.A_fork(),
             note="A is defined through r² + 2r(λ − c) + (λ − c)² − L² = Aθ² (to the fourth order)."),
        Spec(rid(86, "r"), "r = L + c − λ + (A/2L)θ²", src(25, "86"), "r", derivation.r_fork_86,
             deps=FORK_STEPS + (rid(86, "A"),), printed=printed.eq86_r, readings=(READ_86,), check=truth.r_fork()),
        Spec(rid(87, "optimum"), "optimum axis of the fork: A = 0", src(25, "87"), "A", derivation.optimum_87,
             deps=(rid(86, "A"),), printed=printed.eq87, check=truth.ForkOptimum(),
             note="printed as an equation = 0, with λ − c = x and r = L + c − λ."),
    )
