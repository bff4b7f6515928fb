# SPDX-License-Identifier: MIT
"""Serve a rasterizer written in Python over rastrules' external-driver protocol
(spec/driver.md, DRIVER.EXTERNAL.PROTOCOL), so that `rastrules fuzz` and `rastrules check` can
compare it with the reference:

    # my_rasterizer.py
    import rastrules.driver

    def rasterize(scene):            # scene: the scene file as a dict (spec/scene.md)
        ...
        return [(prim, x, y), ...]   # or dicts {"prim", "x", "y", "mask", ...}, or a NumPy
                                     # structured array with fields prim, x, y (mask, ...)

    if __name__ == "__main__":
        rastrules.driver.main(rasterize)

    $ rastrules fuzz --driver "external:python3 my_rasterizer.py" --cases 200

Per draw the protocol runs the program once: the scene arrives on standard input, the fragment
list goes to standard output, exit status 0. main(rasterize, capabilities={...}) declares what
the rasterizer draws (DRIVER.EXTERNAL.CAPABILITIES: primitive types, line modes, sample counts,
fill conventions, pipeline state...): campaigns then send only such scenes and count the rest as
skipped. Returning None from rasterize draws that scene with the reference instead (for scenes
within the declaration it still cannot draw: their fragments always agree). An exception is printed on standard error
and the program exits with status 1: rastrules reports a driver failure quoting it.
"""

import json
import os
import sys
import traceback

import numpy as np

from . import read_scene, render_json

# The keys a fragment may carry in the protocol's output (DRIVER.EXTERNAL.PROTOCOL, item 3).
PROTOCOL_KEYS = ("prim", "x", "y", "mask", "seg", "sample", "helper", "coverage", "centroid",
                 "ddx", "ddy")


def _fragment(f):
    """One fragment as a protocol object: a tuple (prim, x, y[, mask]), a dict (keys outside the
    protocol, such as render()'s "depth" or "attr", are dropped) or a structured array row
    (seg and sample of -1 and coverage NaN mean absent, as render() writes them)."""
    if isinstance(f, dict):
        return {k: f[k] for k in PROTOCOL_KEYS if k in f}
    if isinstance(f, np.void):
        names = f.dtype.names
        out = {"prim": int(f["prim"]), "x": int(f["x"]), "y": int(f["y"])}
        if "mask" in names:
            out["mask"] = int(f["mask"])
        for k in ("seg", "sample"):
            if k in names and int(f[k]) >= 0:
                out[k] = int(f[k])
        if "helper" in names and bool(f["helper"]):
            out["helper"] = True
        if "coverage" in names and not np.isnan(f["coverage"]):
            out["coverage"] = float(f["coverage"])
        return out
    f = tuple(int(v) for v in f)
    if len(f) not in (3, 4):
        raise ValueError(f"a fragment tuple is (prim, x, y) or (prim, x, y, mask), got {f}")
    return dict(zip(("prim", "x", "y", "mask"), f))


def fragments_text(fragments):
    """The protocol's output text for an iterable of fragments (see _fragment)."""
    items = [json.dumps(_fragment(f), separators=(",", ":")) for f in fragments]
    return '{"fragments": [' + ",\n".join(items) + "]}\n"


def serve(rasterize, stdin=None, stdout=None):
    """Runs one draw: reads the scene from stdin (default sys.stdin), checks it with rastrules'
    reader, calls rasterize(scene_dict) and writes its fragments to stdout (default
    sys.stdout); None from rasterize writes the reference's fragments. Returns the exit
    status: 0, or 1 after printing the error on standard error."""
    stdin = sys.stdin if stdin is None else stdin
    stdout = sys.stdout if stdout is None else stdout
    try:
        text = stdin.read()
        if not text.strip():
            raise ValueError("no scene on standard input")
        scene = read_scene(text)  # the reader's ValueError for a scene it refuses
        result = rasterize(json.loads(text))
        stdout.write(render_json(scene) if result is None else fragments_text(result))
        stdout.flush()
        return 0
    except Exception:  # reported on standard error, which rastrules quotes
        traceback.print_exc(file=sys.stderr)
        return 1


def capabilities_reply(capabilities):
    """The reply to the capabilities query (spec/driver.md, DRIVER.EXTERNAL.CAPABILITIES) for a
    dict such as {"primitives": ["triangle"], "sample_counts": [1]}: absent keys restrict
    nothing; rastrules checks the names when it opens the driver."""
    return json.dumps({"capabilities": dict(capabilities)}) + "\n"


def main(rasterize, capabilities=None):
    """serve() on the process's standard input and output, then exit with its status. With
    capabilities (a dict of DRIVER.EXTERNAL.CAPABILITIES), a run with RASTRULES_QUERY set to
    "capabilities" answers the query instead: campaigns then generate only scenes the driver
    declares and count the rest as skipped. Without it the query is not answered (exit 1) and
    the driver is given every scene."""
    if os.environ.get("RASTRULES_QUERY") == "capabilities":
        if capabilities is None:
            sys.exit(1)
        sys.stdout.write(capabilities_reply(capabilities))
        sys.exit(0)
    sys.exit(serve(rasterize))
