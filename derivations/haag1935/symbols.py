"""Haag's symbols for chapter III (the uniform blade), with their assumptions.

Haag 1935, ch. I (eqs. (1)–(14), (79)) and ch. III (eqs. (156)–(183)).
The OCR renders Haag's v, w sometimes as ν, ω; here v, w are the solutions of
(9)–(10) and ω is only the constant 1/√M of (156).
"""
import sympy as sp

from pendsym.blade import S as s   # curvilinear abscissa 0 ≤ s ≤ λ (real)

lam = sp.Symbol("lambda", positive=True)       # length of the blade
u = sp.Symbol("u", positive=True)              # u = λω (156)
omega = sp.Symbol("omega", positive=True)      # ω = 1/√M (156)
M = sp.Symbol("M", positive=True)              # M = EI/(mg), constant (156)
K = sp.Symbol("K", real=True)                  # K of (35)–(36)
k = sp.Symbol("k", real=True)                  # k = K(1 − K) (165)
U = sp.Symbol("U", positive=True)              # th(u/2) (160)
U1 = sp.Symbol("U_1", positive=True)           # 1/sh u (160)
U2 = sp.Symbol("U_2", positive=True)           # 1/th u (160)
n = sp.Symbol("n", integer=True, positive=True)
p = sp.Symbol("p", integer=True, positive=True)
x0 = sp.Symbol("x_0", real=True)               # x = Kv + w at s = 0 (n°48)
xl = sp.Symbol("x_lambda", real=True)          # … at s = λ
Y = sp.Symbol("Y", real=True)                  # reaction component mgY (n°1)
theta = sp.Symbol("theta", real=True)          # angle of the rod (n°1)
a = sp.Symbol("a", positive=True)              # AG (n°1)
b = sp.Symbol("b", real=True)                  # AB, point of attack (n°18)
R = sp.Symbol("R", positive=True)              # radius of gyration (n°1)
z = sp.Symbol("z", real=True)                  # GF, lower focus (n°7)
zp = sp.Symbol("z'", real=True)                # GF', upper focus
a1 = sp.Symbol("a_1", real=True)               # critical distance −wλ (41)
g = sp.Symbol("g", positive=True)
E = sp.Symbol("E", positive=True)              # Young's modulus
e = sp.Symbol("e", positive=True)              # thickness of the blade
h = sp.Symbol("h", positive=True)              # width of the blade
mg = sp.Symbol("mg", positive=True)            # weight of the pendulum
T = sp.Symbol("T", positive=True)              # fatigue mg/(eh) due to the weight (n°51)
c = sp.Symbol("c", real=True)                  # shape parameter (172)
mb = sp.Symbol("m'", positive=True)            # mass of the blade (n°56)
v0, vl, w0, wl = sp.symbols("v_0 v_lambda w_0 w_lambda", real=True)   # end values (n°2)
beta1, beta2 = sp.symbols("beta_1 beta_2", real=True)

Gam = sp.Function("Gamma")   # Γ_n (163)
Gn = sp.Function("G")        # G_n (79)
Fn = sp.Function("F")        # F_n (79)
Sp = sp.Function("S")        # S_p = K^p + (1 − K)^p (footnote of (166))

# Haag's definitions (156), (160): applied to printed and derived forms before comparison.
# 1/sh u and 1/th u are written through t = th(u/2), 1/sh u = (1 − t²)/(2t), 1/th u = (1 + t²)/(2t)
# (the same functions, cf. (161)), so that both forms are rational in th(u/2) and u and their
# exact comparison reduces to a cancellation.
_t = sp.tanh(u / 2)
DEFS = ((omega, u / lam), (M, lam**2 / u**2),
        (U, _t), (U1, (1 - _t**2) / (2 * _t)), (U2, (1 + _t**2) / (2 * _t)))
K_OF_k = ((k, K * (1 - K)),)
