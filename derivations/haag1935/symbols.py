"""Haag's symbols, with their assumptions: chapter III (the uniform blade), then chapter I.

Haag 1935, ch. I (eqs. (1)–(87)) and ch. III (eqs. (156)–(183)).
The OCR renders Haag's v, w sometimes as ν, ω; here v, w are the solutions of
(9)–(10) and ω is only the constant 1/√M of (156).  Primes and subscripts
follow the memoir (β'' is ``beta_ddot``, v_λ is ``vl``, M(λ) is ``M_lambda``).
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

# ================================================================ chapter I (any M(s))
# the blade (n°1–2): v, w solve (9)–(10); M(s) = EI/(mg) > 0 (1); φ(s), x(s), y(s) its shape (2)–(3)
v = sp.Function("v")
w = sp.Function("w")
M_of_s = sp.Function("M", positive=True)
varphi = sp.Function("varphi")                   # φ(s), slope of the blade (2)
x_of_s, y_of_s = sp.Function("x"), sp.Function("y")   # the point of abscissa s (3); x also the increment of v (n°12)
varphi1, varphi2 = sp.Function("varphi_1"), sp.Function("varphi_2")   # φ1 = 1 + v', φ2 = w' (11)
varphi1_s, varphi2_s = sp.symbols("varphi_1 varphi_2", real=True)    # their values at a point s
v_s, w_s, M_s = sp.symbols("v_s w_s M_s", real=True)                 # v(s), w(s), M(s) at a point
epsilon_of_s = sp.Function("epsilon")            # relative change ε(s) of M (n°12)
t = sp.Symbol("t", real=True)                    # time (n°1); the variable of integration of (55)

# the pendulum and the end A of the blade (n°1–2)
m = sp.Symbol("m", positive=True)                # mass of the pendulum (1)
EI = sp.Symbol("EI", positive=True)              # E·I (1)
I_s = sp.Symbol("I_s", positive=True)            # moment of inertia of the section (78)
alpha = sp.Symbol("alpha", real=True)            # abscissa of A (n°1)
beta = sp.Symbol("beta", real=True)              # ordinate of A (n°1)
N = sp.Symbol("N", real=True)                    # couple mgN at A (n°1)
X = sp.Symbol("X", real=True)                    # axial reaction mgX (n°1)
alpha_ddot = sp.Symbol("alpha''", real=True)     # α''
beta_ddot = sp.Symbol("beta''", real=True)       # β''
theta_dot = sp.Symbol("theta'", real=True)       # θ'
theta_ddot = sp.Symbol("theta''", real=True)     # θ''
epsilon = sp.Symbol("epsilon", positive=True)    # order of smallness of θ, φ (n°2)
M1, M2, mu = sp.symbols("M_1 M_2 mu", positive=True)   # min, max of M(s), μ = M2/M1 (n°3)

# foci and periods (n°7–9)
n_squared = sp.Symbol("n^2", positive=True)      # n² (n°7)
K_prime = sp.Symbol("K'", real=True)             # K' (n°8)

# small variations (n°10–15); dz'/z', dR/R, dg/g are log-differentials
da, dlambda, dv0, dvl, dw0, dwl, dz, dzp, dbeta1, dK, dR = sp.symbols(
    "da dlambda dv_0 dv_lambda dw_0 dw_lambda dz dz' dbeta_1 dK dR", real=True)
dlog_zp = sp.Symbol("dz'/z'", real=True)
dlog_R = sp.Symbol("dR/R", real=True)
dlog_g = sp.Symbol("dg/g", real=True)
M_lambda = sp.Symbol("M_lambda", positive=True)  # M at s = λ
Q = sp.Symbol("Q", positive=True)                # a − a1 + K²β1 (45)
G_2 = sp.Symbol("G_2", positive=True)            # ∫(Kv + w)²/M ds (79)
G = sp.Symbol("G", real=True)                    # coefficient of sensitivity (62)
P_lambda = sp.Symbol("P_lambda", positive=True)  # P at s = λ (59)
W_over_mg = sp.Symbol("W/(mg)", positive=True)   # strain energy for θ = 1 radian, over mg (63)
alpha_blade = sp.Symbol("alpha", real=True)      # dilatation of the blade, per degree (60)
alpha_rod = sp.Symbol("alpha'", real=True)       # dilatation of the pendulum (60)
beta_t = sp.Symbol("beta_t", real=True)          # thermo-elastic coefficient (60)

# launching, shape, energy, fork (n°16–25)
Q_B = sp.Symbol("Q", real=True)                  # force applied at B (n°18)
m_striking = sp.Symbol("m'", positive=True)      # striking mass (n°20)
h_restitution = sp.Symbol("h", nonnegative=True)  # coefficient of restitution (n°20)
V = sp.Symbol("V", real=True)                    # velocity of m' before the blow
V_after = sp.Symbol("V'", real=True)             # … after the blow
beta_dot0 = sp.Symbol("beta'_0", real=True)      # β'0
theta_dot0 = sp.Symbol("theta'_0", real=True)    # θ'0
v_F = sp.Symbol("v_F", real=True)                # velocity of F after the blow (printed v_0)
v_Fp = sp.Symbol("v_F'", real=True)              # velocity of F' (printed v'_0)
n_principal = sp.Symbol("n", positive=True)      # angular frequency of the principal oscillation
n_parasitic = sp.Symbol("n'", positive=True)     # … of the parasitic vibration
c_axis = sp.Symbol("c", real=True)               # OC, the axis of the fork (n°25)
L = sp.Symbol("L", positive=True)                # CM, the length of the fork
r = sp.Symbol("r", real=True)                    # AM
x_fork = sp.Symbol("x", real=True)               # λ − c (87)
beta1_positive = sp.Symbol("beta_1", positive=True)   # β1 > 0 (17), under square roots
a_minus_a1 = sp.Symbol("a-a_1", positive=True)        # a − a1 > 0 (40), under square roots
