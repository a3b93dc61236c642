"""pendsym.scenes: the inverted-blade gravity meter (scenes/gravity_meter_inverted_blade.toml).

The truth (slow tier) is the most complete model the engine has for an inverted pendulum on a blade: the slow
periodic oscillation of the rigid pendulum on the exact large-deflection blade with M = EI/(mg) < 0 and g < 0
(``pendsym.nonlinear_blade.orbit(..., mode="slow")``: collocation on the elastica, 20 digits), its period against
the scene's answer, and its sensitivity d log T/d log g at fixed hardware by a 5-point stencil of those orbits in g
(M = EI/(mg) divided by the same factor) against the scene's.  Neither uses a formula the scene used.

The quick tier checks the budget's shape (the base is the inverted blade's, the circular error of a hanging pendulum
is replaced) and that unstable or inconsistent inverted scenes are one-line errors, exit 2.
"""
import tomllib

import mpmath as mp
import pytest
import sympy as sp

from pendsym import blade as B
from pendsym import scenes, suspension

SCENE = "scenes/gravity_meter_inverted_blade.toml"


def data_of(root):
    return tomllib.loads((root / SCENE).read_text(encoding="utf-8"))


def budget_of(root, **changes):
    data = data_of(root)
    for path, value in changes.items():
        table, key = path.split("__")
        data[table][key] = value
    return scenes.solve(scenes.from_data(data))


def massless(root, tolerance=1e-5):
    """The scene without the blade's density (its mass not estimated), at a tighter tolerance."""
    data = data_of(root)
    del data["suspension"]["density"]
    data["wanted"]["tolerance"] = tolerance
    sc = scenes.from_data(data)
    return sc, scenes.solve(sc)


# ----------------------------------------------------------------- the truth (slow)
DPS = 20
NODES = 4          # five nodes agree to 26 digits of the swing at this amplitude (measured)


def exact_blade(sc, scale=1):
    """The inverted blade of the scene at g·scale: M = −EI/(m g scale), exact decimal inputs."""
    sus = sc.suspension
    with mp.workdps(45):
        EI = mp.mpf(repr(sus.E)) * mp.mpf(repr(sus.width)) * mp.mpf(repr(sus.thickness)) ** 3 / 12
        M = EI / (mp.mpf(repr(sc.bob.mass)) * mp.mpf(repr(sc.g)) * scale)
    return B.Blade(sp.Rational(repr(sus.length)), -sp.Float(M, 45))


def exact_swing(sc, scale=1, dps=DPS, nodes=NODES):
    """The swing time of the slow oscillation of amplitude α on the exact inverted blade, g·scale (g < 0)."""
    from pendsym import nonlinear_blade
    bl = exact_blade(sc, scale)
    with mp.workdps(nonlinear_blade.working_dps(bl, dps)):
        a, R, alpha = (mp.mpf(repr(x)) for x in (sc.bob.a, sc.bob.R, sc.amplitude))
        g = -mp.mpf(repr(sc.g)) * scale
        return nonlinear_blade.orbit(bl, a, R, g, alpha, nodes, dps, mode="slow").period / 2


def linear_swing(sc, dps=30):
    """π/n of the slow mode of the linear eigenproblem on the directly solved inverted blade (g < 0)."""
    bl = exact_blade(sc)
    sus = suspension.solve(bl, dps)
    with mp.workdps(sus.wdps):
        a, R = mp.mpf(repr(sc.bob.a)), mp.mpf(repr(sc.bob.R))
        slow = min(suspension.modes(sus, a, R, -mp.mpf(repr(sc.g))), key=lambda mode: mode.n2)
        return mp.pi / mp.sqrt(slow.n2)


def mass_factor(sc, scale=1, dps=25):
    """T/T0 of the slow mode on the inverted blade with its mass (inertia and weight, pendsym.massive_blade: the
    linear blade with density μ = m'/λ, det D(ω²) = 0 by findroot) over the same massless."""
    from pendsym import massive_blade
    sus = sc.suspension
    mu = sp.Float(repr(sus.density * sus.width * sus.thickness / sc.bob.mass), 30)     # μ(s)/m, per metre
    blade = massive_blade.MassiveBlade(exact_blade(sc, scale), mu)
    args = (repr(sc.bob.a), repr(sc.bob.R), str(-sp.Rational(repr(sc.g)) * scale))
    n2 = massive_blade.principal_n2(blade, *args, dps=dps, slowest=True)
    n2_0 = massive_blade.principal_n2(massive_blade.MassiveBlade(blade.blade, 0), *args, dps=dps, slowest=True)
    with mp.workdps(dps + 10):
        return mp.sqrt(n2_0 / n2)


@pytest.mark.slow
def test_gravity_meter_against_the_exact_inverted_blade_and_the_massive_blade(root):
    """The scene as given (with the blade's mass): the slow oscillation on the exact (massless) elastica times the
    massive blade's linear T/T0 (no model of the engine has both; their coupling, ~ the product of the amplitude's
    1e-4 and the weight's 3e-3, is far below the stated error)."""
    sc = scenes.load(root / SCENE)
    b = scenes.solve(sc)
    T_true = exact_swing(sc) * mass_factor(sc)
    off = abs(b.swing - float(T_true)) / float(T_true)
    assert off <= b.error, f"answer {b.swing!r} vs truth {T_true}: {off:.3g} > stated {b.error:.3g}"
    rows = {r.key: r for r in b.rows}
    assert rows["inverted_weight"].status == "kept" and rows["inverted_inertia"].status == "dropped"
    # without the blade's weight the answer would be off by more than ten times the stated error
    assert abs(b.swing / (1 + rows["inverted_weight"].value) / float(T_true) - 1) > 10 * b.error


@pytest.mark.slow
def test_gravity_meter_without_its_mass_against_the_slow_oscillation_on_the_exact_inverted_blade(root):
    """The same instrument without the blade's mass, at 1e-5: the base and the isochronism (283) checked tightly."""
    sc, b = massless(root)
    assert b.error <= 1e-5
    T_true = exact_swing(sc)
    off = abs(b.swing - float(T_true)) / float(T_true)
    assert off <= b.error, f"answer {b.swing!r} vs truth {T_true}: {off:.3g} > stated {b.error:.3g}"
    # the linear base alone is off by more than ten times the stated error: the isochronism matters
    T_lin = linear_swing(sc)
    assert abs(b.T0 / float(T_lin) - 1) < 1e-13               # the base is the exact linear theory
    assert abs(b.T0 - float(T_true)) / float(T_true) > 10 * b.error
    # the circular error of a hanging pendulum (θ0²/16, lengthening) in place of (283) would fail the truth
    hanging = b.T0 * (1 + sc.amplitude**2 / 16)
    assert abs(hanging - float(T_true)) / float(T_true) > 10 * b.error
    # the collocation has converged: one more node changes nothing at the scale of the stated error
    assert abs(exact_swing(sc, nodes=NODES + 1) / T_true - 1) < 1e-15


def stencil_sensitivity(sc, with_mass: bool, h="1e-6"):
    """S = d log T/d log g at fixed E, I, m, a, R, λ (and the blade's density): the 5-point stencil of log T over
    g(1 + kh), T of the exact slow oscillation (times the massive blade's T/T0 ``with_mass``); error O((Sh)⁴)."""
    h = sp.Rational(h)
    with mp.workdps(30):
        logs = {k: mp.log(exact_swing(sc, 1 + k * h, dps=25) * (mass_factor(sc, 1 + k * h) if with_mass else 1))
                for k in (-2, -1, 1, 2)}
        return (8 * (logs[1] - logs[-1]) - (logs[2] - logs[-2])) / (12 * suspension.number(h))


@pytest.mark.slow
def test_gravity_meter_sensitivity_against_a_stencil_of_exact_orbits_in_g(root):
    """The scene's S against the stencil of the truths, with the blade's mass and without (where the stated error is
    smaller: the base's S is exact, the isochronism's part 2S ΔT/T is first order in ε)."""
    sc_bare, bare = massless(root)
    S_bare = stencil_sensitivity(sc_bare, with_mass=False)
    assert abs(bare.sensitivity - float(S_bare)) <= bare.sensitivity_error, (bare.sensitivity, S_bare)
    assert 50 < S_bare < 200          # ~200 times an ordinary pendulum's 1/2 (the sources' figure)
    # the base's S alone (without the isochronism's part) would be off by more than its stated error
    base_only = next(r for r in bare.rows if r.key == "inverted_isochronism").value
    assert abs(bare.sensitivity - 2 * bare.sensitivity * base_only - float(S_bare)) > bare.sensitivity_error
    sc = scenes.load(root / SCENE)
    b = scenes.solve(sc)
    S_true = stencil_sensitivity(sc, with_mass=True)
    assert abs(b.sensitivity - float(S_true)) <= b.sensitivity_error, (b.sensitivity, S_true, b.sensitivity_error)
    assert abs(bare.sensitivity - float(S_true)) > b.sensitivity_error     # the blade's weight matters


# ----------------------------------------------------------------- quick
def test_the_budget_of_the_gravity_meter(root):
    b = budget_of(root)
    rows = {r.key: r for r in b.rows}
    assert rows["inverted_blade"].status == "kept" and rows["inverted_blade"].value == float("inf")
    assert rows["inverted_isochronism"].status == "kept" and rows["inverted_isochronism"].value < 0
    assert rows["inverted_weight"].status == "kept" and rows["inverted_weight"].value > 0
    assert rows["inverted_inertia"].status == "dropped"
    # the hanging pendulum's effects do not apply: the circular error is replaced by (283), no direct blade
    assert not {"circular", "blade", "blade_isochronism", "blade_inertia", "blade_weight"} & rows.keys()
    assert {k for k, r in rows.items() if r.status == "not available"} == {"inverted_clamping"}
    assert b.within and 5 < b.period < 7 and b.sensitivity > 50
    kept = [rows[k].value for k in ("inverted_isochronism", "inverted_weight")]
    assert b.swing == pytest.approx(b.T0 * (1 + kept[0]) * (1 + kept[1]), rel=1e-15)
    # without the density the blade's mass is listed, not counted
    _, bare = massless(root)
    assert {r.key for r in bare.rows if r.status == "not available"} == {
        "inverted_clamping", "inverted_mass"}
    assert bare.within and bare.error < b.error / 10


def test_closer_to_the_critical_distance_the_period_and_the_sensitivity_grow(root):
    near, far = budget_of(root, bob__a=0.03565), budget_of(root, bob__a=0.0350)
    assert near.T0 > far.T0 and near.sensitivity > far.sensitivity > 0
    rel = lambda b: next(r.estimate for r in b.rows if r.key == "inverted_isochronism")
    assert abs(rel(near)) > abs(rel(far))                  # (283) ∝ G ∝ 1/ε


def test_at_zero_amplitude_the_base_is_the_answer(root):
    data = data_of(root)
    data["amplitude"] = 0.0
    del data["suspension"]["density"]
    b = scenes.solve(scenes.from_data(data))
    assert b.swing == b.T0 and [r.key for r in b.rows if r.status == "kept"] == ["inverted_blade"]


def refused(root, message, **changes):
    with pytest.raises(scenes.SceneError) as exc:
        data = data_of(root)
        for path, value in changes.items():
            table, _, key = path.partition("__")
            if key:
                data[table][key] = value
            else:
                data[table] = value
        scenes.solve(scenes.from_data(data))
    line = str(exc.value)
    assert "\n" not in line and message in line, line


def test_unstable_or_inconsistent_inverted_scenes_are_refused(root):
    refused(root, "not below the critical distance", bob__a=0.036)              # a ≥ a1: unstable
    refused(root, "cannot hold the bob", suspension__thickness=1.0e-5)          # u ≥ π/2: too weak a blade
    refused(root, "beyond the perturbation theory", amplitude=0.05)            # θ0²G/16 too large
    refused(root, "the blade's weight (m'/m", bob__a=0.035682, amplitude=0.0)   # m'/(8mε) too large near a1
    refused(root, "support is given with an inverted blade", support={"compliance": 1e-7})
    refused(root, "drift is given with an inverted blade", drift={"rate": 0.001})


def test_an_unstable_gravity_meter_is_one_line_with_exit_2(root, tmp_path, capsys):
    from pendsym import cli
    text = (root / SCENE).read_text(encoding="utf-8").replace("a = 0.0355 ", "a = 0.0400 ")
    assert "a = 0.0400" in text
    f = tmp_path / "unstable.toml"
    f.write_text(text, encoding="utf-8")
    code = cli.main(["scene", str(f), "--json"])
    out, err = capsys.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1 and "Traceback" not in err, err
    assert "bob.a = 0.04 is not below the critical distance" in lines[0]


def test_the_gravity_meter_as_json(root, capsys):
    import json

    from pendsym import cli
    assert cli.main(["scene", str(root / SCENE), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["base"]["inverted"] is True and d["base"]["l_m"] is None and d["base"]["T0_s"] > 2
    assert d["sensitivity"] > 50 and 0 < d["sensitivity_error"] < d["sensitivity"] / 100
    assert d["within_tolerance"] is True and d["period_s"] == pytest.approx(2 * d["swing_time_s"])


def test_the_page_of_the_gravity_meter_names_its_base(root):
    from pendsym.scenes import page
    b = budget_of(root)
    tex = page.tex(b, "gm")
    assert "(the base)" in tex and "eq034.n2\\_inverted" in tex and "Sensitivity" in tex
