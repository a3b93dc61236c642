"""Cellérier's symbols, with their assumptions (Mouvement simultané d'un pendule et de ses supports)."""
import sympy as sp

from pendsym import finite_amplitude

t = sp.Symbol("t", real=True)                    # time
m = sp.Symbol("m", positive=True)                # mass of the pendulum
g = sp.Symbol("g", positive=True)
h = finite_amplitude.h                           # OG = O'G', pivot to centre of gravity
C = sp.Symbol("C", positive=True)                # moment of inertia about the knife edge
l = sp.Symbol("l", positive=True)                # l = C/(m h), length of the simple pendulum
alpha = finite_amplitude.alpha                   # amplitude α
phi = finite_amplitude.phi                       # angle φ of cos θ = cos α cos²φ + sin²φ
theta = sp.Symbol("theta", real=True)            # θ as a variable
thetad = sp.Symbol("thetadot", real=True)        # θ'
thetadd = sp.Symbol("thetaddot", real=True)      # θ''
x1dd = sp.Symbol("x1ddot", real=True)            # x1''
y1dd = sp.Symbol("y1ddot", real=True)            # y1''
x1s, y1s = sp.symbols("x1 y1", real=True)        # pivot coordinates as variables
mu_p = sp.Symbol("mu'", real=True)               # μ'
u = finite_amplitude.u                           # u(φ) = μ'/(2 m g sin ½α)
P, Q = sp.symbols("P Q", real=True)              # pressure components (beyond mg) on the support
F, Fp = sp.Symbol("F", real=True), sp.Symbol("F'", real=True)
K = sp.Symbol("K", positive=True)                # static compliance y1 = K Q
eps = sp.Symbol("epsilon", positive=True)        # deflection under the test force p
p = sp.Symbol("p", positive=True)                # test force
pp = sp.Symbol("p'", positive=True)              # weight m g of the pendulum
delta = sp.Symbol("delta", positive=True)
T = sp.Symbol("T", positive=True)                # swing time
M = sp.Symbol("M", nonnegative=True)             # mass of the support (lumped model)
# elastic bar
z = sp.Symbol("z", nonnegative=True)
c = sp.Symbol("c", positive=True)                # length AO of the bar
n = sp.Symbol("n", positive=True)                # speed of longitudinal waves
a = sp.Symbol("a", positive=True)                # dv/dz = a Q at z = c
rho = sp.Symbol("rho", positive=True)
rho_p = sp.Symbol("rho'", real=True)
gamma = sp.Symbol("gamma", real=True)
x = sp.Symbol("x", positive=True)                # ρc/n
