"""derivations.cellerier.common: ids, locators, readings and the shared helpers."""
import sympy as sp

from derivations.cellerier import common


def test_ids_and_locators():
    assert common.rid("delta_static") == "cellerier.delta_static"
    source = common.src("pressures", "Q = −m d²·(y1 + h sin θ)/dt²")
    assert source.memoir == "cellerier" and source.page is None and source.eq is None
    assert source.para == "« Pour cela reprenons les deux premières équations du mouvement … »"
    assert source.quote.startswith("Q = ")


def test_incipits_are_distinct():
    assert len(set(common.PARAGRAPHS.values())) == len(common.PARAGRAPHS)


def test_proof_of_can_fail():
    x = sp.Symbol("x")
    assert common.proof_of(x).holds(x)
    assert not common.proof_of(x).holds(2 * x)


def test_series_leading_keeps_the_terms_up_to_the_order():
    x, y = sp.symbols("x y")
    assert common.series_leading(sp.sin(x) * sp.cos(y), {x: x, y: y}, 2) == x
    assert common.series_leading(sp.sin(x + y), {x: x, y: y}, 3) == sp.expand(x + y - (x + y) ** 3 / 6)


def test_reading_of_l_as_t():
    reading = common.read_l_as_t("t²", "l²")
    assert (reading.shows, reading.read_as) == ("t²", "l²: OCR reads l as t")
