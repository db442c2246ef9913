"""Collide from Python: one collision worked out, a scene run, a figure drawn.

The functions call the `collide` command's own code (a C++ module), so they return what the
command prints:

    collide.solve(problem)          `collide solve --format json`, as a dict
    collide.run(scene)              `collide step --json` and `--events --json`, one run:
                                    the states as NumPy arrays, the events as dicts
    collide.render_figure(scene)    `collide render`'s figure.png (before / at / after), PNG bytes

A problem or a scene is a file name (str or path), a lesson id (`collide lessons`; scenes
only), or a dict with the file's tables and keys (docs/formats/collision-files.md and
scenario-files.md). Bad input raises ValueError with the command's message: the file, the line and the
key ("<dict>" and the key for a dict).
"""

import json
import os

import numpy as np

from . import _collide
from ._install import LESSONS_FROM_PACKAGE

__all__ = ["solve", "run", "render_figure"]


def _installed_lessons():
    # The lessons installed with this package (share/collide/lessons); the C++ side falls back to
    # $COLLIDE_LESSONS first and to the source tree's when they are not there (a build tree).
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), LESSONS_FROM_PACKAGE))


# How deep a dict may nest (the formats need 4), as the C++ side checks it (python/module.cpp).
_MAX_DEPTH = 64


def _plain(value, where="", depth=0, open_ids=frozenset()):
    """A dict, list or value with NumPy arrays and scalars turned into lists and numbers.

    A dict or list that contains itself, or nests more than _MAX_DEPTH deep, raises ValueError
    naming where ("<dict>: body[0].v: ..."), never RecursionError or a crash."""
    if isinstance(value, (dict, list, tuple)):
        here = where or "(the dict itself)"
        if id(value) in open_ids:
            raise ValueError(f"<dict>: {here}: contains itself (a dict or list inside its own value)")
        if depth >= _MAX_DEPTH:
            raise ValueError(f"<dict>: {here}: nested more than {_MAX_DEPTH} deep (the formats need 4)")
        inner = open_ids | {id(value)}
        if isinstance(value, dict):
            return {
                k: _plain(v, f"{where}.{k}" if where else str(k), depth + 1, inner) for k, v in value.items()
            }
        return [_plain(v, f"{where}[{i}]", depth + 1, inner) for i, v in enumerate(value)]
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def _source(source):
    if isinstance(source, dict):
        return _plain(source)
    if isinstance(source, (str, os.PathLike)):
        return os.fspath(source)
    raise TypeError(f"expected a file name, a lesson id or a dict, got {type(source).__name__}")


def solve(problem, model=None):
    """One collision worked out: the dict of `collide solve --format json` (docs/commands/solve.md, "Output").

    problem: a collision file's name, or a dict of its keys, e.g.
        {"dimension": 1, "restitution": 0.5, "normal": 1,
         "a": {"mass": 2.0, "v": 3.0}, "b": {"mass": 1.0, "v": 0.0}}
    model: instead of the file's: "frictionless", "coulomb", "matrix", "stick",
        "page-listing" or "routh" (as `collide solve --model`).
    """
    return json.loads(_collide.solve_json(_source(problem), model or ""))


def _columns(states):
    """`collide step --json` states as columns: every number and vector of every state stacked
    along a first axis of time (dicts of columns where the states have dicts)."""
    first = states[0]
    if isinstance(first, dict):
        return {key: _columns([s[key] for s in states]) for key in first}
    return np.array(states, dtype=float)


def _budget(max_work):
    """max_work as the module takes it: None (the default budget) or a float (checked there)."""
    return None if max_work is None else float(max_work)


def run(scene, max_work=None):
    """A scene run once: the record of `collide step --json` with its `--events --json`.

    scene: a scenario file, a lesson file, a lesson id, or a dict of a scenario's tables
        ({"scene": {...}, "body": [{...}, ...]}).
    Returns a dict with the keys of `collide step --json`, each a NumPy array over the output
    instants: "t" (s, shape (K,)), "bodies" (per body name: "x", "v" and, 2D and 3D, "w",
    "angle" or "orientation"; shape (K,) for numbers, (K, 2) or (K, 3) or (K, 4) for vectors),
    "kinetic_energy", "potential_energy", "momentum" and (2D, 3D) "angular_momentum"; and
    "events": the `--events --json` objects (time, bodies, point, normal, impulse, velocities
    before and after, energy_gain), a list of dicts.
    max_work: the run's work budget, in units of about a microsecond (`collide step --max-work`;
        default 1e8, docs/stepping.md "Work budget"); a run beyond it raises ValueError.
    """
    states, events = _collide.run_json(_source(scene), _installed_lessons(), _budget(max_work))
    record = _columns([json.loads(line) for line in states])
    record["events"] = [json.loads(line) for line in events]
    return record


def render_figure(scene, size="720p", view=None, quality="medium", fps=30.0, backend="osmesa", max_work=None):
    """The before / at / after figure of the scene's first collision (a lesson's first
    [[figure]]), as `collide render` writes it to figure.png: the PNG's bytes. In Jupyter:
    IPython.display.Image(collide.render_figure(...)).

    size: "WxH", or "480p", "720p", "1080p", "1440p" (the frames' size; the figure is laid
        out from it, as --size). view: "2d" or "3d" (default: 2d for 1D and 2D scenes).
    quality, fps, backend, max_work: as `collide render`'s options (max_work: --max-work).
    Raises ValueError when the scene has no collision to show.
    """
    png = _collide.figure_png(_source(scene), _installed_lessons(), size, view or "", quality, backend, float(fps),
                              _budget(max_work))
    if png is None:
        raise ValueError(f"{scene if not isinstance(scene, dict) else '<dict>'}: no collision in the run, so no figure")
    return png
