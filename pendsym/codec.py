"""A data-only codec: Python values ⇄ JSON-compatible data, for the disk cache.

``encode(value)`` gives plain data (None, bool, int, finite float, str, list,
dict with str keys) that ``json.dumps(..., allow_nan=False)`` accepts;
``decode(data)`` rebuilds an equal value (for SymPy, an identical tree:
``sp.srepr(decode(encode(e))) == sp.srepr(e)``).  Nothing is evaluated,
unpickled or parsed: a class is only ever looked up in a whitelist (the
``sympy`` namespace, SymPy's singletons) or, for classes of this project, in
a module under ``pendsym.`` or ``derivations.``; then it must be a SymPy class
(``sp.Basic``) or a frozen dataclass, else the data is rejected.

Every node other than None, bool, str, a small int and a finite float is a
JSON object tagged by ``"$"``:

    {"$": "int", "hex": "-0x1f"}                 a big int
    {"$": "float", "value": "nan" | "inf" | "-inf"}
    {"$": "tuple" | "list" | "frozenset", "items": [...]}
    {"$": "dict", "items": [[key, value], ...]}
    {"$": "mpf", "mpf": [sign, "hex mantissa", exponent, bits]}
    {"$": "mpc", "real": [...], "imag": [...]}
    {"$": "singleton", "name": "Pi"}            SymPy's S.Pi, S.Half, S.true …
    {"$": "symbol", "name": "x", "assumptions": {...}}
    {"$": "dummy", "name": "x", "index": 12, "assumptions": {...}}
    {"$": "integer", "value": int} · {"$": "rational", "p": int, "q": int}
    {"$": "sfloat", "mpf": [...], "precision": 53}
    {"$": "basic", "class": CLASS, "args": [...]}  any other SymPy tree node
    {"$": "class", "class": CLASS}                 a SymPy class as a value (Function('v'))
    {"$": "dataclass", "module": "pendsym.result", "qualname": "Evidence", "fields": {...}}

where CLASS is ``{"sympy": "Add"}``, ``{"module": ..., "qualname": ...}`` or
``{"undef": "v", "assumptions": {...}}`` (an undefined function).
Any other data, and any value of another type, raises :class:`CodecError`.
"""
from __future__ import annotations

import dataclasses
import importlib
import json
import math
import re
from functools import lru_cache
from typing import Any

import mpmath as mp
import sympy as sp
from mpmath.libmp import MPZ, finf, fnan, fninf, fzero
from sympy.codegen import cfunctions
from sympy.core.assumptions import _assume_defined
from sympy.core.function import AppliedUndef, UndefinedFunction
from sympy.core.singleton import Singleton
from sympy.functions.elementary.piecewise import ExprCondPair

__all__ = ["CodecError", "encode", "decode"]


class CodecError(ValueError):
    """A value the codec cannot encode, or data it cannot decode."""


_SMALL = 2 ** 63                       # ints beyond ±2⁶³ are written in hex
_NAME = r"[A-Za-z][A-Za-z0-9_]*"      # no leading underscore: no dunders, no privates
_MODULE = re.compile(rf"(?:pendsym|derivations)(?:\.{_NAME})*")
_QUALNAME = re.compile(rf"{_NAME}(?:\.{_NAME})*")
_HEX = re.compile(r"-?0x[0-9a-f]+")
_NONFINITE = {"nan": math.nan, "inf": math.inf, "-inf": -math.inf}
_SPECIAL_MPF = (fzero, fnan, finf, fninf)


# ----------------------------------------------------------------- public API
def encode(value: Any) -> Any:
    """JSON-compatible data for value; CodecError for a value of a type it does not know."""
    try:
        return _enc(value)
    except CodecError:
        raise
    except Exception as exc:  # RecursionError, a SymPy object that misbehaves …
        raise CodecError(f"cannot encode: {exc!r}") from exc


def decode(data: Any) -> Any:
    """The value encoded as data; CodecError for anything that is not such data."""
    try:
        return _dec(data, {})
    except CodecError:
        raise
    except Exception as exc:  # a constructor refusing its arguments, RecursionError …
        raise CodecError(f"cannot decode: {exc!r}") from exc


# ----------------------------------------------------------------- classes
@lru_cache(maxsize=None)
def sympy_classes() -> dict[str, type]:
    """The whitelist: SymPy classes by name, from the ``sympy`` namespace and from
    ``sympy.codegen.cfunctions`` (expm1, log1p…: the stable forms of the kernels), plus
    ExprCondPair (the pieces of a Piecewise)."""
    out = {}
    for namespace in (cfunctions, sp):
        out.update({name: obj for name, obj in vars(namespace).items()
                    if isinstance(obj, type) and issubclass(obj, sp.Basic) and obj.__name__ == name})
    out["ExprCondPair"] = ExprCondPair
    return out


def project_class(module: str, qualname: str) -> type:
    """The class module.qualname, for a module of this project (pendsym.…, derivations.…);
    CodecError for any other name, or when the object found is not a class of that name."""
    if not (isinstance(module, str) and _MODULE.fullmatch(module)
            and isinstance(qualname, str) and _QUALNAME.fullmatch(qualname)):
        raise CodecError(f"not a class of this project: {module!r}, {qualname!r}")
    try:
        obj = importlib.import_module(module)
    except ImportError as exc:
        raise CodecError(f"no module {module}") from exc
    for part in qualname.split("."):
        obj = getattr(obj, part, None)
    if not (isinstance(obj, type) and obj.__module__ == module and obj.__qualname__ == qualname):
        raise CodecError(f"{module}.{qualname} is not a class defined there")
    return obj


def _assumptions(a: Any) -> dict[str, bool]:
    """Checked assumptions: known names, boolean values."""
    if not (isinstance(a, dict) and all(k in _assume_defined and type(v) is bool for k, v in a.items())):
        raise CodecError(f"bad assumptions {a!r}")
    return dict(a)


def _enc_class(cls: type) -> dict:
    if isinstance(cls, UndefinedFunction):
        if cls.__bases__ != (AppliedUndef,):
            raise CodecError(f"undefined function {cls} with other bases")
        return {"undef": cls.__name__, "assumptions": _assumptions(cls._kwargs)}
    if sympy_classes().get(cls.__name__) is cls:
        return {"sympy": cls.__name__}
    if project_class(cls.__module__, cls.__qualname__) is cls and issubclass(cls, sp.Basic):
        return {"module": cls.__module__, "qualname": cls.__qualname__}
    raise CodecError(f"class {cls.__module__}.{cls.__qualname__} is not in the whitelist")


def _dec_class(ref: Any) -> type:
    keys = set(ref) if isinstance(ref, dict) else None
    if keys == {"sympy"}:
        cls = sympy_classes().get(ref["sympy"]) if isinstance(ref["sympy"], str) else None
        if cls is None:
            raise CodecError(f"not a whitelisted SymPy class: {ref['sympy']!r}")
        return cls
    if keys == {"undef", "assumptions"}:
        if not (isinstance(ref["undef"], str) and ref["undef"]):
            raise CodecError("bad undefined function name")
        return sp.Function(ref["undef"], **_assumptions(ref["assumptions"]))
    if keys == {"module", "qualname"}:
        cls = project_class(ref["module"], ref["qualname"])
        if not issubclass(cls, sp.Basic):
            raise CodecError(f"{cls.__qualname__} is not a SymPy class")
        return cls
    raise CodecError(f"bad class reference {ref!r}")


# ----------------------------------------------------------------- numbers
def _enc_int(n: int) -> Any:
    return n if -_SMALL < n < _SMALL else {"$": "int", "hex": hex(n)}


def _dec_int(d: Any) -> int:
    if type(d) is int:
        return d
    if isinstance(d, dict) and set(d) == {"$", "hex"} and d["$"] == "int" \
            and isinstance(d["hex"], str) and _HEX.fullmatch(d["hex"]):
        return int(d["hex"], 16)
    raise CodecError(f"not an int: {d!r}")


def _small(d: Any) -> int:
    if type(d) is not int:
        raise CodecError(f"not an int: {d!r}")
    return d


def _enc_mpf(t: tuple) -> list:
    sign, man, exp, bc = t
    return [int(sign), format(int(man), "x"), int(exp), int(bc)]


def _dec_mpf(d: Any) -> tuple:
    """A normalised mpf tuple, exactly as written: no rounding, whatever the working precision."""
    if not (isinstance(d, list) and len(d) == 4 and isinstance(d[1], str) and re.fullmatch(r"[0-9a-f]+", d[1])):
        raise CodecError(f"bad mpf {d!r}")
    sign, man, exp, bc = _small(d[0]), int(d[1], 16), _small(d[2]), _small(d[3])
    t = (sign, MPZ(man), exp, bc)
    if man == 0:
        if t not in _SPECIAL_MPF:
            raise CodecError(f"bad special mpf {d!r}")
    elif sign not in (0, 1) or man % 2 == 0 or bc != man.bit_length():
        raise CodecError(f"mpf not normalised {d!r}")
    return t


# ----------------------------------------------------------------- encoding
def _enc(v: Any) -> Any:
    t = type(v)
    if v is None or t is bool or t is str:
        return v
    if t is int:
        return _enc_int(v)
    if t is float:
        return v if math.isfinite(v) else {"$": "float", "value": repr(v)}
    if t is tuple or t is list:
        return {"$": t.__name__, "items": [_enc(x) for x in v]}
    if t is frozenset:
        items = [_enc(x) for x in v]
        return {"$": "frozenset", "items": sorted(items, key=lambda x: json.dumps(x, sort_keys=True))}
    if t is dict:
        return {"$": "dict", "items": [[_enc(k), _enc(x)] for k, x in v.items()]}
    if t is mp.mpf:
        return {"$": "mpf", "mpf": _enc_mpf(v._mpf_)}
    if t is mp.mpc:
        re_, im_ = v._mpc_
        return {"$": "mpc", "real": _enc_mpf(re_), "imag": _enc_mpf(im_)}
    if isinstance(v, sp.Basic):
        return _enc_basic(v)
    if isinstance(v, type) and issubclass(v, sp.Basic):
        return {"$": "class", "class": _enc_class(v)}
    if dataclasses.is_dataclass(v) and not isinstance(v, type):
        return _enc_dataclass(v)
    raise CodecError(f"cannot encode a {t.__module__}.{t.__qualname__}")


def _enc_basic(x: sp.Basic) -> dict:
    t = type(x)
    if isinstance(t, Singleton):
        if getattr(sp.S, t.__name__, None) is not x:
            raise CodecError(f"singleton {t.__name__} not in S")
        return {"$": "singleton", "name": t.__name__}
    if t is sp.Symbol:
        return {"$": "symbol", "name": x.name, "assumptions": _assumptions(x._assumptions_orig)}
    if t is sp.Dummy:
        return {"$": "dummy", "name": x.name, "index": x.dummy_index,
                "assumptions": _assumptions(x._assumptions_orig)}
    if t is sp.Integer:
        return {"$": "integer", "value": _enc_int(int(x.p))}
    if t is sp.Rational:
        return {"$": "rational", "p": _enc_int(int(x.p)), "q": _enc_int(int(x.q))}
    if t is sp.Float:
        return {"$": "sfloat", "mpf": _enc_mpf(x._mpf_), "precision": x._prec}
    if isinstance(x, sp.Atom):
        raise CodecError(f"cannot encode the atom {t.__name__}")
    if not all(isinstance(a, sp.Basic) for a in x.args):
        raise CodecError(f"{t.__name__} has arguments that are not SymPy objects")
    return {"$": "basic", "class": _enc_class(t), "args": [_enc(a) for a in x.args]}


def _enc_dataclass(v: Any) -> dict:
    cls = type(v)
    if project_class(cls.__module__, cls.__qualname__) is not cls or not cls.__dataclass_params__.frozen:
        raise CodecError(f"{cls.__qualname__} is not a frozen dataclass of this project")
    fields = dataclasses.fields(cls)
    if not all(f.init for f in fields):
        raise CodecError(f"{cls.__qualname__} has fields outside __init__")
    return {"$": "dataclass", "module": cls.__module__, "qualname": cls.__qualname__,
            "fields": {f.name: _enc(getattr(v, f.name)) for f in fields}}


# ----------------------------------------------------------------- decoding
_KEYS = {
    "int": {"hex"}, "float": {"value"}, "tuple": {"items"}, "list": {"items"},
    "frozenset": {"items"}, "dict": {"items"}, "mpf": {"mpf"}, "mpc": {"real", "imag"},
    "singleton": {"name"}, "symbol": {"name", "assumptions"},
    "dummy": {"name", "index", "assumptions"}, "integer": {"value"}, "rational": {"p", "q"},
    "sfloat": {"mpf", "precision"}, "basic": {"class", "args"}, "class": {"class"},
    "dataclass": {"module", "qualname", "fields"},
}


def _items(d: Any) -> list:
    if not isinstance(d, list):
        raise CodecError("items must be a list")
    return d


def _dec(d: Any, dummies: dict) -> Any:
    """Decode one node; dummies maps a Dummy's identity to the one object decoded for it."""
    t = type(d)
    if d is None or t is bool or t is str or t is int:
        return d
    if t is float:
        if not math.isfinite(d):
            raise CodecError("non-finite float outside its tag")
        return d
    if t is not dict or not isinstance(d.get("$"), str) or d["$"] not in _KEYS \
            or set(d) != _KEYS[d["$"]] | {"$"}:
        raise CodecError(f"not codec data: {str(d)[:80]}")
    tag = d["$"]
    if tag == "int":
        return _dec_int(d)
    if tag == "float":
        if d["value"] not in _NONFINITE:
            raise CodecError(f"bad float {d['value']!r}")
        return _NONFINITE[d["value"]]
    if tag in ("tuple", "list", "frozenset"):
        items = [_dec(x, dummies) for x in _items(d["items"])]
        return {"tuple": tuple, "list": list, "frozenset": frozenset}[tag](items)
    if tag == "dict":
        pairs = _items(d["items"])
        if not all(isinstance(p, list) and len(p) == 2 for p in pairs):
            raise CodecError("dict items must be pairs")
        return {_dec(k, dummies): _dec(v, dummies) for k, v in pairs}
    if tag == "mpf":
        return mp.mp.make_mpf(_dec_mpf(d["mpf"]))
    if tag == "mpc":
        return mp.mp.make_mpc((_dec_mpf(d["real"]), _dec_mpf(d["imag"])))
    if tag == "dataclass":
        return _dec_dataclass(d, dummies)
    return _dec_sympy(tag, d, dummies)


def _dec_sympy(tag: str, d: dict, dummies: dict) -> Any:
    if tag == "singleton":
        name = d["name"]
        obj = getattr(sp.S, name, None) if isinstance(name, str) and re.fullmatch(_NAME, name) else None
        if not (isinstance(obj, sp.Basic) and isinstance(type(obj), Singleton) and type(obj).__name__ == name):
            raise CodecError(f"not a SymPy singleton: {name!r}")
        return obj
    if tag in ("symbol", "dummy"):
        if not isinstance(d["name"], str):
            raise CodecError("a symbol's name must be a str")
        a = _assumptions(d["assumptions"])
        if tag == "symbol":
            return sp.Symbol(d["name"], **a)
        ident = (d["name"], _small(d["index"]), tuple(sorted(a.items())))
        if ident not in dummies:
            dummies[ident] = sp.Dummy(d["name"], dummy_index=ident[1], **a)
        return dummies[ident]
    if tag == "integer":
        return sp.Integer(_dec_int(d["value"]))
    if tag == "rational":
        p, q = _dec_int(d["p"]), _dec_int(d["q"])
        if q < 2 or math.gcd(p, q) != 1:
            raise CodecError(f"rational {p}/{q} not in lowest terms")
        return sp.Rational(p, q)
    if tag == "sfloat":
        prec = _small(d["precision"])
        if not 1 < prec < 10 ** 7:
            raise CodecError(f"bad precision {prec}")
        return sp.Float._new(_dec_mpf(d["mpf"]), prec, zero=False)
    if tag == "class":
        return _dec_class(d["class"])
    # tag == "basic"
    cls = _dec_class(d["class"])
    if issubclass(cls, sp.Atom):
        raise CodecError(f"an atom ({cls.__name__}) has no generic form")
    args = tuple(_dec(a, dummies) for a in _items(d["args"]))
    if not all(isinstance(a, sp.Basic) for a in args):
        raise CodecError(f"{cls.__name__}: arguments must be SymPy objects")
    try:
        obj = cls(*args, evaluate=False)
    except TypeError:
        obj = cls(*args)
    if type(obj) is not cls or obj.args != args:
        raise CodecError(f"{cls.__name__} is not rebuilt exactly from its arguments")
    return obj


def _dec_dataclass(d: dict, dummies: dict) -> Any:
    cls = project_class(d["module"], d["qualname"])
    if not (dataclasses.is_dataclass(cls) and cls.__dataclass_params__.frozen):
        raise CodecError(f"{cls.__qualname__} is not a frozen dataclass")
    fields = dataclasses.fields(cls)
    given = d["fields"]
    if not (isinstance(given, dict) and set(given) == {f.name for f in fields} and all(f.init for f in fields)):
        raise CodecError(f"{cls.__qualname__}: fields do not match")
    return cls(**{name: _dec(v, dummies) for name, v in given.items()})
