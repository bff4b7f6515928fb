# SPDX-License-Identifier: MIT
"""rastrules: the reference GPU rasterization rules from Python.

A thin layer over the C++ library (the module ``rastrules._core``): the same strict scene reader
as the command line, the same data flow (``run_pipeline``: transform, clip, cover, depth,
attributes) and the same explanations. Nothing here decides coverage.

    >>> import rastrules
    >>> scene = rastrules.read_scene({"target": {"width": 8, "height": 8},
    ...     "primitives": [{"type": "triangle", "v": [[1, 1], [7, 2], [2, 7]]}]})
    >>> frags = rastrules.render(scene)          # a NumPy structured array
    >>> int(frags.size), sorted(frags.dtype.names)[:3]
    (15, ['coverage', 'helper', 'mask'])
    >>> print(rastrules.explain(scene, 3, 3).splitlines()[-1])
    pixel (3, 3): covered by primitive 0

Scenes (spec/scene.md) are read by ``read_scene`` from JSON text, a file path or a dict; every
function that takes a scene also takes any of those. Bad input raises ``ValueError`` with the
reader's one-line message (``primitives[0].v[1][0]: ...``). ``rastrules.driver`` serves a
rasterizer written in Python over the external-driver protocol (``rastrules fuzz --driver
external:...``).
"""

import json
import math
import os
from collections.abc import Mapping

import numpy as np

from . import _core
from ._core import Scene
from .binary import read_fragments_binary

__version__ = _core.__version__

__all__ = [
    "Scene",
    "read_scene",
    "scene_from_dict",
    "render",
    "render_json",
    "fragments",
    "explain",
    "explain_dict",
    "profiles",
    "fragment_dtype",
    "read_fragments_binary",
    "__version__",
]


def _plain(value):
    """Returns value with NumPy scalars and arrays as Python numbers and lists, and non-finite
    floats as the scene format's strings "NaN", "Infinity", "-Infinity" (SCENE.NUMBER.FLOAT32),
    so that the reader, not json.dumps, judges them."""
    if isinstance(value, Mapping):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return "NaN" if math.isnan(value) else ("Infinity" if value > 0 else "-Infinity")
    return value


def scene_from_dict(d):
    """Returns the scene a dict describes (the keys of spec/scene.md), read by the same strict
    reader as a file: the dict is written as JSON text and read. NumPy numbers and arrays are
    accepted. Raises ValueError naming the field on bad input."""
    return Scene.from_json(json.dumps(_plain(d)))


def read_scene(source):
    """Returns a Scene from any of: a Scene (returned as it is), a dict, JSON text (a str that
    starts with "{" after white space, or bytes), or a path (str or os.PathLike; "-" is standard
    input). Raises ValueError with the reader's one-line message on bad input."""
    if isinstance(source, Scene):
        return source
    if isinstance(source, Mapping):
        return scene_from_dict(source)
    if isinstance(source, (bytes, bytearray)):
        return Scene.from_json(bytes(source))
    if isinstance(source, str) and source.lstrip().startswith("{"):
        return Scene.from_json(source)
    if isinstance(source, (str, os.PathLike)):
        return Scene.from_file(os.fspath(source))
    raise TypeError(f"read_scene: a Scene, dict, JSON text or path, not {type(source).__name__}")


def profiles():
    """The profile names (spec/rules/profile.md): ['d3d11', 'vulkan', 'opengl']. Apply one with
    scene.apply_profile(name)."""
    return list(_core.profiles())


def _dtype(cols):
    fields = [
        ("prim", "<u4"),
        ("x", "<i4"),
        ("y", "<i4"),
        ("mask", "<u4"),
        ("seg", "<i4"),
        ("sample", "<i4"),
        ("helper", "?"),
        ("coverage", "<f8"),
    ]
    if "part" in cols:
        fields += [("part", "<i4"), ("passed", "<u4")]
    if "attr" in cols:
        fields.append(("attr", "<f4", (len(cols["attribute_names"]),)))
    if "depth" in cols:
        samples = cols["samples"]
        fields.append(("depth", "<f8") if samples == 1 else ("depth", "<f8", (samples,)))
    if "area" in cols:
        fields += [("area", "<f8"), ("alpha", "u1")]
    return np.dtype(fields)


_MAX_FRAGMENTS = 1 << 26  # `rastrules render --max-fragments`'s default (SCENE.INPUT.LIMITS)
_MAX_WORK = 1 << 36  # `--max-work`'s default


def render(scene, *, threads=1, max_fragments=_MAX_FRAGMENTS, max_work=_MAX_WORK):
    """Draws the scene as `rastrules render` does (only the stages the scene asks for) and
    returns its fragments in output order (prim, part, y, x, seg, sample) as a NumPy
    structured array with the fields

      prim (uint32), x, y (int32), mask (uint32: covered samples after the sample mask),
      seg (int32, line strips; -1 otherwise), sample (int32, sample shading; -1 otherwise),
      helper (bool, helper lanes), coverage (float64, antialiased lines; NaN otherwise),

    and, when the scene has them:

      part (int32, clipped part; -1 when none) and passed (uint32, samples that passed the depth
      test) for pipeline scenes; attr (float32, one per declared attribute, in declaration
      order; NaN for a killed fragment); depth (float64: the stored value, the UNORM integer for
      d16/d24 and the float for d32f; shape (samples,) indexed by sample when multisampled, NaN
      for samples not in the mask); area (float64, the exact area rounded) and alpha (uint8) for
      paths with "coverage": "area".

    A scene without pipeline state is streamed primitive by primitive as `rastrules render`
    streams it (one thread); threads: the pipeline's threads for a scene with pipeline state
    (the result is the same for every count). Raises ValueError on bad input or beyond a limit
    of SCENE.INPUT.LIMITS: max_fragments and max_work, the command line's --max-fragments and
    --max-work, with their defaults."""
    cols = _core.render_columns(read_scene(scene), threads, max_fragments, max_work)
    dtype = _dtype(cols)
    out = np.empty(len(cols["prim"]), dtype=dtype)
    for name in dtype.names:
        value = cols[name]
        if name == "depth" and cols["samples"] == 1:
            value = value[:, 0]
        out[name] = value
    return out


def fragment_dtype(scene):
    """The dtype render() returns for this scene (a cheap way to see the fields: it renders)."""
    return render(scene).dtype


def render_json(scene, *, threads=1, max_fragments=_MAX_FRAGMENTS, max_work=_MAX_WORK):
    """The fragment list as text, byte for byte what `rastrules render SCENE --fragments -`
    writes (SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.PIPELINE). Arguments as render()'s."""
    return _core.render_json(read_scene(scene), threads, max_fragments, max_work)


def fragments(scene, **kwargs):
    """The fragments as a list of dicts, the objects of render_json()'s list ("prim", "x", "y",
    "mask", and "seg", "coverage", "sample", "attr", "depth", ... when present). Arguments as
    render()'s."""
    return json.loads(render_json(scene, **kwargs))["fragments"]


def explain(scene, x, y):
    """Why each primitive covers pixel (x, y) or not, with the rule IDs that decided: the text
    `rastrules explain SCENE --pixel X,Y` prints. Raises ValueError for a pixel outside the
    target."""
    return _core.explain(read_scene(scene), int(x), int(y), False)


def explain_dict(scene, x, y):
    """The same explanation as a dict: `rastrules explain SCENE --pixel X,Y --json`."""
    return json.loads(_core.explain(read_scene(scene), int(x), int(y), True))
