"""Haag 1935, chapter V: the symbols of n°64–67 beyond those of :mod:`..symbols`."""
import sympy as sp

n2p = sp.Symbol("n'^2", positive=True)        # n'², the parasitic vibration (199)
rho = sp.Symbol("rho", real=True)             # ρ of (207)
eps = sp.Symbol("varepsilon", real=True)      # ε of (207)
R0 = sp.Symbol("R_0", positive=True)          # (205)
a0 = sp.Symbol("a_0", real=True)              # the critical value ν_λ (211)
F0 = sp.Symbol("F_0", positive=True)          # F0 = n0/(2π) (206)
n0 = sp.Symbol("n_0", positive=True)
freq, freq_p, beat = sp.symbols("F F' f", positive=True)
