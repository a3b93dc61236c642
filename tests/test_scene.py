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
    ('results = ["cellerier.delta_static"]\n[parameters]\nK = 1.0\n', "needs parameter"),
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
