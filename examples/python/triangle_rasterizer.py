# SPDX-License-Identifier: MIT
"""A triangle rasterizer in plain Python with a planted bug, served as an external driver.

It draws single-sample scenes of triangles: vertices snapped to 16.8 fixed point (round half to
even), one edge function per edge evaluated at each pixel centre, the D3D top-left rule for
samples exactly on an edge (spec/rules/: TRI.EDGE.FUNCTION, TRI.FILL.TOP_LEFT). Everything else
it declares it does not draw (CAPABILITIES below: campaigns skip those scenes); the rest of what
it does not handle (culling) it leaves to the reference by returning None.

The planted bug: a sample exactly on an edge is always covered (no tie rule), so pixels on the
shared edge of two triangles are drawn twice and right and bottom edges draw one pixel too many.
Find it, shrunk to one triangle:

    rastrules fuzz --driver "external:python3 triangle_rasterizer.py" --cases 30 --out out/py

With RASTRULES_EXAMPLE_FIXED=1 in the environment it follows the rule and agrees with the
reference on every scene.
"""

import os

import rastrules.driver

FIXED = os.environ.get("RASTRULES_EXAMPLE_FIXED") == "1"


def snap(v):
    """16.8 fixed point, round half to even (Python's round on an exact binary value)."""
    return round(float(v) * 256)


# What it draws (spec/driver.md, DRIVER.EXTERNAL.CAPABILITIES): campaigns send nothing else.
CAPABILITIES = {
    "primitives": ["triangle"],
    "sample_counts": [1],
    "sample_patterns": ["standard"],
    "fill_conventions": ["top-left"],
    "sample_mask": False,
    "sample_shading": False,
    "pipeline": False,
}


def supported(scene):
    return (
        scene.get("samples", 1) == 1
        and scene.get("cull", "none") == "none"
        and scene.get("fill", "top-left") == "top-left"
        and all(p["type"] == "triangle" and "v" in p for p in scene["primitives"])
        and not any(k in scene for k in ("viewport", "transform", "depth", "attributes",
                                          "sample_mask", "sample_pattern", "centroid", "quads"))
    )


def top_left(dx, dy):
    # With the edge function below and the interior on its positive side (y down): a top edge
    # is horizontal going right, a left edge goes up (TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE).
    return (dy == 0 and dx > 0) or dy < 0


def rasterize(scene):
    if not supported(scene):
        return None  # drawn by the reference
    w, h = scene["target"]["width"], scene["target"]["height"]
    out = []
    for prim, p in enumerate(scene["primitives"]):
        a, b, c = [(snap(x), snap(y)) for x, y in p["v"]]

        def edge(p0, p1, q):
            return (p1[0] - p0[0]) * (q[1] - p0[1]) - (p1[1] - p0[1]) * (q[0] - p0[0])

        area = edge(a, b, c)
        if area == 0:
            continue  # degenerate: nothing drawn
        if area < 0:
            b, c = c, b  # the interior on every edge's positive side
        edges = [(a, b), (b, c), (c, a)]
        xs, ys = [a[0], b[0], c[0]], [a[1], b[1], c[1]]
        x0, x1 = max(0, min(xs) // 256 - 1), min(w - 1, max(xs) // 256 + 1)
        y0, y1 = max(0, min(ys) // 256 - 1), min(h - 1, max(ys) // 256 + 1)
        for y in range(y0, y1 + 1):
            for x in range(x0, x1 + 1):
                q = (x * 256 + 128, y * 256 + 128)  # the pixel centre
                inside = True
                for p0, p1 in edges:
                    e = edge(p0, p1, q)
                    tie_ok = top_left(p1[0] - p0[0], p1[1] - p0[1]) if FIXED else True
                    if e < 0 or (e == 0 and not tie_ok):
                        inside = False
                        break
                if inside:
                    out.append((prim, x, y))
    return out


if __name__ == "__main__":
    rastrules.driver.main(rasterize, CAPABILITIES)
