"""pendsym.scenes: the temperature coefficient d log T/dϑ (issue #15; Haag n°14, (223), (315)).

The truth is independent of the Results the scene uses: the same instrument's linear period computed directly at
ϑ = ±h (h = 1e-6 K): the blade's length λ(1 + αϑ) and its M = EI/(mg) times 1 + (β + 4α)ϑ (E grows by β, I = e³h/12
by 4α: n°14's own definitions, and the schema's), the pendulum's a and R by 1 + α'ϑ, g and m fixed; the blade solved
by ``pendsym.suspension`` (the linearised (2)–(3) integrated, 30 digits) and the rigid pendulum on it by the
eigenproblem K q = n² 𝕄 q (M < 0 and g < 0 for the inverted blade, n°100); the principal (direct) or slow
(inverted) mode; a centred difference of log T = −½ log n² in ϑ.  No formula of the memoir is used.
"""
import math
import tomllib

import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as B
from pendsym import scenes, suspension
from pendsym.scenes import budget

METER = "scenes/gravity_meter_inverted_blade.toml"
REGULATOR = "scenes/regulator_spring_blade.toml"
# per kelvin: a steel blade's α and β, a brass rod's α' (the check's own numbers, large enough to see each term)
STEEL_BRASS = {"alpha": 11e-6, "beta": -2.4e-4, "alpha_prime": 19e-6}
H = mp.mpf("1e-6")      # K: the centred difference's step (its error O(h² c³) ~ 1e-15 of c)
DPS = 30


def data_of(root, path, temperature=None, massless=False):
    data = tomllib.loads((root / path).read_text(encoding="utf-8"))
    if temperature is not None:
        data["temperature"] = dict(temperature)
    if "temperature" not in data["wanted"]["quantities"]:
        data["wanted"]["quantities"] = [*data["wanted"]["quantities"], "temperature"]
    if massless:
        data["suspension"].pop("density", None)
    return data


def log_T(sc, theta):
    """log of the linear swing time (π/n) at ϑ = theta kelvin, from the blade solved directly."""
    sus, bob, t = sc.suspension, sc.bob, sc.temperature
    sign = -1 if sus.mounting == "inverted" else 1
    with mp.workdps(DPS + 15):
        x = lambda v: mp.mpf(repr(v))
        alpha, beta, rod = x(t.alpha), x(t.beta), x(t.alpha_prime)
        EI = x(sus.E) * x(sus.width) * x(sus.thickness) ** 3 / 12
        M = sign * EI / (x(bob.mass) * x(sc.g)) * (1 + (beta + 4 * alpha) * theta)
        lam = x(sus.length) * (1 + alpha * theta)
        a, R, g = x(bob.a) * (1 + rod * theta), x(bob.R) * (1 + rod * theta), sign * x(sc.g)
        solved = suspension.solve(B.Blade(sp.Float(lam, DPS + 15), sp.Float(M, DPS + 15)), DPS)
    with mp.workdps(solved.wdps):
        K = suspension.stiffness_matrix(solved, a, 1, g)
        ev = mp.eig(mp.inverse(suspension.mass_matrix(a, R)) * K, left=False, right=False)
        n2 = sorted(mp.re(e) for e in ev)[0]        # the principal (direct) or the slow (inverted) mode
        assert n2 > 0
        return -mp.log(n2) / 2 + mp.log(mp.pi)


def truth(sc):
    """d log T/dϑ by the centred difference over ±H."""
    return float((log_T(sc, H) - log_T(sc, -H)) / (2 * H))


def solve(root, path, temperature=STEEL_BRASS, **kw):
    sc = scenes.from_data(data_of(root, path, temperature, **kw))
    return sc, scenes.solve(sc)


# ----------------------------------------------------------------- the independent check
@pytest.mark.parametrize("path", [REGULATOR, METER])
def test_coefficient_against_the_instrument_warmed(root, path):
    """The scene's d log T/dϑ against the period computed directly at ±1e-6 K, within its stated error; the rigid
    pendulum's α'/2 alone (what a knife edge would give) is outside it."""
    sc, b = solve(root, path)
    true = truth(sc)
    assert abs(b.temperature - true) <= b.temperature_error, (b.temperature, true, b.temperature_error)
    assert b.temperature_error < abs(true) / 10
    assert abs(STEEL_BRASS["alpha_prime"] / 2 - true) > b.temperature_error


@pytest.mark.parametrize("path", [REGULATOR, METER])
@pytest.mark.parametrize("alone", ["alpha", "beta", "alpha_prime"])
def test_each_term_is_kept(root, path, alone):
    """Each coefficient alone (the others 0): the scene's answer must match the directly warmed instrument, which it
    could not if the effect dropped that coefficient's terms (the answer would be 0, or α'/2 for α' alone, both
    outside the stated error)."""
    temperature = {k: (v if k == alone else 0.0) for k, v in STEEL_BRASS.items()}
    sc, b = solve(root, path, temperature)
    true = truth(sc)
    assert abs(b.temperature - true) <= b.temperature_error, (alone, b.temperature, true, b.temperature_error)
    assert abs(true) > b.temperature_error
    if alone == "alpha_prime":      # the blade's part of α''s term (the rod moves the bob against the blade)
        assert abs(true - STEEL_BRASS["alpha_prime"] / 2) > b.temperature_error


def test_in_the_budget_and_json(root):
    sc, b = solve(root, METER)
    out = budget.as_json(b, "m")
    assert out["temperature_coefficient_per_K"] == b.temperature
    assert out["temperature_coefficient_error"] == b.temperature_error
    assert "eq315.dg" in out["temperature_model"] and "eq314" not in out["temperature_model"].split(";")[0]
    text = budget.text(b, "m")
    assert "temperature coefficient d log T/dϑ" in text and "per K" in text
    # built from the Results it needs: (315)'s closure ((272), (271), (270), (60), …) beside the period's
    plain = tomllib.loads((root / METER).read_text(encoding="utf-8"))
    plain.pop("temperature", None)
    plain["wanted"]["quantities"] = [q for q in plain["wanted"]["quantities"] if q != "temperature"]
    without = scenes.solve(scenes.from_data(plain))
    assert 0 < b.built - without.built <= 12 and b.built < b.total / 10
    assert (b.period, b.error) == (without.period, without.error)


# ----------------------------------------------------------------- errors: one line, exit 2
@pytest.mark.parametrize("change, needle", [
    (lambda d: d.update(temperature={"alpha": 1e-5, "beta": 0.01, "alpha_prime": 1e-5}), "temperature.beta"),
    (lambda d: d.update(temperature={"alpha": 1e-3, "beta": 0.0, "alpha_prime": 1e-5}), "temperature.alpha"),
    (lambda d: d.update(temperature={"alpha": 1e-5, "beta": 0.0}), "alpha_prime"),
    (lambda d: d.update(temperature={"alpha": "1e-5", "beta": 0.0, "alpha_prime": 0.0}), "temperature.alpha"),
    (lambda d: d.pop("temperature"), "required when wanted.quantities asks for 'temperature'"),
    (lambda d: d["wanted"].update(quantities=["period"]), "does not ask for 'temperature'"),
    (lambda d: d.update(suspension={"kind": "knife"}), "knife suspension"),
])
def test_bad_temperature_is_one_line(root, change, needle):
    data = data_of(root, METER, STEEL_BRASS)
    change(data)
    with pytest.raises(scenes.SceneError) as exc:
        scenes.from_data(data)
    line = str(exc.value)
    assert "\n" not in line and needle in line, line


def test_holed_blade_cannot_give_it(root):
    data = data_of(root, "scenes/gravity_meter_rhombus_blade.toml", STEEL_BRASS)
    with pytest.raises(scenes.SceneError) as exc:
        scenes.solve(scenes.from_data(data))
    line = str(exc.value)
    assert "\n" not in line and "'temperature'" in line and "rhombus" in line, line


def test_the_example_scene_as_written(root):
    """scenes/gravity_meter_inverted_blade.toml's own (cited) coefficients: its answer against the meter warmed."""
    sc = scenes.load(root / METER)
    b = scenes.solve(sc)
    true = truth(sc)
    assert sc.temperature is not None and "temperature" in sc.wanted.quantities
    assert abs(b.temperature - true) <= b.temperature_error, (b.temperature, true, b.temperature_error)
    assert abs(true) > 10 * b.temperature_error


def test_the_inverted_coefficients_error_is_first_order_in_epsilon(root):
    """(315) and (314) are leading order in ε = (a1 − a)/λ: the scene's residual against the warmed meter (massless,
    zero amplitude, a moved towards a1) must fall like ε¹ and stay within the stated |c|ε (measured: −0.0108 ε)."""
    from derivations.haag1935.scene_effects import _epsilon
    points = []
    for a in (0.0355, 0.03565, 0.03568):
        data = data_of(root, METER, STEEL_BRASS, massless=True)
        data["bob"]["a"], data["amplitude"] = a, 0.0
        sc = scenes.from_data(data)
        b = scenes.solve(sc)
        true = truth(sc)
        assert abs(b.temperature - true) <= b.temperature_error
        points.append((math.log(_epsilon(b.inst)), math.log(abs(b.temperature - true) / abs(true))))
    (x0, y0), (x1, y1) = points[0], points[-1]
    assert abs((y1 - y0) / (x1 - x0) - 1) < 0.05, points


def test_a_long_direct_blade_cannot_give_it(root):
    """λ/a > 0.1: (223) is first order in λ/a; chapter I's general (60) is not evaluated by any scene effect."""
    data = data_of(root, REGULATOR, STEEL_BRASS)
    data["bob"]["a"] = 9 * data["suspension"]["length"]
    with pytest.raises(scenes.SceneError) as exc:
        scenes.solve(scenes.from_data(data))
    line = str(exc.value)
    assert "\n" not in line and "'temperature'" in line and "λ/a > 0.1" in line, line
