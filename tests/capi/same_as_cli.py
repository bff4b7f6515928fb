#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
# The C example (examples/c/render.c) against the command line on one scene: the same
# fragments, field by field (SCENE.OUTPUT.FRAGMENTS, SCENE.OUTPUT.COVERAGE, SCENE.OUTPUT.AREA,
# SCENE.OUTPUT.PIPELINE). The example prints coverage in 1/65536 and attributes and depths
# in decimal: they are compared as the exact values (coverage) and as float32 (attributes).
#   same_as_cli.py EXAMPLE CLI SCENE
import json
import struct
import subprocess
import sys
from fractions import Fraction


def f32(v):
    return struct.unpack("<f", struct.pack("<f", float(v)))[0]


def normal_cli(frag):
    out = dict(frag)
    if "coverage" in out:
        out["coverage_q16"] = int(Fraction(str(out.pop("coverage"))) * 65536)
    if "attr" in out:
        out["attr"] = [f32(v) for v in out["attr"].values()]
    if "depth" in out:
        out["depth"] = [f32(v) for v in out["depth"]]
    return out


def normal_c(frag):
    out = dict(frag)
    if "attr" in out:
        out["attr"] = [f32(v) for v in out["attr"]]
    if "depth" in out:
        out["depth"] = [f32(v) for v in out["depth"]]
    return out


def main():
    example, cli, scene = sys.argv[1:4]
    want = json.loads(subprocess.run([cli, "render", scene, "--fragments", "-"], check=True,
                                     capture_output=True, text=True).stdout)["fragments"]
    got = json.loads(subprocess.run([example, scene], check=True, capture_output=True,
                                    text=True).stdout)["fragments"]
    want = [normal_cli(f) for f in want]
    got = [normal_c(f) for f in got]
    if len(want) != len(got):
        print(f"{scene}: the C API gave {len(got)} fragments, the CLI {len(want)}")
        return 1
    for i, (w, g) in enumerate(zip(want, got)):
        if w != g:
            print(f"{scene}: fragment {i} differs:\n  CLI   {w}\n  C API {g}")
            return 1
    print(f"{scene}: {len(got)} fragments, the same as rastrules render")
    return 0


if __name__ == "__main__":
    sys.exit(main())
