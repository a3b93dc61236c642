"""Haag 1935, chapter III: the independent truth of n°50 and n°54, the normal modes of the suspension.

The small oscillations (25)–(26) of chapter I are written with β1, β2, v_0, v_λ,
w_λ of the shot uniform blade (:mod:`.truth`) and solved by mpmath eig: each mode
gives its pulsation n² and its fixed point (focus), the principal mode being the
one that keeps F' fixed (z' < 0, n°9), and K = −n²z'/g (34).  The launches of
n°18–20 start the same linear system from the static deviation (67) or the shock
(70), (74); the stresses at the ends follow from (78).
"""
from __future__ import annotations

import mpmath as mp

from ..symbols import K, vl, w0, wl, z, zp
from .launch_symbols import K_prime, m_striking, n_parasitic, n_principal, weight
from .truth import formula_input

DYNAMIC = {"a": "0.9", "R": "0.35", "g": "9.81"}
LAUNCH = {"a": "0.9", "R": "0.35", "g": "9.81", "b": "0.35", "Q": "0.7", "t": "0.83", "V": "0.4", "h": "0.6",
          "m": "2.5", "m'": "0.3", "E": "2.1", "T": "0.4"}
MODES = ("normal modes of (25)–(26) (mpmath eig) with β1, β2, v0, v_λ, w_λ of the uniform blade; "
         "K = −n²z'/g (34), z' from the mode that keeps F' fixed")


def motion_matrix(solution, a, R, g) -> mp.matrix:
    """A⁻¹C of (25)–(26), A q'' = C q for q = (β, θ), with the shot β1, β2, v_0, v_λ, w_λ."""
    lam_value = mp.mpf(solution.blade.length)
    A = mp.matrix([[1, a], [0, R**2]])
    C = mp.matrix([[-1, solution.beta2],
                   [a - solution.vl, -(a * (lam_value - solution.v0) + solution.vl**2 + solution.beta1 * solution.wl)]])
    return mp.inverse(A) * (C * (g / solution.beta1))


def normal_modes(solution, a, R, g) -> tuple:
    """(z, z', n², K) of the principal mode: K = −n²z'/g (34)."""
    values, vectors = mp.eig(motion_matrix(solution, a, R, g))
    modes = []
    for i in range(2):
        beta_i, theta_i = vectors[0, i], vectors[1, i]
        modes.append((-values[i].real, (-(beta_i / theta_i) - a).real))   # (n², the fixed point's z)
    # the principal oscillation keeps F' fixed, z' < 0 (n°9); the parasitic one keeps F fixed
    principal, parasitic = (modes[0], modes[1]) if modes[0][1] < 0 else (modes[1], modes[0])
    n2, z_prime = principal
    z_value = parasitic[1]
    return z_value, z_prime, n2, -n2 * z_prime / g


def modes_at(solution, env) -> tuple:
    return normal_modes(solution, mp.mpf(env["a"]), mp.mpf(env["R"]), mp.mpf(env["g"]))


def mode_quantity(name: str):
    """z, z' ("zp"), K, n² ("n2") or k = K(1 − K) of the principal mode."""
    def quantity(solution, env):
        z_value, z_prime, n2, K_value = modes_at(solution, env)
        return {"z": z_value, "zp": z_prime, "K": K_value, "n2": n2, "k": K_value * (1 - K_value)}[name]
    return quantity


def foci_inputs(solution, env) -> dict:
    """z of the modes and the shot v_λ, w_λ, w_0: what k of (165) is written with."""
    z_value = modes_at(solution, env)[0]
    return {z.name: formula_input(z_value), vl.name: formula_input(solution.vl),
            wl.name: formula_input(solution.wl), w0.name: formula_input(solution.w0)}


# ================================================================ n°54: the launches
def modal_state(solution, env, shock: bool) -> tuple:
    """(β, θ) at time t from the eigen-decomposition of (25)–(26), started by the static
    deviation (67) or by the shock (70), (74)."""
    a, R, g, b, t = (mp.mpf(env[x]) for x in ("a", "R", "g", "b", "t"))
    values, eigenvectors = mp.eig(motion_matrix(solution, a, R, g))
    eigenvectors_inverse = mp.inverse(eigenvectors)
    if shock:
        denominator = (a - b) ** 2 + R**2 * (1 + mp.mpf(env["m"]) / mp.mpf(env["m'"]))
        theta_speed = (1 + mp.mpf(env["h"])) * mp.mpf(env["V"]) * (b - a) / denominator
        q0, q_speed = mp.matrix([0, 0]), mp.matrix([-a * theta_speed - R**2 * theta_speed / (a - b), theta_speed])
    else:
        Q_over_mg = mp.mpf(env["Q"]) / g          # Q/(mg) with m = 1
        theta_0 = Q_over_mg * (b - solution.vl) / (a + solution.wl)
        beta_0 = Q_over_mg * (solution.beta1 - solution.vl * (b - solution.vl) / (a + solution.wl))
        q0, q_speed = mp.matrix([beta_0, theta_0]), mp.matrix([0, 0])
    pulsations = [mp.sqrt(-values[i].real) for i in range(2)]
    c0, c_speed = eigenvectors_inverse * q0, eigenvectors_inverse * q_speed
    modal = mp.matrix([c0[i] * mp.cos(pulsations[i] * t) + c_speed[i] * mp.sin(pulsations[i] * t) / pulsations[i]
                       for i in range(2)])
    q = eigenvectors * modal
    return q[0].real, q[1].real


def end_stress(at: int, shock: bool):
    """T'_0 (at = 0) or T'_λ (at = 1) = √(3ET)(u/λ)(Y v + θ w) at the end (78), Y of (23), from the modal state."""
    def quantity(solution, env):
        beta, theta = modal_state(solution, env, shock)
        Y = (beta + theta * solution.vl) / solution.beta1
        v, w = (solution.v0, solution.w0) if at == 0 else (solution.vl, solution.wl)
        u_value, lam_value = mp.mpf(env["u"]), mp.mpf(env["lambda"])
        return mp.sqrt(3 * mp.mpf(env["E"]) * mp.mpf(env["T"])) * u_value / lam_value * (Y * v + theta * w)
    return quantity


def launch_inputs(solution, env) -> dict:
    """The foci, K, K' (36) and the pulsations n, n' (34) of the two modes, and mg (m = 1)."""
    a, g = mp.mpf(env["a"]), mp.mpf(env["g"])
    z_value, z_prime, _n2, _K = modes_at(solution, env)
    K_prime_value = (a + solution.wl) / (a + z_prime - solution.vl)       # (36) with z ↔ z'
    K_value = (a + solution.wl) / (a + z_value - solution.vl)
    n2_parasitic = -K_prime_value * g / z_value                          # (34) with z ↔ z'
    n2_principal = -K_value * g / z_prime
    return {z.name: formula_input(z_value), zp.name: formula_input(z_prime), K.name: formula_input(K_value),
            K_prime.name: formula_input(K_prime_value), n_principal.name: formula_input(mp.sqrt(n2_principal)),
            n_parasitic.name: formula_input(mp.sqrt(n2_parasitic)), weight.name: formula_input(env["g"]),
            m_striking.name: formula_input(env["m'"])}
