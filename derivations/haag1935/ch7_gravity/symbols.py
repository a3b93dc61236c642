"""Symbols of chapters VII–VIII (Haag 1935, n°82–103) beyond those of :mod:`..symbols`."""
import sympy as sp

eps = sp.Symbol("varepsilon", positive=True)      # a − a1 = ελ (256); a1 − a = ελ (312)
eps_p = sp.Symbol("varepsilon'", real=True)       # ε' of (258)
a_r = sp.Symbol("a", real=True)                   # AG, negative near a1 < 0 for the direct blade (n°85)
l_syn = sp.Symbol("l", real=True)                 # length of the synchronous simple pendulum (R² + a²)/a (n°68)
n2_p = sp.Symbol("n'^2", positive=True)           # n'² of the parasitic (fast) vibration (266)
g_s = sp.Symbol("g", real=True)                   # g, negative for the inverted blade (n°100)
C_s = sp.Symbol("C", positive=True)               # coefficient C of (284)
S_s = sp.Symbol("S", real=True)                   # suppleness S (82)
x_n = sp.Symbol("x_n", positive=True)             # n-th root of tan x = x (309)
