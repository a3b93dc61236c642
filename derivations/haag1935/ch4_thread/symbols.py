"""Haag 1935, chapter IV: the symbols of the thread (n°59–63) beyond those of :mod:`..symbols`."""
import sympy as sp

psi = sp.Symbol("psi", real=True)              # angle of the thread with the vertical (186)
psi_dot = sp.Symbol("psi'", real=True)
psi_ddot = sp.Symbol("psi''", real=True)
theta0 = sp.Symbol("theta_0", positive=True)   # amplitude (196)
time = sp.Symbol("t", real=True)
