#!/usr/bin/env python3
"""Regenerates the seed corpora fuzz/corpus/<target>/ (Python 3 standard library only).

fuzz_scene_parser:     tests/bad_input/*.json, the showcase scenes (`rastrules showcase --out
                       DIR` writes *.scene.json), and the hand-made scenes below.
                       Files named crash_* (reproducers of bugs found by fuzzing) are kept.
fuzz_kernel_vs_oracle: the same valid scenes encoded in the byte layout of fuzz/support.cpp
                       (decode_scene; fuzz/README.md), clipped to its limits (target <= 64 px,
                       <= 8 primitives, strips <= 5 vertices), plus a few hand-made byte strings.

usage: fuzz/gen_corpus.py --rastrules build/tools/rastrules
"""

import argparse
import json
import pathlib
import shutil
import struct
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
FUZZ = ROOT / "fuzz"

CULL = {"none": 0, "back": 1, "front": 2}
FILL = {"top-left": 0, "top-right": 1, "bottom-left": 2, "bottom-right": 3}
LINE_MODE = {"d3d": 0, "vulkan-bresenham": 1, "quad-wide": 2, "quad-narrow": 3}
TYPE = {"triangle": 0, "point": 1, "line": 2, "line_strip": 3}


def scene(w, h, prims, **state):
    s = {"version": 1, "target": {"width": w, "height": h}}
    s.update(state)
    s["primitives"] = prims
    return s


# Hand-made scenes: every primitive type, state and line mode, ties, range edges.
HAND = {
    "points": scene(8, 8, [{"type": "point", "v": [[1.5, 1.5]]}, {"type": "point", "v": [[4.0, 4.0]]},
                           {"type": "point", "v": [[6.0, 2.5]]}], fill="bottom-right"),
    "lines_d3d": scene(16, 8, [{"type": "line", "v": [[0.5, 0.5], [15.5, 7.5]]},
                               {"type": "line", "v": [[2.0, 6.0], [2.0, 1.0]]},
                               {"type": "line", "v": [[3.5, 3.5], [3.5, 3.5]]}]),
    "lines_vulkan": scene(16, 8, [{"type": "line", "v": [[0.0, 0.0], [15.0, 4.0]]},
                                  {"type": "line_strip", "v": [[1, 7], [8, 1], [14, 7]]}],
                          line_mode="vulkan-bresenham"),
    "lines_quad_wide": scene(12, 12, [{"type": "line", "v": [[1.25, 1.75], [10.5, 9.0]]},
                                      {"type": "line_strip", "v": [[1, 10], [6, 2], [11, 10], [1, 10]]}],
                             line_mode="quad-wide", fill="top-right"),
    "lines_quad_narrow": scene(12, 12, [{"type": "line", "v": [[6.0, 0.5], [6.0, 11.5]]},
                                        {"type": "line", "v": [[0.5, 6.0], [11.5, 6.0]]}],
                               line_mode="quad-narrow", cull="back"),
    "lines_aa": scene(16, 16, [{"type": "line", "v": [[0.5, 1.0], [15.0, 12.25]], "aa": True},
                               {"type": "line_strip", "v": [[2, 14], [8, 3], [14, 14]], "aa": True},
                               {"type": "line", "v": [[7.5, 7.5], [7.5, 7.5]], "aa": True}]),
    "mixed_ccw_front": scene(20, 10, [{"type": "triangle", "v": [[1, 1], [1, 9], [9, 1]]},
                                      {"type": "point", "v": [[12.5, 5.5]]},
                                      {"type": "line", "v": [[10, 1], [19, 9]]}],
                             cull="front", front_face="ccw", fill="bottom-left"),
    "range_edges": scene(4, 4, [{"type": "triangle", "v": [[-32768, -32768], [32767.99609375, -32768], [0, 32767.99609375]]},
                                {"type": "point", "v": [[-32767.5, 32767.49609375]]},
                                {"type": "line", "v": [[-32768, 0], [32767.99609375, 3]]}]),
    "ties": scene(8, 8, [{"type": "triangle", "v": [[0.001953125, 0.005859375], [7.998046875, 0.5], [4, 7.501953125]]},
                         {"type": "line", "v": [[0.501953125, 0.5], [7.498046875, 6.5]]}]),
    "nan_strings": scene(4, 4, [{"type": "triangle", "v": [["NaN", 1], [2, "Infinity"], ["-Infinity", 0]]}]),
    "exponents": scene(4, 4, [{"type": "triangle", "v": [[1e0, 2.5E+0], [3.999e-0, 1e-45], [-0.0, 4e0]]}]),
    # multisampling (SCENE.MSAA): every key, every pattern kind, both centroid rules
    "msaa_4x": scene(6, 4, [{"type": "triangle", "v": [[0.5, 0.5], [5.5, 1.5], [1.5, 3.5]], "color": [255, 0, 0, 255]},
                            {"type": "point", "v": [[4.5, 3.0]]},
                            {"type": "line", "v": [[0.0, 3.5], [6.0, 2.0]], "aa": True}],
                     samples=4, sample_mask=13, centroid="d3d11", quads=True, derivatives="fine",
                     clear_color=[0, 0, 0, 255]),
    "msaa_16x_sample_shading": scene(4, 4, [{"type": "triangle", "v": [[0, 0], [4, 0.5], [0.5, 4]]}],
                                     samples=16, shading="sample", derivatives="coarse"),
    "msaa_center_bresenham": scene(4, 4, [{"type": "line", "v": [[0.5, 0.5], [3.5, 2.5]]}],
                                   samples=8, sample_pattern="center", line_mode="vulkan-bresenham",
                                   centroid="d3d10"),
    "msaa_custom": scene(4, 4, [{"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]]},
                                {"type": "line_strip", "v": [[0, 3], [3, 0], [4, 4]]}],
                         sample_pattern=[[-8, -8], [7, 7], [0, 0], [0, 0], [-8, 7]], line_mode="quad-narrow",
                         sample_mask=0, quads=True),
}


def f32(x):
    if isinstance(x, str):
        x = {"NaN": float("nan"), "Infinity": float("inf"), "-Infinity": float("-inf")}[x]
    try:
        return struct.pack("<Bf", 4, float(x))  # selector 4: float32 bits
    except OverflowError:
        return struct.pack("<BI", 4, 0x7F800000 if x > 0 else 0xFF800000)


def encode(s):
    """Encodes a scene in decode_scene's byte layout, clipped to its limits."""
    w = min(max(s["target"]["width"], 1), 64)
    h = min(max(s["target"]["height"], 1), 64)
    mode = LINE_MODE[s.get("line_mode", "d3d")]
    st = CULL[s.get("cull", "none")] | (4 if s.get("front_face", "cw") == "ccw" else 0) \
        | (FILL[s.get("fill", "top-left")] << 3) | (mode << 5)
    prims = s["primitives"][:8]
    out = bytearray([w - 1, h - 1, st, len(prims)])
    for p in prims:
        t = TYPE[p["type"]]
        v = p["v"]
        if t == 3:
            v = v[:5]
        out.append(t | (8 if p.get("aa") else 0) | ((max(len(v) - 2, 0) & 3) << 4))
        for x, y in v:
            out += f32(x) + f32(y)
    return bytes(out)


# Hand-made byte strings for the differential target (see fuzz/README.md for the layout).
RAW_SEEDS = {
    # 64x64, d3d, 8 primitives of each type, coordinates as raw 16.8 int16 (selector 0).
    "raw_all_types": bytes([63, 63, 0, 4,
                            0, 0, 0x80, 0x02, 0, 0x00, 0x01, 0, 0x00, 0x30, 0, 0x40, 0x05, 0, 0x00, 0x3e, 0, 0x80, 0x3f,
                            1, 0, 0x80, 0x10, 0, 0x80, 0x10,
                            2, 0, 0x00, 0x01, 0, 0x00, 0x01, 0, 0x00, 0x3f, 0, 0x55, 0x20,
                            0x1b, 0, 0x00, 0x02, 0, 0x00, 0x3c, 0, 0x00, 0x20, 0, 0x00, 0x02, 0, 0x00, 0x3c, 0, 0x00, 0x3c]),
    # ties (selector 2) and ulps (selector 3) in vulkan-bresenham mode with fill bottom-right
    "ties_ulps_vulkan": bytes([15, 15, (1 << 5) | (3 << 3), 2,
                               2, 2, 0x00, 0x01, 2, 0x00, 0x02, 3, 0x00, 0x0e, 0x05, 3, 0x80, 0x0c, 0xfb,
                               0, 2, 0x80, 0x00, 2, 0x80, 0x00, 3, 0x00, 0x08, 0x01, 3, 0x00, 0x02, 0xff,
                               2, 0x00, 0x0c, 2, 0x00, 0x0e]),
    # arbitrary float bits: NaN, infinity, -0, a subnormal, 2^24
    "float_bits": bytes([7, 7, 0, 3,
                         1, 4, 0x00, 0x00, 0xc0, 0x7f, 4, 0x00, 0x00, 0x80, 0x00,
                         1, 4, 0x00, 0x00, 0x80, 0x7f, 4, 0x01, 0x00, 0x00, 0x00,
                         2, 4, 0x00, 0x00, 0x80, 0x4b, 4, 0, 0, 0, 0, 4, 0x00, 0x00, 0x80, 0x3f, 4, 0x00, 0x00, 0x80, 0x3f]),
    # full-range raw values (selector 1) for an AA line and a point near the point-range edge
    "full_range": bytes([31, 31, 0, 2,
                         0x0a, 1, 0x00, 0x00, 0x00, 1, 0x00, 0x00, 0x00, 1, 0xff, 0xff, 0xff, 1, 0x10, 0x00, 0x80,
                         1, 1, 0x80, 0x00, 0x00, 1, 0x7f, 0xff, 0xff]),
    # aa in quad mode kept (bit 7): prepare must reject it
    "aa_bad_mode": bytes([7, 7, 0x80 | (2 << 5), 1, 0x0a, 0, 0, 1, 0, 0, 1, 0, 0, 6, 0, 0, 6]),
    "empty": b"",
}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rastrules", required=True, help="the rastrules command line (for `showcase`)")
    args = ap.parse_args()

    parser_dir = FUZZ / "corpus" / "fuzz_scene_parser"
    diff_dir = FUZZ / "corpus" / "fuzz_kernel_vs_oracle"
    # Regenerated files are replaced; reproducers of bugs found by fuzzing (crash_*) are kept.
    for d in (parser_dir, diff_dir):
        d.mkdir(parents=True, exist_ok=True)
        for f in d.iterdir():
            if not f.name.startswith("crash_"):
                f.unlink()

    for f in sorted((ROOT / "tests" / "bad_input").glob("*.json")):
        shutil.copy(f, parser_dir / ("bad_" + f.name))

    valid = {}
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([args.rastrules, "showcase", "--out", tmp], check=True, stdout=subprocess.DEVNULL)
        for f in sorted(pathlib.Path(tmp).glob("*.scene.json")):
            name = "showcase_" + f.name[: -len(".scene.json")]
            shutil.copy(f, parser_dir / (name + ".json"))
            valid[name] = json.loads(f.read_text())
    for name, s in HAND.items():
        (parser_dir / ("hand_" + name + ".json")).write_text(json.dumps(s) + "\n")
        valid["hand_" + name] = s

    for name, s in valid.items():
        (diff_dir / (name + ".bin")).write_bytes(encode(s))
    for name, b in RAW_SEEDS.items():
        (diff_dir / ("raw_" + name + ".bin")).write_bytes(b)

    for d in (parser_dir, diff_dir):
        files = list(d.iterdir())
        print(f"{d.relative_to(ROOT)}: {len(files)} files, {sum(f.stat().st_size for f in files)} bytes")


if __name__ == "__main__":
    main()
