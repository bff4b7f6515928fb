# SPDX-License-Identifier: MIT
"""Render a scene file with the rastrules Python module and explain one pixel.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/render_and_explain.py \
        examples/scenes/triangle_and_line.json 3 1

Prints the fragment count, the covered pixels of each primitive (from the NumPy array
rastrules.render returns) and the explanation of pixel (X, Y): which rules decided it
(the same text as `rastrules explain SCENE X Y`).
"""

import sys

import numpy as np

import rastrules


def main(argv):
    if len(argv) != 4:
        print("usage: render_and_explain.py SCENE X Y", file=sys.stderr)
        return 2
    path, x, y = argv[1], int(argv[2]), int(argv[3])
    try:
        scene = rastrules.read_scene(path)
    except ValueError as e:  # the reader's one-line message
        print(f"render_and_explain.py: {e}", file=sys.stderr)
        return 2
    frags = rastrules.render(scene)
    print(f"{frags.size} fragments (rastrules {rastrules.__version__})")
    for prim in np.unique(frags["prim"]):
        mine = frags[frags["prim"] == prim]
        pixels = " ".join(f"({int(f['x'])},{int(f['y'])})" for f in mine)
        print(f"primitive {int(prim)}: {mine.size} pixels: {pixels}")
    sys.stdout.write(rastrules.explain(scene, x, y))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
