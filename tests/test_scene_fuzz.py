"""Fuzz the hardware scene loader and the ``scene`` command with hypothesis.

Generated scenes: valid ones mutated at a random key (wrong types, missing and unknown keys,
negative and zero lengths, NaN and ±inf, huge numbers, deep nesting), random tables, random
text and bytes.  The contract: every input either answers (text on stdout, exit 0) or is
refused with exactly one line on stderr and exit 2, with nothing on stdout; never a
traceback, never a partial output.  Quick tier: 1,530 scenes (each property with a sample); the slow
tier runs the same properties on 13,470 more (the full tier's 15,000 in all).
"""
import copy
import math
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pendsym import cli, scene
from pendsym import scenes

BASE = {
    "name": "fuzz",
    "g": 9.81,
    "amplitude": 0.05,
    "bob": {"mass": 5.0, "a": 0.66, "R": 0.3},
    "suspension": {"kind": "knife"},
    "support": {"compliance": 1e-7, "mass": 10.0},
    "wanted": {"quantities": ["period", "rate"], "tolerance": 1e-7, "target_period": 2.0},
}
THREAD = {"kind": "thread", "length": 2.0, "EA": 1e6}
BLADE = {"kind": "blade", "E": 2e11, "thickness": 1e-4, "width": 0.02, "length": 0.008, "mounting": "direct"}

scalars = st.one_of(
    st.integers(min_value=-(2**70), max_value=2**70),
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from([0, 0.0, -0.0, -1.0, 1e308, -1e308, 5e-324, 1e-300, math.nan, math.inf, -math.inf]),
    st.booleans(),
    st.text(max_size=20),
    st.sampled_from(["knife", "thread", "blade", "direct", "inverted", "period", "rate", "swing", ""]),
)
values = st.recursive(scalars, lambda kids: st.one_of(st.lists(kids, max_size=4),
                                                      st.dictionaries(st.text(max_size=8), kids, max_size=4)),
                      max_leaves=12)


def deep(n):
    v = 1.0
    for i in range(n):
        v = {"x": v} if i % 2 else [v]
    return v


PATHS = [(), ("name",), ("g",), ("amplitude",), ("bob",), ("bob", "mass"), ("bob", "a"), ("bob", "R"),
         ("suspension",), ("suspension", "kind"), ("suspension", "length"), ("suspension", "EA"),
         ("suspension", "E"), ("suspension", "thickness"), ("suspension", "width"), ("suspension", "mounting"),
         ("support",), ("support", "compliance"), ("support", "mass"), ("drift",), ("drift", "rate"),
         ("wanted",), ("wanted", "quantities"), ("wanted", "tolerance"), ("wanted", "target_period")]


@st.composite
def mutated(draw):
    """A valid scene (knife, thread or blade) with one to three keys changed, removed or added."""
    data = copy.deepcopy(BASE)
    kind = draw(st.sampled_from(["knife", "thread", "blade"]))
    if kind == "thread":
        data["suspension"] = dict(THREAD)
        del data["bob"]["a"]
    elif kind == "blade":
        data["suspension"] = dict(BLADE)
    if draw(st.booleans()):
        data["drift"] = {"rate": draw(st.floats(-1e-3, 1e-3))}
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(PATHS))
        op = draw(st.sampled_from(["set", "set", "delete", "unknown", "deep", "scale"]))
        parent = data
        for p in path[:-1]:
            parent = parent.get(p) if isinstance(parent, dict) else None
            if not isinstance(parent, dict):
                break
        if not isinstance(parent, dict):
            continue
        key = path[-1] if path else draw(st.text(min_size=1, max_size=6))
        if op == "set":
            parent[key] = draw(values)
        elif op == "delete":
            parent.pop(key, None)
        elif op == "unknown":
            parent[draw(st.text(min_size=1, max_size=6))] = draw(values)
        elif op == "deep":
            parent[key] = deep(draw(st.integers(1, 60)))
        elif isinstance(parent.get(key), float):
            parent[key] = parent[key] * draw(st.sampled_from([-1.0, 0.0, 1e-12, 1e12, 1e300, 1.5, 0.5]))
    return data


def refused_in_one_line(exc: Exception) -> None:
    msg = str(exc)
    assert msg and "\n" not in msg and "Traceback" not in msg, msg


def load_or_refuse(data):
    try:
        return scenes.from_data(data)
    except scene.SceneError as exc:
        refused_in_one_line(exc)
        return None


# each property runs on a sample in the quick tier and on many more examples in the slow tier (below)
TABLES = st.dictionaries(st.text(max_size=10), values, max_size=8)
FILES = st.one_of(st.binary(max_size=300), st.text(max_size=300).map(lambda s: s.encode("utf-8", "surrogatepass")))


def table_is_refused(data):
    assert load_or_refuse(data) is None or set(data) >= {"bob", "suspension", "wanted", "g", "amplitude"}


def file_is_refused(tmp_path_factory, content):
    f = tmp_path_factory.mktemp("fz") / "s.toml"
    f.write_bytes(content)
    try:
        data = scene.parse(f)
        if scene.is_hardware(data):
            scenes.from_data(data)
    except scene.SceneError as exc:
        refused_in_one_line(exc)


@settings(max_examples=1000, deadline=None, suppress_health_check=list(HealthCheck))
@given(mutated())
def test_mutated_scenes_load_or_are_refused_in_one_line(data):
    load_or_refuse(data)


@settings(max_examples=300, deadline=None, suppress_health_check=list(HealthCheck))
@given(TABLES)
def test_random_tables_are_refused_in_one_line(data):
    table_is_refused(data)


@settings(max_examples=200, deadline=None, suppress_health_check=list(HealthCheck))
@given(FILES)
def test_random_files_are_refused_in_one_line(tmp_path_factory, content):
    file_is_refused(tmp_path_factory, content)


# ----------------------------------------------------------------- the command, in process
def toml_value(v) -> str:
    """A TOML literal for the generated value (the test's own writer: the project only reads TOML)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return '"' + "".join(ch if ch.isprintable() and ch not in '"\\' else f"\\u{ord(ch):04x}" if ord(ch) < 0x10000
                             else f"\\U{ord(ch):08x}" for ch in v) + '"'
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return "{" + ", ".join(f"{toml_value(str(k))} = {toml_value(x)}" for k, x in v.items()) + "}"


def toml_text(data: dict) -> str:
    return "".join(f"{toml_value(str(k))} = {toml_value(v)}\n" for k, v in data.items())


class NoAnswerCache:
    """The answers of generated scenes are computed, not remembered (the shared cache stays small)."""

    def __enter__(self):
        self.remember = scenes.remember
        scenes.remember = lambda key, compute: compute()

    def __exit__(self, *exc):
        scenes.remember = self.remember


def run_in_process(capsys, path):
    with NoAnswerCache():
        code = cli.main(["scene", str(path)])
    out, err = capsys.readouterr()
    assert "Traceback" not in out + err
    if code == 0:
        assert out.strip() and not err, err
    else:
        assert code == 2 and out == "" and len(err.strip().splitlines()) == 1, (code, out, err)
    return code


def command_without_drift(tmp_path_factory, capsys, data):
    data.pop("drift", None)            # the drift's integration is slow; it is covered below
    f = tmp_path_factory.mktemp("cli") / "s.toml"
    f.write_text(toml_text(data), encoding="utf-8")
    run_in_process(capsys, f)


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(mutated())
def test_the_command_answers_or_refuses_in_one_line(tmp_path_factory, capsys, data):
    command_without_drift(tmp_path_factory, capsys, data)


# ----------------------------------------------------------------- heavier: the slow tier
@pytest.mark.slow
@settings(max_examples=9500, deadline=None, suppress_health_check=list(HealthCheck))
@given(mutated())
def test_many_mutated_scenes(data):
    load_or_refuse(data)


@pytest.mark.slow
@settings(max_examples=400, deadline=None, suppress_health_check=list(HealthCheck))
@given(TABLES)
def test_many_random_tables(data):
    table_is_refused(data)


@pytest.mark.slow
@settings(max_examples=300, deadline=None, suppress_health_check=list(HealthCheck))
@given(FILES)
def test_many_random_files(tmp_path_factory, content):
    file_is_refused(tmp_path_factory, content)


@pytest.mark.slow
@settings(max_examples=270, deadline=None, suppress_health_check=list(HealthCheck))
@given(mutated())
def test_many_scenes_through_the_command_without_drift(tmp_path_factory, capsys, data):
    command_without_drift(tmp_path_factory, capsys, data)


@pytest.mark.slow
@settings(max_examples=3000, deadline=None, suppress_health_check=list(HealthCheck))
@given(mutated())
def test_many_scenes_through_the_command(tmp_path_factory, capsys, data):
    if isinstance(data.get("drift"), dict) and isinstance(data["drift"].get("rate"), float):
        data["drift"]["rate"] *= 1e-3     # slow enough for the first order (the integration is tested apart)
    f = tmp_path_factory.mktemp("cli") / "s.toml"
    f.write_text(toml_text(data), encoding="utf-8")
    run_in_process(capsys, f)


# ----------------------------------------------------------------- hostile files, by the real command
def run(path):
    return subprocess.run([sys.executable, "-m", "pendsym.cli", "scene", str(path)], capture_output=True,
                          text=True, timeout=300)


@pytest.mark.parametrize("content, message", [
    (toml_text({**BASE, "g": math.nan}), "g = nan"),
    (toml_text({**BASE, "amplitude": math.inf}), "amplitude = inf"),
    (toml_text({**BASE, "bob": {"mass": 5.0, "a": -0.66, "R": 0.3}}), "bob.a = -0.66"),
    (toml_text({**BASE, "bob": {"mass": 5.0, "a": 0.0, "R": 0.3}}), "bob.a = 0.0"),
    (toml_text({**BASE, "bob": {"mass": "5", "a": 0.66, "R": 0.3}}), "bob.mass = '5'"),
    (toml_text({**BASE, "g": 1e300}), "g = 1e+300"),
    (toml_text({**BASE, "colour": 1}), "colour: unknown key"),
    (toml_text({k: v for k, v in BASE.items() if k != "bob"}), "bob: missing"),
    (toml_text({**BASE, "suspension": THREAD}), "bob.a = 0.66 is given with a thread"),
    (toml_text({**BASE, "suspension": {**BLADE, "mounting": "inverted"}}), "inverted"),
    (toml_text({**BASE, "wanted": {"quantities": ["rate"], "tolerance": 1e-7}}), "target_period"),
    (toml_text({**BASE, "support": {"compliance": 1e-3, "mass": 0.0}}), "beyond a perturbation"),
    ("bob = " + "[" * 50_000 + "]" * 50_000 + "\n", "nested too deeply"),
    ("g = 9.81\n" + "# padding\n" * 200_000, "larger than"),
])
def test_hostile_scenes_by_the_command(tmp_path, content, message):
    f = tmp_path / "s.toml"
    f.write_text(content, encoding="utf-8")
    p = run(f)
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 2 and p.stdout == "" and len(lines) == 1 and "Traceback" not in p.stderr, p.stderr
    assert message in lines[0], lines[0]
