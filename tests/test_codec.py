"""pendsym.codec: exact round trips through strict JSON; data naming anything else is refused."""
import json
import math
import os
import random
import subprocess
import sys

import mpmath as mp
import pytest
import sympy as sp

from pendsym import codec, registry, stages
from pendsym.emit import kernels as kn
from pendsym.result import Evidence, KernelArg


def through_json(value):
    """encode, strict JSON text, decode."""
    text = json.dumps(codec.encode(value), allow_nan=False, sort_keys=True)
    return codec.decode(json.loads(text))


def same(a, b) -> bool:
    """Equal, of the same type, and for SymPy the same tree."""
    if isinstance(a, sp.Basic) or isinstance(b, sp.Basic):
        return type(a) == type(b) and a == b and sp.srepr(a) == sp.srepr(b)  # == : Function("v") is a new class each time
    return type(a) is type(b) and a == b


# ----------------------------------------------------------------- Python values
PLAIN = [
    None, True, False, 0, 1, -7, 2 ** 63, -(2 ** 63), 3 ** 200, -(5 ** 90), 1.5, 1e300, 5e-324, 0.1,
    "", "pendule — θ\u0000\ud800", (), (1, "a", None), [1, [2.5, (3,)]], {}, {"a": 1},
    {(1, 2): "pair", 3: [4], None: True, frozenset({1}): 2.0, "s": {"nested": (1,)}},
    frozenset(), frozenset({1, "b", (2, 3), 4.5}),
]


@pytest.mark.parametrize("value", PLAIN, ids=lambda v: type(v).__name__)
def test_plain_values_round_trip(value):
    back = through_json(value)
    assert same(back, value)
    if isinstance(value, dict):
        assert list(back) == list(value)          # order kept
        assert all(type(k) is type(j) for k, j in zip(back, value))


def test_bool_int_float_stay_apart():
    back = through_json([True, 1, 1.0, False, 0, 0.0])
    assert [type(x) for x in back] == [bool, int, float, bool, int, float]


def test_non_finite_floats_and_signed_zero():
    back = through_json((math.inf, -math.inf, math.nan, -0.0, 0.0))
    assert back[0] == math.inf and back[1] == -math.inf and math.isnan(back[2])
    assert math.copysign(1, back[3]) == -1 and math.copysign(1, back[4]) == 1
    json.dumps(codec.encode(back), allow_nan=False)   # strict JSON


def test_mpmath_exact_whatever_the_precision():
    with mp.workdps(80):
        values = [+mp.pi, -mp.e / 3, mp.mpf(2) ** -2000, mp.mpf("1e100000"), mp.mpf(0),
                  mp.inf, -mp.inf, mp.mpc(+mp.pi, -mp.sqrt(2)), mp.mpc(0, 1)]
        data = json.dumps(codec.encode(values), allow_nan=False)
    with mp.workdps(5):                              # decoding does not round to the context
        back = codec.decode(json.loads(data))
    for a, b in zip(values, back):
        assert type(a) is type(b)
        assert (a._mpf_ == b._mpf_) if isinstance(a, mp.mpf) else (a._mpc_ == b._mpc_)
    nan = through_json(mp.nan)
    assert isinstance(nan, mp.mpf) and mp.isnan(nan)


# ----------------------------------------------------------------- SymPy
x, y = sp.symbols("x y")
p = sp.Symbol("p", positive=True)
n = sp.Symbol("n", integer=True, nonnegative=True)
c = sp.Symbol("c", commutative=False)
v = sp.Function("v", real=True)
f = sp.Function("f")
s = sp.Symbol("s")

EXPRESSIONS = [
    x, p, n, c, sp.Symbol("k", real=True, zero=False),
    sp.Integer(12), sp.Integer(-3 ** 80), sp.Rational(-7, 12), sp.Rational(3 ** 60, 2 ** 70),
    sp.Float("0.1", 50), sp.Float(2.5), sp.Float("-1e-400", 30), sp.Float(0.0), sp.Float("1.0", 3),
    sp.pi, sp.E, sp.I, sp.oo, -sp.oo, sp.zoo, sp.nan, sp.S.Half, sp.S.One, sp.S.Zero, sp.S.NegativeOne,
    sp.EulerGamma, sp.Catalan, sp.true, sp.false, sp.S.EmptySet,
    v(s), f(x, y), sp.Derivative(v(s), s), sp.Derivative(f(x, y), (x, 2), y),
    sp.Integral(sp.exp(-p * s) * v(s), (s, 0, sp.oo)), sp.Integral(f(x), x),
    sp.Subs(sp.Derivative(f(x), x), x, 0), sp.Lambda((x, y), x ** 2 + y), sp.Tuple(1, x, sp.Tuple()),
    sp.Piecewise((x, x < 1), (x ** 2, sp.And(x >= 1, y > 0)), (0, True)),
    sp.Eq(x, y, evaluate=False), sp.Lt(x, 1), sp.Ge(p, n), sp.Ne(x, 2), sp.Gt(y, x),
    sp.Add(x, x, evaluate=False), sp.Mul(2, 3, x, evaluate=False), sp.Pow(4, sp.S.Half, evaluate=False),
    sp.Mul(sp.Add(1, 1, evaluate=False), sp.Pow(x, 1, evaluate=False), evaluate=False),
    sp.sqrt(1 - sp.sin(x) ** 2) / (1 + sp.cos(2 * p)), sp.elliptic_k(p / 3), sp.atan2(y, x),
    sp.Sum(1 / n ** 2, (n, 1, sp.oo)), sp.O(x ** 3), c * x * c ** 2, sp.re(f(x)) + sp.Abs(x),
    sp.exp(sp.I * sp.pi * x) - sp.factorial(n) + sp.binomial(n, 2),
    kn.Grouped(x + 1) + x,
]


@pytest.mark.parametrize("expr", EXPRESSIONS, ids=lambda e: sp.srepr(e)[:40])
def test_sympy_round_trip(expr):
    assert same(through_json(expr), expr)


def test_symbol_assumptions_exact():
    k = sp.Symbol("k", positive=True, integer=True)
    back = through_json(k)
    assert back.assumptions0 == k.assumptions0 and back._assumptions_orig == k._assumptions_orig
    assert through_json(sp.Symbol("k")) != k


def test_undefined_functions_keep_assumptions():
    back = through_json((v, f, v(s)))
    assert back[0] == v and back[0]._kwargs == v._kwargs and back[0](s).is_real
    assert back[1] == f and back[1] != v
    assert same(back[2], v(s))
    assert same(through_json(sp.sin), sp.sin)       # a SymPy class as a value


def test_dummy_identity():
    d = sp.Dummy("t", real=True)
    e = sp.Integral(sp.exp(-d) * x, (d, 0, 1))
    back = through_json((e, d, d + 1))
    assert same(back[0], e) and same(back[1], d)
    assert back[1] is back[0].limits[0][0] is back[2].args[1]   # one object for one Dummy
    other = sp.Dummy("t", real=True)
    assert through_json(other) != back[1]


def test_non_canonical_trees_are_kept():
    e = sp.Mul(sp.Integer(2), sp.Add(x, x, evaluate=False), sp.Pow(x, 0, evaluate=False), evaluate=False)
    back = through_json(e)
    assert sp.srepr(back) == sp.srepr(e) and back != sp.simplify(e)


# ----------------------------------------------------------------- dataclasses of the project
EVIDENCE = Evidence(kind="order", passed=True, truth="quadrature at 40 digits", max_residual=1.5e-12,
                    order=4.02, expected_order=4.0, band=(3.5, 4.5), param="k", params=(("k", "0.1"),),
                    series=((0.1, 1e-5), (0.05, 6.2e-7)), printed_series=((0.1, math.inf),),
                    printed_agrees=None, values=((0.1, 2.0, 2.0000001),), note="ok")


def test_evidence_and_kernel_arg():
    assert same(through_json(EVIDENCE), EVIDENCE)
    arg = KernelArg("u", 1e-3, 700.0, log=True, unit="rad")
    assert same(through_json(arg), arg)
    assert same(through_json([EVIDENCE, None, arg]), [EVIDENCE, None, arg])


def test_kernel_of_a_charbonnier_result():
    rid = next(i for i, spec in registry.all_specs(["charbonnier1908"]).items() if spec.kernel is not None)
    result = registry.build(ids=[rid])[rid]
    k = kn.kernel_of(result)
    assert k is not None and k.reference and k.naive is not None
    back = through_json(k)
    assert back == k and sp.srepr(back.expr) == sp.srepr(k.expr)
    assert all(t._mpf_ == u._mpf_ for (t, _), (u, _) in zip(back.reference, k.reference)
               if isinstance(t, mp.mpf))
    assert kn.py_function(back) == kn.py_function(k)


def forms(results):
    return [(rid, name, e) for rid, r in results.items() for name, e in (("derived", r.derived), ("printed", r.printed))]


def assert_forms_round_trip(results):
    bad = [(rid, name) for rid, name, e in forms(results) if not same(through_json(e), e)]
    assert not bad


def test_forms_of_one_memoir_round_trip():
    results = registry.build(memoirs=["cellerier"])
    assert len(results) > 10
    assert_forms_round_trip(results)


@pytest.fixture(scope="module")
def every_result():
    return stages.results()


@pytest.mark.slow
def test_every_derived_and_printed_form_round_trips(every_result):
    assert {r.spec.memoir for r in every_result.values()} == set(registry.memoirs())
    assert_forms_round_trip(every_result)


# ----------------------------------------------------------------- what it refuses to encode
class Opaque:
    pass


@pytest.mark.parametrize("value", [
    lambda: 1, len, os.system, Opaque(), Opaque, {1, 2}, b"bytes", bytearray(b"x"), 1j, range(3),
    mp.pi, sys.stdout, [1, lambda: 2], {"k": object()}, sp.Wild("w"), type, codec.CodecError,
], ids=lambda v: type(v).__name__)   # ids without addresses: the same in every test worker
def test_refuses_to_encode(value):
    with pytest.raises(codec.CodecError):
        codec.encode(value)


def test_refuses_ctypes_and_files(tmp_path):
    import ctypes
    with pytest.raises(codec.CodecError):
        codec.encode(ctypes.c_int(3))
    with open(tmp_path / "f", "w") as fh, pytest.raises(codec.CodecError):
        codec.encode(fh)


def test_refuses_result_and_spec():
    r = registry.build(ids=["cellerier.P_exact"])["cellerier.P_exact"]
    for value in (r, r.spec):                     # they hold functions
        with pytest.raises(codec.CodecError):
            codec.encode(value)


# ----------------------------------------------------------------- what it refuses to decode
DANGER = [
    {"$": "class", "class": {"module": "os", "qualname": "system"}},
    {"$": "basic", "class": {"module": "os", "qualname": "system"}, "args": ["touch /tmp/x"]},
    {"$": "dataclass", "module": "builtins", "qualname": "eval", "fields": {"source": "1"}},
    {"$": "class", "class": {"module": "builtins", "qualname": "eval"}},
    {"$": "basic", "class": {"module": "subprocess", "qualname": "Popen"}, "args": [["true"]]},
    {"$": "dataclass", "module": "subprocess", "qualname": "Popen", "fields": {"args": ["true"]}},
    {"$": "dataclass", "module": "this", "qualname": "d", "fields": {}},          # import prints
    {"$": "class", "class": {"module": "pendsym.cli", "qualname": "os.system"}},  # a module's attribute
    {"$": "class", "class": {"module": "pendsym.cli", "qualname": "__builtins__"}},
    {"$": "class", "class": {"module": "pendsym.__main__", "qualname": "main"}},
    {"$": "class", "class": {"module": "pendsymx", "qualname": "A"}},
    {"$": "class", "class": {"module": "sympy.core.add", "qualname": "Add"}},    # no module paths for SymPy
    {"$": "class", "class": {"sympy": "sympify"}},                               # a function, not a class
    {"$": "class", "class": {"sympy": "parse_expr"}},
    {"$": "basic", "class": {"sympy": "Symbol"}, "args": []},                     # atoms only by their tag
    {"$": "basic", "class": {"sympy": "Add"}, "args": ["__import__('os').system('true')", 1]},
    {"$": "singleton", "name": "register"},
    {"$": "singleton", "name": "__class__"},
    {"$": "class", "class": {"undef": "f", "assumptions": {"real": "yes"}}},
    {"$": "class", "class": {"undef": "f", "assumptions": {"__init__": True}}},
]


@pytest.mark.parametrize("data", DANGER, ids=lambda d: json.dumps(d)[:60])
def test_refuses_to_decode_anything_else(data, monkeypatch):
    called = []
    monkeypatch.setattr(os, "system", lambda *a: called.append(a))
    monkeypatch.setattr(subprocess, "Popen", lambda *a, **k: called.append(a))
    before = set(sys.modules)
    with pytest.raises(codec.CodecError):
        codec.decode(data)
    assert not called
    assert "this" not in set(sys.modules) - before


def test_refuses_dataclasses_that_do_not_match():
    good = codec.encode(EVIDENCE)
    extra = {**good, "fields": {**good["fields"], "evil": "1"}}
    missing = {**good, "fields": {k: x for k, x in good["fields"].items() if k != "note"}}
    for data in (extra, missing):
        with pytest.raises(codec.CodecError):
            codec.decode(data)
    not_dataclass = [
        {"$": "dataclass", "module": "pendsym.registry", "qualname": "UnknownResult", "fields": {}},
        {"$": "dataclass", "module": "pendsym.emit.kernels", "qualname": "KernelPy", "fields": {}},
        {"$": "dataclass", "module": "pendsym.emit.kernels", "qualname": "Grouped", "fields": {}},
        {"$": "class", "class": {"module": "pendsym.emit.kernels", "qualname": "KernelPy"}},
        {"$": "class", "class": {"module": "pendsym.result", "qualname": "Evidence"}},
    ]
    for data in not_dataclass:
        with pytest.raises(codec.CodecError):
            codec.decode(data)


@pytest.mark.parametrize("data", [
    [1, 2], {"a": 1}, {"$": "tuple"}, {"$": "tuple", "items": [], "x": 1}, {"$": "nope"}, math.inf,
    {"$": "float", "value": "1.5"}, {"$": "int", "hex": "12"}, {"$": "int", "hex": 12},
    {"$": "dict", "items": [[{"$": "list", "items": []}, 1]]},          # unhashable key
    {"$": "dict", "items": [[1, 2, 3]]},
    {"$": "mpf", "mpf": [0, "2", 0, 2]},                                # not normalised
    {"$": "mpf", "mpf": [0, "0", 5, 0]},
    {"$": "mpf", "mpf": [2, "1", 0, 1]},
    {"$": "mpf", "mpf": [0, "-1", 0, 1]},
    {"$": "rational", "p": 2, "q": 4}, {"$": "rational", "p": 1, "q": 1},
    {"$": "sfloat", "mpf": [0, "1", 0, 1], "precision": -3},
    {"$": "symbol", "name": 3, "assumptions": {}},
    {"$": "dummy", "name": "d", "index": "1", "assumptions": {}},
    {"$": "basic", "class": {"sympy": "Add"}, "args": [1, 2]},          # raw ints are not SymPy
    {"$": "basic", "class": {"sympy": "Pow"}, "args": [{"$": "symbol", "name": "x", "assumptions": {}}]},
], ids=lambda d: json.dumps(d)[:50])
def test_rejects_malformed_data(data):
    with pytest.raises(codec.CodecError):
        codec.decode(data)


def test_rejects_deep_nesting():
    data = 1
    for _ in range(100_000):
        data = {"$": "list", "items": [data]}
    with pytest.raises(codec.CodecError):
        codec.decode(data)


def test_mutated_data_decodes_or_raises_codec_error():
    """Random damage to valid data never escapes as another exception."""
    rng = random.Random(1)
    base = codec.encode([EVIDENCE, EXPRESSIONS, PLAIN[:12]])
    text = json.dumps(base)
    junk = [None, True, 0, -1, 2 ** 70, 1.5, "", "x", "$", [], {}, {"$": "list"}, "Add", "pendsym.result"]
    for _ in range(300):
        data = json.loads(text)
        for _ in range(rng.randint(1, 3)):
            _mutate(data, rng, junk)
        try:
            codec.decode(data)
        except codec.CodecError:
            pass


def _mutate(data, rng, junk):
    node = data
    while True:
        kids = list(node.items()) if isinstance(node, dict) else list(enumerate(node)) if isinstance(node, list) else []
        if not kids:
            return
        k, child = rng.choice(kids)
        if not isinstance(child, (dict, list)) or rng.random() < 0.15:
            node[k] = rng.choice(junk)
            return
        node = child


def test_the_kernels_stable_functions_round_trip():
    from sympy.codegen.cfunctions import expm1, log1p
    x = sp.Symbol("x", positive=True)
    for e in (expm1(x) / x, log1p(x**2) - expm1(-x)):
        assert same(through_json(e), e)
