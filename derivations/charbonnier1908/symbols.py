"""Charbonnier's symbols, with their assumptions (memoir, n°18–35), and his own definitions."""
import sympy as sp

t = sp.Symbol("t", nonnegative=True)            # time
k = sp.Symbol("k", positive=True)               # k² = g/l0
alpha = sp.Symbol("alpha", positive=True)       # amplitude α (start at rest at −α)
eps = sp.Symbol("epsilon", real=True)           # ε of θ'' + k²θ + εφ = 0
theta = sp.Symbol("theta", real=True)           # θ as a variable of φ(θ, θ', t)
dtheta = sp.Symbol("thetadot", real=True)       # θ' as a variable
m = sp.Symbol("m", integer=True, positive=True)  # exponent of the monomial θ^m (n°19)
n = sp.Symbol("n", integer=True, nonnegative=True)
y = sp.Symbol("y", real=True)                   # variable of J_m(y)
T = sp.Symbol("T", positive=True)               # Charbonnier's durée d'oscillation π/k (one swing)
theta_m = sp.Symbol("theta'_m", positive=True)  # speed at the lowest point, kα
beta = sp.Symbol("beta", positive=True)         # coefficient of the winding curve (n°22)
q = sp.Symbol("q", real=True)                   # coefficient of l = l0(1 + qθ²) (n°23)
mu = sp.Symbol("mu", positive=True)             # mg/e, stretch of the thread under mg (n°24)
a = sp.Symbol("a", positive=True)               # growth rate of l = l0(1 + at) (n°27)
l0 = sp.Symbol("l_0", positive=True)
l = sp.Symbol("l", positive=True)
g = sp.Symbol("g", positive=True)
e = sp.Symbol("e", positive=True)               # elasticity coefficient of the thread
mass = sp.Symbol("m_p", positive=True)          # the bob's mass (printed m; renamed from the exponent)
omega = sp.Symbol("omega", positive=True)       # polar angle of the curve (n°22, n°35)
v = sp.Symbol("v", real=True)                   # speed of the bob (n°24)
theta_i = sp.Symbol("theta_i", real=True)       # general initial angle (machinery tests)
omega_i = sp.Symbol("omega_i", real=True)       # general initial speed

# The phase kt and its sine and cosine, as the memoir writes them (∫ … d(kt)).
kt = k * t
cos_kt, sin_kt = sp.cos(kt), sp.sin(kt)

# E_s, E_c of the phase, as the memoir writes them: E_s(π) is the value at kt = π (n°9, n°18).
E_s, E_c = sp.Function("E_s"), sp.Function("E_c")
varphi = sp.Function("varphi")                  # the perturbing function φ (n°8, n°18)

# Charbonnier's own definitions, applied to a printed formula before it is
# compared or evaluated: T = π/k, θ'_m = kα, g = k² l0, e = m g/μ.
DEFS = {T: sp.pi / k, theta_m: k * alpha, g: k**2 * l0, e: mass * k**2 * l0 / mu}
DEF_ITEMS = tuple(DEFS.items())
