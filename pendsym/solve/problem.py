"""A user's perturbation problem: the TOML schema, read with tomllib, validated in full.

    name = "Duffing"                  # optional
    variable = "u"                    # the unknown (default "theta")
    velocity = "v"                    # the name of its derivative in formulas (default "d" + variable)
    time = "t"                        # default "t"
    small = "eps"                     # the small parameter
    order = 3                         # the order wanted (1 … 12)
    method = "auto"                   # auto | lindstedt | variation | averaging
    # either the oscillator  u'' + k**2 u + phi(u, v, t) = 0  (phi vanishes with the small parameter)
    k = "1"
    phi = "eps*u**3"
    # or the variable-length pendulum  u'' + (2 l'/l) v + (g/l) u = 0, l = l(t)
    # length = "l0*(1 + eps*t)"
    # gravity = "g"

    [initial]
    value = "A"                       # u(0)
    velocity = "0"                    # u'(0)

    [parameters]                      # numbers for the verification (every other name)
    A = 0.5

    [verify]                          # optional
    small = [0.01, 0.08]              # range of the geometric sequence of the small parameter
    slow = [0.1, 0.4]                 # its range for the slow-flow checks (compared at t = 1/small)
    points = 5
    dps = 30

    [domain]                          # optional: the range of each kernel argument (--emit)
    eps = [0, 0.1]
    A = [0.1, 2]

Every formula goes through :func:`pendsym.solve.parse.parse`.  Any fault raises
:class:`ProblemError` with a one-line message.
"""
from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from .parse import FormulaError, parse

MAX_BYTES = 64 * 1024
MAX_ORDER = 12
METHODS = ("auto", "lindstedt", "variation", "averaging")
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9]{0,15}$")
_TOP = {"name", "variable", "velocity", "time", "small", "order", "method", "k", "phi", "length",
        "gravity", "initial", "parameters", "verify", "domain"}


class ProblemError(ValueError):
    """A problem pendsym refuses; the message is one line."""


@dataclass(frozen=True)
class Problem:
    """A validated problem: θ'' + k²θ + φ(θ, θ', t) = 0 with its initial values and parameters."""

    name: str
    theta: sp.Symbol
    dtheta: sp.Symbol
    t: sp.Symbol
    small: sp.Symbol
    order: int
    method: str
    k: sp.Expr
    phi: sp.Expr
    theta_i: sp.Expr
    omega_i: sp.Expr
    parameters: dict = field(default_factory=dict)     # Symbol -> number (a string, exact)
    small_range: tuple = ("0.01", "0.08")
    slow_range: tuple = ("0.1", "0.4")               # ε of the slow-flow checks, compared at t = 1/ε
    points: int = 5
    dps: int = 30
    length: sp.Expr | None = None                      # set for the variable-length form
    domain: tuple = ()                                 # ((name, (lo, hi)), …): kernel argument ranges (--emit)

    @property
    def autonomous(self) -> bool:
        return not self.phi.has(self.t)

    def values(self) -> dict:
        """Exact SymPy values of the parameters (the small parameter excluded)."""
        return {s: sp.Rational(v) for s, v in self.parameters.items()}


def _name(data: dict, key: str, default: str) -> str:
    val = data.get(key, default)
    if not isinstance(val, str) or not _NAME.match(val):
        raise ProblemError(f"{key} must be a name of letters and digits, starting with a letter")
    if val in ("pi", "sin", "cos", "tan", "exp", "log", "sqrt", "abs", "sign", "sinh", "cosh", "tanh", "atan"):
        raise ProblemError(f"{key}: {val!r} is a reserved name")
    return val


def _number_text(key: str, val) -> str:
    if isinstance(val, bool) or not isinstance(val, (int, float, str)):
        raise ProblemError(f"parameter {key} must be a number")
    if isinstance(val, str):
        try:
            num = parse(val, {}, what=f"parameter {key}")
        except FormulaError as exc:
            raise ProblemError(str(exc)) from None
        if not num.is_number or not num.is_real:
            raise ProblemError(f"parameter {key} must be a real number")
        return str(sp.nsimplify(num)) if num.is_rational else str(sp.N(num, 40))
    if not math.isfinite(val):
        raise ProblemError(f"parameter {key} must be finite")
    return repr(val)


def _range(ver: dict, key: str, default: list, where: str) -> list:
    rng = ver.get(key, default)
    if (not isinstance(rng, list) or len(rng) != 2 or any(isinstance(r, bool) or not isinstance(r, (int, float))
                                                          or not 0 < r < 10 for r in rng) or rng[0] >= rng[1]):
        raise ProblemError(f"{where}: verify.{key} must be [low, high] with 0 < low < high < 10")
    return rng


def from_dict(data: dict, where: str = "problem") -> Problem:
    """Validate a problem given as a dict (the parsed TOML, or the Python API's keywords)."""
    unknown = sorted(set(data) - _TOP)
    if unknown:
        raise ProblemError(f"{where}: unknown key {unknown[0]!r} (known: {', '.join(sorted(_TOP))})")
    var = _name(data, "variable", "theta")
    vel = _name(data, "velocity", "d" + var)
    tim = _name(data, "time", "t")
    if "small" not in data:
        raise ProblemError(f"{where}: the small parameter must be named (small = \"eps\")")
    small = _name(data, "small", "eps")
    params = data.get("parameters", {})
    if not isinstance(params, dict):
        raise ProblemError(f"{where}: [parameters] must be a table of numbers")
    for pname in params:
        if not isinstance(pname, str) or not _NAME.match(pname):
            raise ProblemError(f"{where}: parameter name {str(pname)[:20]!r} is not a plain name")
    names_used = [var, vel, tim, small, *params]
    if len(set(names_used)) != len(names_used):
        raise ProblemError(f"{where}: the names of the variable, velocity, time, small parameter and "
                           f"parameters must differ")
    theta, dtheta = sp.Symbol(var, real=True), sp.Symbol(vel, real=True)
    t, eps = sp.Symbol(tim, real=True), sp.Symbol(small, positive=True)
    psyms = {p: sp.Symbol(p, real=True) for p in params}
    pvals = {psyms[p]: _number_text(p, v) for p, v in params.items()}
    env_const = {small: eps, **psyms}
    env = {var: theta, vel: dtheta, tim: t, **env_const}

    def formula(key: str, text, names) -> sp.Expr:
        try:
            return parse(text, names, what=key)
        except FormulaError as exc:
            raise ProblemError(str(exc)) from None

    order = data.get("order", 1)
    if isinstance(order, bool) or not isinstance(order, int) or not 1 <= order <= MAX_ORDER:
        raise ProblemError(f"{where}: order must be an integer from 1 to {MAX_ORDER}")
    method = data.get("method", "auto")
    if method not in METHODS:
        raise ProblemError(f"{where}: method must be one of {', '.join(METHODS)}")
    length = None
    if "length" in data or "gravity" in data:
        if "phi" in data or "k" in data:
            raise ProblemError(f"{where}: give either k and phi, or length and gravity, not both")
        length = formula("length", data.get("length"), {tim: t, **env_const})
        grav = formula("gravity", data.get("gravity", "1"), env_const)
        l0 = length.subs(t, 0)
        if l0 == 0:
            raise ProblemError(f"{where}: the length vanishes at t = 0")
        k = sp.sqrt(grav / l0)
        phi = 2 * sp.diff(length, t) / length * dtheta + (grav / length - grav / l0) * theta
    else:
        if "phi" not in data:
            raise ProblemError(f"{where}: phi (the perturbation in θ'' + k²θ + phi = 0) is missing")
        k = formula("k", data.get("k", "1"), env_const)
        phi = formula("phi", data["phi"], {"k": k, **env} if "k" not in env else env)
    if k.has(eps):
        raise ProblemError(f"{where}: k must not depend on the small parameter (put that part in phi)")
    init = data.get("initial", {})
    if not isinstance(init, dict) or set(init) - {"value", "velocity"}:
        raise ProblemError(f"{where}: [initial] holds value and velocity only")
    theta_i = formula("initial value", init.get("value", "0"), env_const)
    omega_i = formula("initial velocity", init.get("velocity", "0"), env_const)
    if theta_i == 0 and omega_i == 0:
        raise ProblemError(f"{where}: [initial] value and velocity are both 0: the unperturbed motion is at rest")
    ver = data.get("verify", {})
    if not isinstance(ver, dict) or set(ver) - {"small", "slow", "points", "dps"}:
        raise ProblemError(f"{where}: [verify] holds small, slow, points and dps only")
    rng = _range(ver, "small", [0.01, 0.08], where)
    slow = _range(ver, "slow", [0.1, 0.4], where)
    points = ver.get("points", 5)
    if isinstance(points, bool) or not isinstance(points, int) or not 3 <= points <= 12:
        raise ProblemError(f"{where}: verify.points must be an integer from 3 to 12")
    dps = ver.get("dps", 30)
    if isinstance(dps, bool) or not isinstance(dps, int) or not 30 <= dps <= 60:
        raise ProblemError(f"{where}: verify.dps must be an integer from 30 to 60")
    domain = _domain(data.get("domain", {}), {small, *params, "tau", tim}, where)
    name = data.get("name", "problem")
    if not isinstance(name, str) or len(name) > 200:
        raise ProblemError(f"{where}: name must be a short string")
    return Problem(name=name, theta=theta, dtheta=dtheta, t=t, small=eps, order=order, method=method,
                   k=k, phi=phi, theta_i=theta_i, omega_i=omega_i, parameters=pvals,
                   small_range=(repr(float(rng[0])), repr(float(rng[1]))),
                   slow_range=(repr(float(slow[0])), repr(float(slow[1]))), points=points, dps=dps,
                   length=length, domain=domain)


def _domain(table, names: set, where: str) -> tuple:
    """The [domain] table: a range [lo, hi] (finite numbers, lo < hi) for any kernel argument."""
    if not isinstance(table, dict):
        raise ProblemError(f"{where}: [domain] must be a table of ranges")
    out = []
    for key, rng in table.items():
        if key not in names:
            raise ProblemError(f"{where}: domain.{str(key)[:20]} is not a kernel argument (the small parameter, "
                               f"a parameter, tau or the time)")
        if (not isinstance(rng, list) or len(rng) != 2 or any(isinstance(r, bool) or not isinstance(r, (int, float))
                                                              or not math.isfinite(r) or abs(r) > 1e300 for r in rng)
                or rng[0] >= rng[1]):
            raise ProblemError(f"{where}: domain.{key} must be [low, high], finite numbers with low < high")
        out.append((key, (float(rng[0]), float(rng[1]))))
    return tuple(sorted(out))


def load(path) -> Problem:
    """Read and validate a problem file (TOML, UTF-8, at most 64 KiB)."""
    shown = "".join(ch if ch.isprintable() else "?" for ch in str(path))[:200]
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as exc:
        raise ProblemError(f"cannot read {shown}: {exc.strerror}") from None
    if len(raw) > MAX_BYTES:
        raise ProblemError(f"{shown} is larger than {MAX_BYTES // 1024} KiB")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ProblemError(f"{shown} is not UTF-8 text (byte {exc.start})") from None
    try:
        data = tomllib.loads(text)
    except (tomllib.TOMLDecodeError, RecursionError) as exc:
        msg = str(exc).splitlines()[0] if str(exc) else type(exc).__name__
        raise ProblemError(f"{shown} is not valid TOML: {msg[:120]}") from None
    return from_dict(data, where=Path(shown).name)
