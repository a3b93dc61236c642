"""pendsym.emit.kernels.plan and .printing: one codegen-AST block of statements, printed in
C99 and Python by SymPy's printers; docstrings give a kernel's own figures and point to the
contract."""
import math

import sympy as sp

from pendsym.emit import kernels as kn
from pendsym.result import KernelArg

u = sp.Symbol("u", positive=True)
lam = sp.Symbol("lambda", positive=True)
ARGS = (KernelArg("lambda", 1e-3, 10.0, unit="m"), KernelArg("u", 1e-6, 700.0))
FORM = lam * sp.Piecewise((u**2 / 12, u < sp.Rational(1, 8)), (1 - 2 * sp.tanh(u / 2) / u, True))


def _kernel(**figures) -> kn.Kernel:
    return kn.Kernel("beta", "test.eq1.beta", ARGS, FORM, "a rule", "β = λ(1 − 2 th(u/2)/u)", "n°1, eq. 1",
                     **figures)


def test_a_piecewise_is_an_if_chain_in_c():
    proto, definition = kn.c_function(_kernel())
    assert proto == "double beta(double lambda_, double u)"
    assert definition == (
        "double beta(double lambda_, double u)\n{\n"
        "    if (!(0.001 <= lambda_ && lambda_ <= 10.0)) {\n"
        "        errno = EDOM;  /* lambda_ outside its domain [0.001, 10] */\n"
        "        return NAN;\n"
        "    }\n"
        "    if (!(1e-06 <= u && u <= 700.0)) {\n"
        "        errno = EDOM;  /* u outside its domain [1e-06, 700] */\n"
        "        return NAN;\n"
        "    }\n"
        "    double x_0;\n"
        "    if (u < 1.0/8.0) {\n"
        "        x_0 = (1.0/12.0)*((u)*(u));\n"
        "    } else {\n"
        "        x_0 = 1 - 2*tanh((1.0/2.0)*u)/u;\n"
        "    }\n"
        "    return lambda_*x_0;\n}\n")


def test_a_piecewise_is_an_if_chain_in_python_and_the_function_runs():
    text = kn.py_function(_kernel())
    assert text.startswith("def beta(lambda_, u):\n    \"\"\"β = λ(1 − 2 th(u/2)/u) — test.eq1.beta (n°1, eq. 1).\n")
    assert text.endswith(
        "    if (u < 1/8):\n"
        "        x_0 = (1/12)*u**2\n"
        "    else:\n"
        "        x_0 = 1 - 2*math.tanh((1/2)*u)/u\n"
        "    return lambda_*x_0\n")
    ns = {"math": math}
    exec(compile(text, "<beta>", "exec"), ns)
    assert ns["beta"](2.0, 1e-3) == 2.0 * 1e-6 / 12 and ns["beta"](2.0, 3.0) == 2.0 * (1 - 2 * math.tanh(1.5) / 3.0)


def test_the_docstring_gives_only_the_kernels_figures_and_points_to_the_contract():
    acc = kn.Accuracy(225, 2.03, 0.96, (1.3, 0.2))
    naive = kn.Naive("printed", kn.Accuracy(225, 9.85e12, 3.28e12, (1.3, 1e-6)), "u in [1e-06, 0.125]")
    doc = _kernel(py_accuracy=acc, c_accuracy=kn.Accuracy(225, 1.9, 0.9, ()), naive=naive,
                  notes=("1 - 2*tanh(u/2)/u: series below 0.125 (1.93 ulp)",)).docstring()
    lines = doc.splitlines()
    assert lines[0] == "β = λ(1 − 2 th(u/2)/u) — test.eq1.beta (n°1, eq. 1)."
    assert lines[1] == "Domain: lambda in [0.001, 10] m; u in [1e-06, 700] 1."
    assert "Measured error on 225 points: Python 2.03 ulp (0.96 scaled), C 1.9 ulp (0.9 scaled)." in lines
    assert ("Naive printed form on the same points: 9.85e+12 ulp (3.28e+12 scaled); "
            "over the bound: u in [1e-06, 0.125].") in lines
    assert lines[-1].startswith(f"Contract (bound, κ, sampling, domain): {kn.CONTRACT}")
    assert "condition number" not in doc and "ill-conditioned" not in doc


def test_generated_docstrings_point_to_the_contract_once_each(generated):
    for path in sorted((generated / "python").glob("*.py")) + sorted((generated / "c").glob("*.h")):
        if path.stem == "pendulum":
            continue
        text = path.read_text()
        assert "Beyond 4 ulp only where" not in text, path.name
        lines = text.splitlines()
        if path.suffix == ".py":
            kernels = sum(1 for ln in lines if ln.startswith("def ") and not ln.startswith("def _"))
        else:
            kernels = sum(1 for ln in lines if ln.startswith("double ") and ln.endswith(");"))
        assert kernels > 0, path.name
        assert text.count("Contract (bound, κ, sampling, domain): docs/kernel-accuracy.md") == kernels, path.name


def test_the_contract_is_written_once(root):
    doc = (root / "docs" / "kernel-accuracy.md").read_text()
    for fact in ("4 ulp × max(1, κ)", "50 significant digits", "forward difference at 80 digits", "10⁻³⁵",
                 "measured as emitted", "withheld", "issue #11"):
        assert fact.lower() in doc.lower(), fact
