"""The Python module `collide` against the `collide` command: the same results, records,
figures and error messages (python/collide/__init__.py). Run by ctest (tests/python/CMakeLists.txt)
with the build tree's python/ on PYTHONPATH, COLLIDE_BIN the command and COLLIDE_SOURCE_DIR the
source tree."""

import json
import os
import pathlib
import subprocess
import tomllib

import numpy as np
import pytest

import collide

BIN = os.environ["COLLIDE_BIN"]
SOURCE = pathlib.Path(os.environ["COLLIDE_SOURCE_DIR"])
LESSONS = SOURCE / "lessons"
BAD = SOURCE / "tests" / "bad-input"


def cli(*args, cwd=None):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, cwd=cwd)


def cli_json_lines(*args):
    out = cli(*args)
    assert out.returncode == 0, out.stderr
    return [json.loads(line) for line in out.stdout.splitlines()]


def toml_dict(path):
    with open(path, "rb") as f:
        return tomllib.load(f)


# ---- solve ----

@pytest.mark.parametrize("path", sorted((LESSONS / "solve").glob("*.toml")), ids=lambda p: p.stem)
def test_solve_is_the_commands_json(path):
    assert collide.solve(path) == json.loads(cli("solve", path, "--format", "json").stdout)
    assert collide.solve(str(path), model="coulomb") == json.loads(
        cli("solve", path, "--format", "json", "--model", "coulomb").stdout)


@pytest.mark.parametrize("path", sorted((LESSONS / "solve").glob("*.toml")), ids=lambda p: p.stem)
def test_solve_a_dict_as_its_file(path):
    assert collide.solve(toml_dict(path)) == collide.solve(path)


def test_solve_a_dict_of_numpy_values():
    carts = {"dimension": 1, "restitution": np.float64(0.5), "normal": 1,
             "a": {"mass": 2.0, "v": np.float64(3.0)}, "b": {"mass": np.int64(1), "v": 0.0}}
    result = collide.solve(carts)
    # 1D: J = (1 + e) (va - vb) / (1/ma + 1/mb) = 1.5 * 3 / 1.5 = 3 N s on B.
    assert result["impulse"] == pytest.approx(3.0, rel=1e-15)
    assert result["b"]["v"] == pytest.approx(3.0, rel=1e-15)
    rod = toml_dict(LESSONS / "solve" / "rod-on-ground.toml")
    rod["b"]["v"] = np.array(rod["b"]["v"])
    rod["normal"] = np.array(rod["normal"], dtype=np.float32)
    assert collide.solve(rod) == collide.solve(LESSONS / "solve" / "rod-on-ground.toml")


def test_a_dicts_mistake_names_the_key():
    carts = {"dimension": 1, "restitution": 0.5, "normal": 1,
             "a": {"mass": -2.0, "v": 3.0}, "b": {"mass": 1.0, "v": 0.0}}
    with pytest.raises(ValueError, match=r"^<dict>: a\.mass: "):
        collide.solve(carts)
    carts["a"]["mass"] = 2.0
    carts["a"]["velocity"] = 1.0
    with pytest.raises(ValueError, match=r"^<dict>: a\.velocity: .*did you mean 'v'"):
        collide.solve(carts)
    del carts["a"]["velocity"]
    carts["b"]["v"] = {1.0}
    with pytest.raises(ValueError, match=r"^<dict>: b\.v: expected a number, a string, a boolean, a list or a dict, got a set"):
        collide.solve(carts)
    with pytest.raises(ValueError, match="model"):
        collide.solve(LESSONS / "solve" / "carts-1d.toml", model="magic")
    with pytest.raises(TypeError):
        collide.solve(42)


def test_a_dict_nested_too_deep_or_containing_itself_raises_valueerror_never_a_crash():
    # Lists nested 20 000 deep crashed the interpreter (exit 139) or raised RecursionError; a
    # dict that contains itself crashed _collide.solve_json. Both sides check: the package's
    # own conversion (_plain) and the C++ one, called here directly too.
    deep = [1.0]
    for _ in range(20000):
        deep = [deep]
    carts = {"dimension": 1, "restitution": 0.5, "normal": 1,
             "a": {"mass": 2.0, "v": deep}, "b": {"mass": 1.0, "v": 0.0}}
    with pytest.raises(ValueError, match=r"^<dict>: a\.v(\[0\])+: nested more than 64 deep"):
        collide.solve(carts)
    with pytest.raises(ValueError, match=r"^<dict>: a\.v(\[0\])+: nested more than 64 deep"):
        collide._collide.solve_json(carts, "")
    me = {"dimension": 1, "restitution": 0.5}
    me["a"] = me
    with pytest.raises(ValueError, match=r"^<dict>: a: contains itself"):
        collide.solve(me)
    with pytest.raises(ValueError, match=r"^<dict>: a: contains itself"):
        collide._collide.solve_json(me, "")
    loop = [0.0]
    loop.append(loop)
    scene = {"scene": {"dimension": 1, "duration": 1.0}, "body": [{"name": "x", "mass": 1.0, "v": loop}]}
    with pytest.raises(ValueError, match=r"^<dict>: body\[0\]\.v\[1\]: contains itself"):
        collide.run(scene)
    with pytest.raises(ValueError, match=r"contains itself"):
        collide._collide.run_json(scene, "")
    # The same list in two places is not a cycle.
    shared = [0.0, -1.0]
    two = {"scene": {"dimension": 2, "duration": 0.1},
           "body": [{"name": "a", "shape": "disc", "radius": 0.1, "mass": 1.0, "v": shared},
                    {"name": "b", "shape": "disc", "radius": 0.1, "mass": 1.0, "position": [1.0, 0.0], "v": shared}]}
    assert len(collide.run(two)["t"]) > 1


def test_a_run_beyond_its_work_budget_raises_valueerror():
    with pytest.raises(ValueError, match=r"units of work by t = .* more than its budget of 1000 "):
        collide.run("bouncing-ball", max_work=1000)
    assert len(collide.run("bouncing-ball", max_work=1e6)["t"]) > 1
    for wrong in (-1, 0, float("nan"), float("inf")):
        with pytest.raises(ValueError, match="max_work: expected a number > 0"):
            collide.run("bouncing-ball", max_work=wrong)


# ---- The bad-input catalogue: the command's message, word for word ----

def bad_cases(kind, command):
    """(file, command) pairs of the catalogue that the command refuses (exit code 2)."""
    cases = []
    for f in sorted((BAD / kind).glob("*.toml")):
        lines = f.read_text(errors="replace").splitlines()
        if kind == "lesson" and len(lines) > 1 and lines[1].startswith("# only:"):
            continue  # refused by render or worksheet only; `collide step` runs it
        cases.append(pytest.param(f, command, id=f"{kind}/{f.stem}"))
    return cases


@pytest.mark.parametrize("path,command", bad_cases("solve", "solve") + bad_cases("scene", "step")
                         + bad_cases("lesson", "step"))
def test_bad_input_raises_the_commands_message(path, command):
    # Relative to the catalogue, as a user in that folder names a file.
    out = cli(command, path.name, cwd=path.parent)
    assert out.returncode == 2, out.stderr
    call = collide.solve if command == "solve" else collide.run
    cwd = os.getcwd()
    os.chdir(path.parent)
    try:
        with pytest.raises(ValueError) as raised:
            call(path.name)
    finally:
        os.chdir(cwd)
    assert out.stderr == f"collide: error: {raised.value}\n"


# ---- run ----

def assert_record_is_the_commands(record, target):
    states = cli_json_lines("step", target, "--json")
    events = cli_json_lines("step", target, "--events", "--json")
    assert record["events"] == events
    assert np.array_equal(record["t"], [s["t"] for s in states])
    assert record["t"].shape == (len(states),)
    for key in ("kinetic_energy", "potential_energy", "momentum", "angular_momentum"):
        if key in states[0]:
            assert np.array_equal(record[key], np.array([s[key] for s in states])), key
    assert set(record["bodies"]) == set(states[0]["bodies"])
    for name, body in record["bodies"].items():
        for key, column in body.items():
            expected = np.array([s["bodies"][name][key] for s in states])
            assert column.shape == expected.shape and np.array_equal(column, expected), (name, key)


@pytest.mark.parametrize("path", sorted((LESSONS / "scenes").glob("*.toml")), ids=lambda p: p.stem)
def test_run_is_the_commands_record(path):
    assert_record_is_the_commands(collide.run(path), path)


def test_run_a_lesson_by_its_id():
    record = collide.run("catch-up")
    assert_record_is_the_commands(record, "catch-up")
    assert [e["a"] + " " + e["b"] for e in record["events"]] == ["A B"]
    assert record["bodies"]["A"]["x"].shape == record["t"].shape  # 1D: numbers


def test_run_a_dict_as_its_file():
    path = LESSONS / "scenes" / "tilted-box-2d.toml"
    record, expected = collide.run(toml_dict(path)), collide.run(path)
    assert record["events"] == expected["events"]
    assert np.array_equal(record["bodies"]["box"]["x"], expected["bodies"]["box"]["x"])
    assert record["bodies"]["box"]["x"].shape == (len(record["t"]), 2)


def test_run_mistakes():
    with pytest.raises(ValueError, match=r"^<dict>: missing table \[scene\]"):
        collide.run({"body": []})
    with pytest.raises(ValueError, match="did you mean 'catch-up'"):
        collide.run("catch-upp")


# ---- render_figure ----

@pytest.mark.parametrize("target,size", [("catch-up", "480p"), (str(LESSONS / "scenes" / "dropped-box-3d.toml"), "320x240")])
def test_render_figure_is_the_commands_figure_png(tmp_path, target, size):
    out = cli("render", target, "-o", tmp_path / "render", "--size", size, "--quiet")
    assert out.returncode == 0, out.stderr
    png = collide.render_figure(target, size=size)
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert png == (tmp_path / "render" / "figure.png").read_bytes()


def test_render_figure_mistakes():
    with pytest.raises(ValueError, match=r"^size: "):
        collide.render_figure("catch-up", size="huge")
    with pytest.raises(ValueError, match=r"^view: "):
        collide.render_figure("catch-up", view="4d")
    alone = {"scene": {"dimension": 2, "duration": 0.5},
             "body": [{"name": "ball", "shape": "disc", "radius": 0.1, "mass": 1.0}]}
    with pytest.raises(ValueError, match="no collision"):
        collide.render_figure(alone)
