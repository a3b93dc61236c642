"""Haag 1935, chapter II, n°40 and n°43, eqs. (145) and (150): the incoming friction, and what the period and
the damping measured against the amplitude can tell of the internal friction, derived.

(145) is n°41's replacement for θ > 0, θ' < 0 (a → −b, c' → −c' = |c'|) in the outgoing term of (144).
n°43 reads (147) and (149) (derived, :mod:`.derivation_friction`): they hold a, a', b, b' only through
α = b + b' − a − a' and β = b + b' + a + a', so only the sums a + a', b + b' can be measured (no dissymmetry);
their powers of θ0 are p + q − 1 and p + q, whence the forms (150) for a friction of degrees 0, p, p + 1; and
Le Rolland's ΔT/T without a term in 1/θ0 asks that (147) at p = q = 0 vanish: α_00 = 0.
"""
from __future__ import annotations

import sympy as sp

from ..ch2_common import theta0
from .derivation_friction import a_f, ap_f, b_f, bp_f, c_rate, eq147, eq149, friction_moment, p_f, q

alpha_f, beta_f = sp.symbols("alpha_pq beta_pq", real=True)      # n°43
a00, ap00, b00, bp00 = sp.symbols("a_00 a'_00 b_00 b'_00", real=True)
p_first = sp.Symbol("p", integer=True, positive=True)           # the degree of the first non-constant term (150)
A150, B150, C150 = sp.symbols("a b c")                           # the coefficients of (150), ΔT/T
A150p, B150p, C150p = sp.symbols("a' b' c'")                     # and Δθ0


def eq145() -> sp.Expr:
    """(145): the incoming friction's ε for θ > 0, θ' < 0 (c > 0, c' < 0), by n°41's replacement in the
    outgoing term (:func:`.derivation_friction.friction_moment`): a → −b, c' → −c' = |c'|."""
    return friction_moment().xreplace({a_f: -b_f, c_rate: sp.Abs(c_rate)})


def alpha_beta() -> sp.Tuple:
    """n°43: α_pq = b + b' − a − a' and β_pq = b + b' + a + a' (a definition): the combinations that (147) and
    (149) (derived) hold, read off as the coefficients of g_{p+q}(1)i/(4Q) and −πg_{p+q}(1)i/(2Q)."""
    from .derivation import g_fn, i_fn
    g = g_fn(p_f + q, 1)
    alpha = sp.factor(eq147() / (sp.Symbol("n", positive=True) ** q * g * i_fn(p_f + 1, q)
                                 * theta0 ** (p_f + q - 1) / (4 * sp.Symbol("Q", positive=True))))
    beta = sp.factor(eq149() / (-sp.pi * sp.Symbol("n", positive=True) ** q * g * i_fn(p_f, q + 1)
                                * theta0 ** (p_f + q) / (2 * sp.Symbol("Q", positive=True))))
    return sp.Tuple(sp.expand(alpha), sp.expand(beta))


def means() -> sp.Tuple:
    """n°43: ½(a + a') and ½(b + b') from α, β (:func:`alpha_beta` solved for the two sums)."""
    sa, sb = sp.symbols("S_a S_b")
    alpha, beta = alpha_beta()
    eqs = [sp.Eq(alpha_f, sp.expand(alpha).subs(ap_f, sa - a_f).subs(bp_f, sb - b_f)),
           sp.Eq(beta_f, sp.expand(beta).subs(ap_f, sa - a_f).subs(bp_f, sb - b_f))]
    sol = sp.solve(eqs, [sa, sb], dict=True)[0]
    return sp.Tuple(sol[sa] / 2, sol[sb] / 2)


def no_dissymmetry() -> sp.Tuple:
    """n°43: (147) and (149) unchanged when friction moves from one side to the other (a → a + d, a' → a' − d,
    b → b + e, b' → b' − e): the differences, (0, 0)."""
    d, e = sp.symbols("d e", real=True)
    move = {a_f: a_f + d, ap_f: ap_f - d, b_f: b_f + e, bp_f: bp_f - e}
    return sp.Tuple(*(sp.simplify(x.xreplace(move) - x) for x in (eq147(), eq149())))


def _theta0_power(expr: sp.Expr) -> sp.Expr:
    """The exponent of θ0 in a monomial c·θ0^k."""
    _, power = expr.as_independent(theta0, as_Add=False)
    base, k = power.as_base_exp()
    if base != theta0:
        raise ValueError(f"not c·θ0^k: {expr}")
    return k


def _series(expr: sp.Expr, coefficients) -> sp.Expr:
    """Σ c_d θ0^{k(d)} over the degrees d = p + q ∈ (0, p, p + 1) of (144)–(145): the first constant term, the
    first non-constant one (of degree p) and the next; k from the derived form."""
    k = _theta0_power(expr)
    return sum(c * theta0 ** sp.expand(k.subs(q, d - p_f)) for c, d in zip(coefficients, (0, p_first, p_first + 1)))


def eq150_period() -> sp.Expr:
    """(150), first line: ΔT/T from (147) (θ0^{p+q−1}) for the degrees 0, p, p + 1."""
    return _series(eq147(), (A150, B150, C150))


def eq150_amplitude() -> sp.Expr:
    """(150), second line: Δθ0 from (149) (θ0^{p+q}) for the degrees 0, p, p + 1."""
    return _series(eq149(), (A150p, B150p, C150p))


def alpha00() -> sp.Expr:
    """n°43: Le Rolland's ΔT/T = aθ0 + bθ0² + cθ0³ has no term in 1/θ0, which only degree 0 gives ((150)):
    (147) at p = q = 0 must vanish; with i_{1,0} ≠ 0 and g_0(1) ≠ 0 the factor α_00 must.  Returns
    that factor, a_00 + a'_00 − b_00 − b'_00 (= 0), normalised by its coefficient of a_00."""
    from .derivation import g_fn, i_fn
    at0 = eq147().subs({p_f: 0, q: 0}).xreplace({a_f: a00, ap_f: ap00, b_f: b00, bp_f: bp00})
    if sp.simplify(_theta0_power(eq147()).subs({p_f: 0, q: 0}) + 1) != 0:
        raise ValueError("the degree 0 does not give 1/θ0")
    rest = sp.expand(at0 / (g_fn(0, 1) * i_fn(1, 0) / theta0))
    return sp.expand(rest / rest.coeff(a00))
