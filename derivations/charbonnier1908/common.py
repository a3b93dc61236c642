"""What every section of Charbonnier 1908 shares: its key, ids, sources, the OCR readings met in
several paragraphs, the precision and parameters of the checks, and the kernel arguments."""
from __future__ import annotations



from pendsym import checks
from pendsym.checks import Geometric  # noqa: F401  (the memoir's sections import it from here)
from pendsym.result import printed  # noqa: F401
from pendsym.result import KernelArg, Reading, Source

MEMOIR = "charbonnier1908"
DPS = checks.DPS          # working digits of a truth (the engine confirms it at checks.CONFIRM_DPS)
K_CHECK = "1.3"          # k of the worked examples' integrations
ALPHA_CHECK = "0.3"      # amplitude of an integration whose small parameter is not α
K_OSCILLATOR, ALPHA_OSCILLATOR = "1.7", "0.4"   # θ'' + k²θ + εφ = 0 of the checks of n°8–9 and n°19–20


def rid(paragraph: int, name: str) -> str:
    """The id of a Result of paragraph n° ``paragraph``: charbonnier1908.nNN.name."""
    return f"{MEMOIR}.n{paragraph:02d}.{name}"


def src(para: str, page: int) -> Source:
    """The source of a Result: paragraph n° (and item) and the page of the printed memoir."""
    return Source(MEMOIR, para, page)


EPSILONS = Geometric("1e-4", "1e-2")   # ε of the oscillator checks


# ----------------------------------------------------------------- OCR readings met in several paragraphs
READ_ALPHA_AS_X = Reading("x² (x³)", "α² (α³): the OCR reads α as x")
READ_RATE = Reading("α (or x) where the rate a stands", "a: the OCR confuses a, α and x", certain=True)
READ_DALPHA = Reading("Δx", "Δα")

# ----------------------------------------------------------------- kernel arguments (declared domains)
ALPHA = KernelArg("alpha", 1e-3, 3.0, unit="rad")
K = KernelArg("k", 0.1, 10.0, unit="1/s")
TIME = KernelArg("t", 0.0, 10.0, log=False, unit="s")
THETA = KernelArg("theta", -1.0, 1.0, log=False, unit="rad")
THETADOT = KernelArg("thetadot", -10.0, 10.0, log=False, unit="rad/s")
L0 = KernelArg("l_0", 1e-3, 100.0, unit="m")
RATE = KernelArg("a", 1e-8, 1e-1, unit="1/s")
BETA = KernelArg("beta", 1e-3, 10.0)
MU = KernelArg("mu", 1e-6, 1.0)
