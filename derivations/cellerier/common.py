"""What every section of Cellérier's memoir shares: its key, ids, locators, the OCR readings met
in several places, the precision and the model pendulum of the checks.

The memoir (Ch. Cellérier, *Mouvement simultané d'un pendule et de ses supports*) has no
numbered paragraphs, no equation numbers and no section headings, and the OCR text shows no
page numbers: a Result is located by the paragraph it stands under, named by its opening
words (its incipit: the OCR's words, its formulas transcribed and its misreadings of α, θ, δ,
ρ and F' read as in the Results), and by a quote of the text; no page is recorded.
"""
from __future__ import annotations


import sympy as sp

from pendsym import checks
from pendsym.checks import Geometric  # noqa: F401  (the memoir's sections import it from here)
from pendsym.result import printed  # noqa: F401
from pendsym.result import Reading, Source

MEMOIR = "cellerier"
DPS = checks.DPS          # working digits of a truth (the engine confirms it at checks.CONFIRM_DPS)
H_TRUTH = "0.2"            # h/l of the model pendulum on its support (m = g = l = 1, C = m h l)

# The paragraphs of the memoir that hold a Result, in the order of the text, by their opening words.
PARAGRAPHS = {
    "relative_axes": "En nommant x', y', les coordonnées de dm par rapport à des axes O'X', O'Y'",
    "inertia": "Nommant ensuite r la distance de l'élément dm au couteau",
    "length_l": "En posant l = C/(mh), on pourra l'écrire",
    "earlier_memoir": "Cette équation coïncide avec celle qui se trouve",
    "substitution": "En substituant les valeurs de μ' et de u, il en résulte, dans le cas actuel",
    "pressures": "Pour cela reprenons les deux premières équations du mouvement",
    "pivot_neglected": "Ces valeurs des pressions P et Q ne sont point très-petites",
    "two_forces": "On voit que P et Q pourraient être remplacées par deux forces F, F'",
    "horizontal": "la seconde est donc beaucoup plus grande, et par suite la pression est plus énergique",
    "static_deviation": "Le mouvement du support est alors dû uniquement à la force horizontale Q",
    "sin_theta": "Or, de la relation cos θ = cos α cos²φ + sin²φ, on tire",
    "radical": "et en supposant que α ne dépasse pas 2°, le radical précédent peut être remplacé par l'unité",
    "cos_theta_one": "d'où résulte, en remplaçant de même cos θ par 1",
    "principal_terms": "On voit qu'en ne conservant dans le calcul que les termes principaux",
    "bar_forced": "En substituant Q = Σ γ cos(ρt + ρ'), on satisfera à toutes ces conditions",
    "slow_load": "Si ρc/n et par suite ρz/n est très-petit",
    "principal_rho": "Or, pour le terme principal de Q, on a ρ = √(g/l)",
    "test_force": "De ce qui précède résulte que la valeur trouvée pour δ doit être regardée comme très-exacte",
    "example": "expression où n'entrent que des rapports abstraits. En supposant, par exemple",
}


def rid(name: str) -> str:
    """The id of a Result: cellerier.name."""
    return f"{MEMOIR}.{name}"


def src(paragraph: str, quote: str) -> Source:
    """The source of a Result: the paragraph it stands under (by its incipit) and a quote of the text."""
    return Source(MEMOIR, f"« {PARAGRAPHS[paragraph]} … »", None, None, quote)


def proof_of(expected) -> checks.Proof:
    """SymPy reduces the derived form to ``expected``."""
    return checks.Proof(f"SymPy reduces the derived form to {sp.sstr(expected)}",
                        holds=lambda expr: sp.simplify(expr - expected) == 0, truth="symbolic")


def series_leading(expr: sp.Expr, scale: dict, order: int) -> sp.Expr:
    """expr with each symbol of ``scale`` scaled by λ, expanded to λ^order, then λ → 1."""
    lam = sp.Symbol("lambda", positive=True)
    ser = sp.series(expr.subs({k: lam * v for k, v in scale.items()}, simultaneous=True), lam, 0, order + 1).removeO()
    return sp.expand(ser.subs(lam, 1))


# ----------------------------------------------------------------- OCR readings met in several places
def read_l_as_t(shows: str, read_as: str) -> Reading:
    """The OCR prints Cellérier's l (the length C/(mh)) as t."""
    return Reading(shows, f"{read_as}: OCR reads l as t")
