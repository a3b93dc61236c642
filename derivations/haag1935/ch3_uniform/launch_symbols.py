"""Symbols of n°18–20 and n°54 that chapter III needs and :mod:`..symbols` does not hold.

The two vibrations of the suspension (n°8–9, n°54): the principal one, of pulsation n
and coefficient K, and the parasitic one, of pulsation n' and coefficient K' (z and z'
exchanged).  The launch by a shock (n°19–20) uses the striking mass m', its speed V and
the restitution coefficient h: the memoir reuses m' (the blade's mass in n°56) and h
(the blade's width in n°47), and so do these symbols, which are the same SymPy symbols.
"""
import sympy as sp

from ..symbols import E, T, h, mb, mg

K_prime = sp.Symbol("K'", real=True)              # K of the parasitic vibration
n_principal = sp.Symbol("n", positive=True)       # pulsation n of the principal vibration
n_parasitic = sp.Symbol("n'", positive=True)      # pulsation n' of the parasitic vibration
t = sp.Symbol("t", real=True)                     # time
Q = sp.Symbol("Q", real=True)                     # force of the static launch (n°18)
V = sp.Symbol("V", real=True)                     # speed of the striking mass (n°20)
m = sp.Symbol("m", positive=True)                 # mass of the pendulum
m_striking = mb                                   # m' of n°20, the striking mass
restitution = h                                   # h of n°20, the restitution coefficient
weight = mg                                       # mg
stress_scale = sp.sqrt(3 * E * T)                 # √(3ET) of (175), T = mg/(eh) (n°51)
