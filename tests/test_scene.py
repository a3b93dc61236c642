"""pendsym.scene: a concrete configuration, built from the closure of the Results it names."""
import subprocess
import sys

import pytest

from pendsym import registry, scene

SCENE = "derivations/cellerier/scenes/gravity_pendulum_on_support.toml"


def test_example_scene(root):
    sc = scene.load(root / SCENE)
    rows, n_built = scene.evaluate(sc)
    vals = {i: float(v) for i, _, v in rows}
    # by hand from the printed δ = Kmgh/(2l²): 1e-7 · 5 · 9.81 · 0.66 / (2 · 0.994²)
    assert vals["cellerier.delta_static"] == pytest.approx(1.0e-7 * 5 * 9.81 * 0.66 / (2 * 0.994**2), rel=1e-12)
    # the practical form with ε = K p and p' = mg gives the same δ
    assert vals["cellerier.delta_practical"] == pytest.approx(vals["cellerier.delta_static"], rel=1e-12)
    assert n_built < len(registry.all_specs(["cellerier"]))


@pytest.mark.parametrize("text, message", [
    ('results = ["cellerier.delta_static"]\n[parameters]\nK = -1.0\nm = 1\ng = 1\nh = 1\nl = 1\n', "outside its domain"),
    ('results = ["cellerier.delta_static"]\n[parameters]\nK = 1.0e-7\n', "needs parameter"),
    ('results = ["cellerier.delta_static"]\n[parameters]\nK = 1.0\nm = 1\ng = 1\nh = 1\nl = 1\n', "outside the range"),
    ('results = ["nosuch.id"]\n', "unknown result id"),
    ('results = "x"\n', "non-empty list"),
    ('results = ["cellerier.delta_static"]\ncolour = 3\n', "unknown keys"),
    ('results = [\n', "not valid TOML"),
    ('results = ["cellerier.delta_static"]\n[parameters]\nK = "1e-7"\n', "finite number"),
])
def test_bad_scenes_are_one_line_errors_with_exit_2(tmp_path, text, message):
    f = tmp_path / "s.toml"
    f.write_text(text)
    p = subprocess.run([sys.executable, "-m", "pendsym.cli", "scene", str(f)], capture_output=True, text=True)
    assert p.returncode == 2
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], p.stderr


def run_scene(path, *extra):
    return subprocess.run([sys.executable, "-m", "pendsym.cli", "scene", str(path), *extra],
                          capture_output=True, text=True, timeout=120)


def one_line_exit_2(p, message):
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 2 and len(lines) == 1 and message in lines[0] and "Traceback" not in p.stderr, p.stderr
    assert p.stdout == ""


GOOD = 'results = ["cellerier.delta_static"]\n[parameters]\nK = 1e-7\nm = 5.0\ng = 9.81\nh = 0.66\nl = 0.994\n'


@pytest.mark.parametrize("content, message", [
    (b"\xff\xfe results = []", "not UTF-8"),
    (b"a = " + b"[" * 100_000 + b"]" * 100_000, "nested too deeply"),
    (GOOD.encode() + b"colour = 2.0\n", "not used by the scene's Results: colour"),
    (b'results = ["cellerier.F"]\n[parameters]\nh = 1e300\nm = 1e300\nthetadot = 1e300\n', "not a finite double"),
    (b'name = "evil\\u202E"\n' + GOOD.encode(), "control characters"),
    (b'results = ["cellerier.delta_static", "charbonnier1908.n21.dT"]\n[parameters]\nK = 1.0\n',
     "[parameters.<memoir>]"),
])
def test_hostile_scenes_are_one_line_errors(tmp_path, content, message):
    f = tmp_path / "s.toml"
    f.write_bytes(content)
    one_line_exit_2(run_scene(f), message)


def test_a_huge_scene_is_refused_before_it_is_read_whole(tmp_path):
    one_line_exit_2(run_scene("/dev/zero"), "larger than")


def test_a_value_outside_the_declared_range_is_refused(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text('results = ["haag1935.eq159.beta1"]\n[parameters]\nu = 900.0\nlambda = 0.1\n')
    one_line_exit_2(run_scene(f), "outside the range")


def test_json_output_is_valid_json(root):
    import json
    p = run_scene(root / SCENE, "--json")
    assert p.returncode == 0, p.stderr
    assert json.loads(p.stdout)["values"]
