"""The safe formula parser and the problem schema: attacks and junk give one-line errors, exit 2."""
import subprocess
import sys
import time

import pytest
import sympy as sp
from hypothesis import given, settings, strategies as st

from pendsym.solve import ProblemError, from_dict
from pendsym.solve.parse import FormulaError, parse

X = sp.Symbol("x", real=True)

ATTACKS = [
    "().__class__.__bases__[0].__subclasses__()", "__import__('os').system('ls')", "x.__class__",
    "__builtins__", "lambda: 0", "(lambda q: q)(x)", "9**9**9", "2**64**64", "10**10**10**10",
    "(" * 200 + "x" + ")" * 200, "-" * 5000 + "x", "x" + "+x" * 1500, "open('/etc/passwd')",
    "eval('1')", "exec('1')", "sympify('x')", "x[0]", "[x for x in x]", "{x: 1}", "'x'", "b'x'",
    "x if x else x", "x and x", "x < 1", "f'{x}'", "x @ x", "x // 2", "x % 2", "1j", "True",
    "sin(x, x)", "sin(x=x)", "sin(*x)", "x; x", "import os", "x = 1", "1/0", "0**-1", "1e999",
    "x**x", "x**(1/x)", "sin", "y", "_x", "x\n__import__('os')", "\x00", "",
]


@pytest.mark.parametrize("text", ATTACKS)
def test_attack_is_refused_in_one_line_at_once(text):
    t0 = time.perf_counter()
    with pytest.raises(FormulaError) as exc:
        parse(text, {"x": X})
    assert time.perf_counter() - t0 < 10.0       # a guard against a hang (9**9**9 evaluated), not a speed goal
    assert "\n" not in str(exc.value) and len(str(exc.value)) < 400


def test_allowed_formula_becomes_the_expected_sympy():
    got = parse("-x**3/6 + sin(x)*cos(2*x) - abs(x)*sign(x) + sqrt(x) + exp(-x) + 0.5*pi", {"x": X})
    want = -X**3 / 6 + sp.sin(X) * sp.cos(2 * X) - sp.Abs(X) * sp.sign(X) + sp.sqrt(X) + sp.exp(-X) + sp.pi / 2
    assert sp.simplify(got - want) == 0


@settings(max_examples=300, deadline=2000)
@given(st.text(alphabet=st.sampled_from(list("x()+-*/.0123456789 _sincoab[]'\"lmd:,=e")), max_size=60))
def test_fuzz_text_either_parses_or_gives_one_line(text):
    try:
        out = parse(text, {"x": X})
    except FormulaError as exc:
        assert "\n" not in str(exc)
    else:
        assert out.free_symbols <= {X}


@settings(max_examples=200, deadline=2000)
@given(st.text(max_size=80))
def test_fuzz_any_unicode(text):
    try:
        parse(text, {"x": X})
    except FormulaError as exc:
        assert "\n" not in str(exc)


@pytest.mark.parametrize("data, needle", [
    ({"phi": "eps*theta"}, "small parameter"),
    ({"small": "eps", "phi": "eps*theta.real"}, "attribute"),
    ({"small": "eps", "phi": "eps*y"}, "unknown name"),
    ({"small": "eps", "phi": "eps*theta", "order": 99}, "order"),
    ({"small": "eps", "phi": "eps*theta", "bogus": 1}, "unknown key"),
    ({"small": "eps", "phi": "eps*theta", "parameters": {"A": "os"}}, "parameter"),
    ({"small": "eps", "phi": "eps*theta", "k": "eps"}, "small parameter"),
    ({"small": "sin", "phi": "1"}, "reserved"),
    ({"small": "eps", "phi": "eps*theta", "verify": {"dps": 10}}, "dps"),
])
def test_bad_problem_one_line(data, needle):
    with pytest.raises(ProblemError) as exc:
        from_dict({"initial": {"value": "1"}, **data})
    assert needle in str(exc.value) and "\n" not in str(exc.value)


def run(*args):
    return subprocess.run([sys.executable, "-m", "pendsym.cli", *args], capture_output=True, text=True)


@pytest.mark.parametrize("body", [
    'small = "eps"\nphi = "().__class__"\n',
    'small = "eps"\nphi = "9**9**9"\n',
    'small = "eps"\nphi = "' + "(" * 100 + "theta" + ")" * 100 + '"\n',
    'small = "eps"\nphi = "lambda: 1"\n',
    'small = "eps"\nphi = "__import__(\'os\')"\n',
    'this is not toml',
    'small = "eps"\nphi = "eps*theta"\n',
])
def test_cli_bad_file_is_exit_2_one_line(tmp_path, body):
    f = tmp_path / "p.toml"
    f.write_text(body)
    p = run("solve", str(f), "--no-verify")
    assert p.returncode == 2, (p.stdout, p.stderr)
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("pendsym: error:"), p.stderr
    assert p.stdout == ""


def test_cli_missing_file_exit_2():
    p = run("solve", "/nonexistent/p.toml")
    assert p.returncode == 2 and "Traceback" not in p.stderr
