# SPDX-License-Identifier: MIT
"""The Python module against the command line (RASTRULES_CLI, set by CTest): the same bytes,
values and errors for the same scenes, the NumPy dtype, and the external-driver helper with the
example rasterizer of examples/python/ (its planted tie bug found by `rastrules check`)."""

import doctest
import io
import json
import math
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import rastrules
import rastrules.driver

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = os.environ.get("RASTRULES_CLI", str(ROOT / "build" / "tools" / "rastrules"))
EXAMPLE = ROOT / "examples" / "python" / "triangle_rasterizer.py"

TRIANGLE = {"target": {"width": 8, "height": 8},
            "primitives": [{"type": "triangle", "v": [[1, 1], [7, 2], [2, 7]]}]}

# Scenes of every kind of fragment field: a strip's seg and an antialiased line's coverage;
# multisampling with a sample mask and a centroid; sample shading; a path with exact areas.
SCENES = {
    "strip_and_aa": {"target": {"width": 12, "height": 8}, "primitives": [
        {"type": "line_strip", "v": [[1, 1], [10, 3], [2, 7]]},
        {"type": "line", "v": [[0.5, 6], [11, 0.25]], "aa": True},
        {"type": "point", "v": [[6.5, 4.5]]}]},
    "msaa": {"target": {"width": 8, "height": 6}, "samples": 4, "sample_mask": 13,
             "centroid": "d3d11", "primitives": [
                 {"type": "triangle", "v": [[0.25, 0.5], [7.5, 1], [1, 5.75]]},
                 {"type": "line", "v": [[0, 5], [8, 0]]}]},
    "sample_shading": {"target": {"width": 6, "height": 4}, "samples": 2, "shading": "sample",
                       "primitives": [{"type": "triangle", "v": [[0, 0], [6, 0.5], [0.5, 4]]}]},
    "path_area": {"target": {"width": 8, "height": 8}, "primitives": [
        {"type": "path", "d": "M 1 1 L 7 2 L 6.5 6 L 2 7 Z", "coverage": "area"}]},
    "pipeline": {"target": {"width": 8, "height": 8}, "samples": 4,
                 "depth": {"format": "d24", "func": "less"},
                 "attributes": [{"name": "u"}, {"name": "v", "interpolation": "flat"}],
                 "primitives": [
                     {"type": "triangle", "v": [[0, 0], [8, 0], [0, 8]], "z": [0.5, 0.25, 0.75],
                      "attr": [[0, 1], [1, 2], [2, 3]]},
                     {"type": "triangle", "v": [[8, 8], [0, 8], [8, 0]], "z": [0.1, 0.9, 0.3],
                      "attr": [[3, 4], [4, 5], [5, 6]]}]},
}
CASES = sorted((ROOT / "spec" / "cases").glob("*[!t].json"))  # not NAME.expect.json


def cli(*args, stdin=None):
    return subprocess.run([CLI, *args], input=stdin, capture_output=True, text=True, check=False)


def scene_file(tmp_path, d, name="scene.json"):
    path = tmp_path / name
    path.write_text(json.dumps(d))
    return path


def all_scene_paths(tmp_path):
    return [scene_file(tmp_path, d, f"{k}.json") for k, d in SCENES.items()] + CASES


def test_render_json_is_the_command_lines_output(tmp_path):
    paths = all_scene_paths(tmp_path)
    assert len(paths) >= len(SCENES) + 10
    for path in paths:
        expected = cli("render", str(path), "--fragments", "-")
        assert expected.returncode == 0, expected.stderr
        assert rastrules.render_json(path) == expected.stdout, path.name
        # A dict and JSON text read by the same reader give the same scene.
        text = path.read_text()
        assert rastrules.read_scene(text) == rastrules.read_scene(json.loads(text))


def nan_or(v):
    return math.nan if v is None else v


def test_arrays_hold_the_command_lines_values(tmp_path):
    for path in all_scene_paths(tmp_path):
        listed = json.loads(cli("render", str(path), "--fragments", "-").stdout)["fragments"]
        got = rastrules.render(path, threads=2)
        assert got.size == len(listed), path.name
        assert rastrules.fragments(path) == listed
        for row, f in zip(got, listed):
            assert (row["prim"], row["x"], row["y"], row["mask"]) == (
                f["prim"], f["x"], f["y"], f.get("mask", 1)), path.name
            assert row["seg"] == f.get("seg", -1) and row["sample"] == f.get("sample", -1)
            assert bool(row["helper"]) == f.get("helper", False)
            assert np.isnan(row["coverage"]) == ("coverage" not in f)
            if "coverage" in f:
                assert row["coverage"] == float(f["coverage"])
            names = got.dtype.names
            if "part" in names:
                assert row["part"] == f.get("part", -1)
                assert row["passed"] == f.get("passed", row["mask"])
            if "attr" in names and "attr" in f:
                # float32 values, written in their shortest round-trip form
                assert row["attr"].tolist() == [float(np.float32(a)) for a in f["attr"].values()]
            if "depth" in names and "depth" in f:
                depths = np.atleast_1d(row["depth"])
                present = [float(d) for d in depths if not np.isnan(d)]
                # d16/d24: UNORM integers; d32f: float32 in shortest round-trip form
                assert present == [float(np.float32(d)) if isinstance(d, float) else float(d)
                                   for d in f["depth"]], path.name
            if "area" in names:
                assert row["alpha"] == f["alpha"]
                num, _, den = f["area"].partition("/")
                assert row["area"] == pytest.approx(int(num) / int(den or 1), rel=1e-12)


def test_dtype_of_each_kind_of_scene():
    plain = [("prim", "<u4"), ("x", "<i4"), ("y", "<i4"), ("mask", "<u4"), ("seg", "<i4"),
             ("sample", "<i4"), ("helper", "?"), ("coverage", "<f8")]
    assert rastrules.render(TRIANGLE).dtype == np.dtype(plain)
    assert rastrules.render(SCENES["path_area"]).dtype == np.dtype(
        plain + [("area", "<f8"), ("alpha", "u1")])
    assert rastrules.render(SCENES["pipeline"]).dtype == np.dtype(
        plain + [("part", "<i4"), ("passed", "<u4"), ("attr", "<f4", (2,)),
                 ("depth", "<f8", (4,))])
    frags = rastrules.render(TRIANGLE)
    assert frags.size == 15 and frags["x"].dtype == np.int32
    assert rastrules.render({"target": {"width": 4, "height": 4}, "primitives": []}).size == 0


def cli_error(path):
    r = cli("render", str(path), "--fragments", "-")
    assert r.returncode == 2 and r.stdout == ""
    line = r.stderr.strip()
    assert line.startswith("rastrules: error: ") and "\n" not in line
    return line[len("rastrules: error: "):]


@pytest.mark.parametrize("bad", [
    {"target": {"width": 8, "height": 8},
     "primitives": [{"type": "triangle", "v": [[1, 1], [float("nan"), 2], [2, 7]]}]},
    {"target": {"width": 8, "height": 8}, "primitives": [{"type": "line", "v": [[1, 1]]}]},
    {"target": {"width": 0, "height": 8}, "primitives": []},
    {"target": {"width": 8, "height": 8}, "primitives": [], "samples": 3},
    {"target": {"width": 8, "height": 8}, "wrong_key": 1, "primitives": []},
])
def test_bad_input_raises_the_command_lines_one_line(tmp_path, bad):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(rastrules._plain(bad)))
    expected = cli_error(path)
    with pytest.raises(ValueError) as from_dict:
        rastrules.render(bad)
    assert str(from_dict.value) == expected
    with pytest.raises(ValueError) as from_file:
        rastrules.render(path)
    assert str(from_file.value) == expected


def test_limits_are_the_command_lines_made_smaller(tmp_path):
    # SCENE.INPUT.LIMITS scaled down: the same words as `rastrules render --max-fragments N`
    # and `--max-work N`, with the keyword that raises them.
    for name in ("strip_and_aa", "pipeline"):
        path = scene_file(tmp_path, SCENES[name])
        assert rastrules.render(path, max_fragments=10**6).size == len(rastrules.fragments(path))
        for option, keyword, value in [("--max-fragments", "max_fragments", 5),
                                       ("--max-work", "max_work", 10)]:
            r = cli("render", str(path), "--fragments", "-", option, str(value))
            assert r.returncode == 2
            words = r.stderr.strip().removeprefix("rastrules: error: ").removeprefix("render: ")
            words = words.replace(f"raise it with {option} N", f"raise it with {keyword}=N")
            words = words.replace(option, keyword)
            for call in (rastrules.render, rastrules.render_json):
                with pytest.raises(ValueError) as e:
                    call(path, **{keyword: value})
                assert str(e.value) == words


def test_malformed_json_names_its_origin(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text('{"target": ')
    expected = cli_error(path)
    with pytest.raises(ValueError) as e:
        rastrules.read_scene(path)
    assert str(e.value) == expected and str(e.value).startswith(str(path) + ": parse error")
    with pytest.raises(ValueError, match=r"^<string>: parse error at line 1"):
        rastrules.read_scene('{"target": ')
    with pytest.raises(ValueError, match="cannot open"):
        rastrules.read_scene(tmp_path / "missing.json")
    with pytest.raises(TypeError):
        rastrules.read_scene(42)


def test_explain_is_the_command_lines(tmp_path):
    for name, x, y in [("strip_and_aa", 5, 2), ("msaa", 1, 1), ("path_area", 3, 3),
                       ("pipeline", 3, 4)]:
        path = scene_file(tmp_path, SCENES[name])
        text = cli("explain", str(path), "--pixel", f"{x},{y}")
        assert text.returncode == 0, text.stderr
        assert rastrules.explain(SCENES[name], x, y) == text.stdout
        as_json = cli("explain", str(path), "--pixel", f"{x},{y}", "--json")
        assert rastrules.explain_dict(path, x, y) == json.loads(as_json.stdout)
    assert "[TRI.FILL.TOP_EDGE, TRI.FILL.LEFT_EDGE]" in rastrules.explain(TRIANGLE, 3, 3)
    with pytest.raises(ValueError, match=r"pixel \(8, 0\) is outside the 8x8 target"):
        rastrules.explain(TRIANGLE, 8, 0)


def test_scene_object_profiles_and_version(tmp_path):
    scene = rastrules.read_scene(TRIANGLE)
    assert (scene.width, scene.height, scene.samples, len(scene)) == (8, 8, 1, 1)
    assert not scene.has_pipeline and rastrules.read_scene(SCENES["pipeline"]).has_pipeline
    assert rastrules.read_scene(scene.to_json()) == scene
    assert rastrules.read_scene(scene_file(tmp_path, TRIANGLE)) == scene
    assert rastrules.profiles() == ["d3d11", "vulkan", "opengl"]
    vulkan = scene.copy()
    vulkan.apply_profile("vulkan")
    assert vulkan != scene and '"front_face": "ccw"' in vulkan.to_json()
    assert '"front_face": "cw"' in scene.to_json()
    with pytest.raises(ValueError, match=r'unknown profile "d3d9" \(d3d11, vulkan, opengl\)'):
        scene.apply_profile("d3d9")
    with pytest.raises(ValueError, match="threads"):
        rastrules.render(scene, threads=0)
    assert rastrules.__version__ == "0.1.0"


def serve(rasterize, scene):
    out = io.StringIO()
    status = rastrules.driver.serve(rasterize, io.StringIO(json.dumps(scene)), out)
    return status, out.getvalue()


def test_driver_helper_writes_the_protocol(tmp_path, capsys):
    # Tuples, dicts (with keys outside the protocol dropped) and structured rows.
    status, text = serve(lambda s: [(0, 1, 2), (0, 3, 4, 1)], TRIANGLE)
    assert status == 0
    assert json.loads(text) == {"fragments": [{"prim": 0, "x": 1, "y": 2},
                                              {"prim": 0, "x": 3, "y": 4, "mask": 1}]}
    status, text = serve(lambda s: rastrules.render(s), SCENES["strip_and_aa"])
    listed = rastrules.fragments(SCENES["strip_and_aa"])
    assert status == 0 and json.loads(text)["fragments"] == listed
    status, text = serve(lambda s: rastrules.fragments(s), SCENES["pipeline"])
    assert status == 0 and "depth" not in text and "attr" not in text
    # None: the reference draws the scene.
    status, text = serve(lambda s: None, SCENES["msaa"])
    assert status == 0 and text == rastrules.render_json(SCENES["msaa"])
    # An exception or a scene the reader refuses: status 1 and the error on standard error.
    status, text = serve(lambda s: 1 / 0, TRIANGLE)
    assert status == 1 and text == "" and "ZeroDivisionError" in capsys.readouterr().err
    status, _ = serve(lambda s: [], {"target": {"width": 1, "height": 1}, "bogus": 1, "primitives": []})
    assert status == 1 and "bogus" in capsys.readouterr().err


def example_check(tmp_path, scene, fixed):
    env = dict(os.environ, RASTRULES_EXAMPLE_FIXED="1" if fixed else "0")
    return subprocess.run(
        [CLI, "check", str(scene_file(tmp_path, scene)), "--driver",
         f"external:{sys.executable} {EXAMPLE}", "--out", str(tmp_path / "out")],
        capture_output=True, text=True, env=env, check=False)


def test_example_rasterizer_tie_bug_is_found_and_the_fixed_one_agrees(tmp_path):
    shared_edge = {"target": {"width": 4, "height": 4}, "primitives": [
        {"type": "triangle", "v": [[0, 0], [4, 0], [0, 4]]},
        {"type": "triangle", "v": [[4, 0], [4, 4], [0, 4]]}]}
    found = example_check(tmp_path, shared_edge, fixed=False)
    assert found.returncode == 1, found.stdout + found.stderr
    report = json.loads((tmp_path / "out" / "case-000000.json").read_text())
    assert report["extra"] and not report["missing"]
    assert report["primitives_after"] == 1  # shrunk to one triangle
    agrees = example_check(tmp_path, shared_edge, fixed=True)
    assert agrees.returncode == 0, agrees.stdout + agrees.stderr
    # A short campaign of every scene family: the fixed rasterizer (and the reference for what
    # it leaves) agrees throughout.
    env = dict(os.environ, RASTRULES_EXAMPLE_FIXED="1")
    campaign = subprocess.run(
        [CLI, "fuzz", "--driver", f"external:{sys.executable} {EXAMPLE}", "--cases", "6",
         "--seed", "3", "--no-progress"], capture_output=True, text=True, env=env, check=False)
    assert campaign.returncode == 0, campaign.stdout + campaign.stderr
    assert "capabilities declared" in campaign.stdout, campaign.stdout


def test_the_example_answers_the_capabilities_query():
    # rule: DRIVER.EXTERNAL.CAPABILITIES
    env = dict(os.environ, RASTRULES_QUERY="capabilities")
    reply = subprocess.run([sys.executable, str(EXAMPLE)], input="", capture_output=True,
                           text=True, env=env, check=False)
    assert reply.returncode == 0, reply.stderr
    caps = json.loads(reply.stdout)["capabilities"]
    assert caps["primitives"] == ["triangle"] and caps["sample_counts"] == [1]
    # A driver without a declaration does not answer: rastrules gives it every scene.
    silent = subprocess.run([sys.executable, "-c",
                             "import rastrules.driver; rastrules.driver.main(lambda s: None)"],
                            input="", capture_output=True, text=True, env=env, check=False)
    assert silent.returncode == 1 and silent.stdout == ""


def test_the_docstring_example_runs():
    result = doctest.testmod(rastrules)
    assert result.attempted >= 4 and result.failed == 0


# rule: SCENE.OUTPUT.BINARY
# The binary fragment list the command line writes, read by the NumPy reader: the fragments of
# the JSON list, field for field, for single-sample and multisampled scenes and a strip's seg.
BINARY_SCENES = {
    "triangles": {"target": {"width": 16, "height": 12}, "primitives": [
        {"type": "triangle", "v": [[0.5, 0.5], [15.5, 2], [3, 11.5]]},
        {"type": "triangle", "v": [[15, 11], [4, 11.5], [15.5, 1]]},
        {"type": "point", "v": [[7.5, 6.5]]}]},
    "strip": {"target": {"width": 12, "height": 8}, "primitives": [
        {"type": "line_strip", "v": [[1, 1], [10, 3], [2, 7], [11, 6]]}]},
    "msaa": {"target": {"width": 8, "height": 6}, "samples": 4, "sample_mask": 13,
             "primitives": [{"type": "triangle", "v": [[0.25, 0.5], [7.5, 1], [1, 5.75]]},
                            {"type": "line", "v": [[0, 5], [8, 0]]}]},
    "path": {"target": {"width": 10, "height": 10}, "primitives": [
        {"type": "path", "d": "M 1 1 L 9 1 L 1 9 Z M 2 2 L 6 2 L 2 6 Z", "fill_rule": "evenodd"}]},
}


@pytest.mark.parametrize("name", sorted(BINARY_SCENES))
def test_binary_fragments_equal_the_json_list(tmp_path, name):
    scene = scene_file(tmp_path, BINARY_SCENES[name])
    out = tmp_path / "f.bin"
    r = cli("render", str(scene), "--fragments", str(out))
    assert r.returncode == 0, r.stderr
    header, frags = rastrules.read_fragments_binary(out)
    listed = json.loads(cli("render", str(scene), "--fragments", "-").stdout)["fragments"]
    assert header["width"] == BINARY_SCENES[name]["target"]["width"]
    assert len(frags) == len(listed) > 0
    for got, want in zip(frags, listed):
        assert (int(got["prim"]), int(got["x"]), int(got["y"]), int(got["mask"]),
                int(got["seg"])) == (want["prim"], want["x"], want["y"], want["mask"],
                                     want.get("seg", -1))
    # The same bytes from standard output with the format named.
    assert subprocess.run([CLI, "render", str(scene), "--fragments", "-", "--fragments-format",
                           "binary"], capture_output=True, check=True).stdout == out.read_bytes()
    assert header["version"] == 2
    # Version 1 holds the same list.
    v1 = subprocess.run([CLI, "render", str(scene), "--fragments", "-", "--fragments-format",
                         "binary-v1"], capture_output=True, check=True).stdout
    header1, frags1 = rastrules.read_fragments_binary(v1)
    assert header1["version"] == 1 and header1["runs"] == header["runs"]
    assert np.array_equal(frags1, frags)


@pytest.mark.parametrize("version", [1, 2])
def test_binary_reader_refuses_damaged_files(tmp_path, version):
    scene = scene_file(tmp_path, BINARY_SCENES["msaa"])
    good = subprocess.run([CLI, "render", str(scene), "--fragments", "-", "--fragments-format",
                           "binary" if version == 2 else "binary-v1"],
                          capture_output=True, check=True).stdout
    assert rastrules.read_fragments_binary(good)[0]["version"] == version
    # Every cut is refused with a one-line error naming a byte offset.
    for cut in range(len(good)):
        with pytest.raises(ValueError, match=r"^byte \d+: "):
            rastrules.read_fragments_binary(good[:cut])

    def damaged(at, value):
        b = bytearray(good)
        b[at:at + len(value)] = value
        return bytes(b)

    u32 = lambda v: v.to_bytes(4, "little")
    u64 = lambda v: v.to_bytes(8, "little")
    cases = [
        (damaged(0, b"\x88"), "wrong magic"),
        (damaged(8, u32(3)), "version 3 is neither 1 nor 2"),
        (damaged(12, u32(0)), "width 0"),
        (damaged(20, u32(17)), "samples 17"),
        (damaged(24, u32(1)), "mask bytes 1"),
        (damaged(28, u32(1)), "reserved"),
        (good + b"\x00", "bytes after the end record"),
        (damaged(len(good) - 16, (1 << 40).to_bytes(8, "little")), "the end record counts"),
    ]
    if version == 1:
        cases += [
            (damaged(32 + 8, u32(6)), "row 6 is outside"),
            (damaged(32 + 16, u32(0)), "a run of 0 pixels"),
            (damaged(32 + 20, b"\x00\x00"), "mask 0"),
            (damaged(32 + 20, b"\x10\x00"), "mask 16"),
        ]
    else:
        w = int.from_bytes(good[32:40], "little")
        n, x, y = w & 0x7FFF, (w >> 15) & 0x3FFF, (w >> 29) & 0x3FFF
        run = lambda n, x, y, step=0: u64(n | (x << 15) | (y << 29) | (step << 43))
        cases += [
            (damaged(32, run(n, x, 6)), "byte 32: row 6 is outside"),
            (damaged(32, run(n, 8, y)), "byte 32: column 8 is outside"),
            (damaged(32, run(100, x, y)), "a run of 100 pixels"),
            (damaged(32, u64(9 << 15)), "byte 32: a control word of unknown kind 9"),
            (damaged(40, b"\x00\x00"), "mask 0"),
            (damaged(40, b"\x10\x00"), "mask 16"),
            (damaged(len(good) - 20, u32(1)), "the end record's value is not 0"),
            (good[:32] + u64((0xFFFFFFFF << 32) | (1 << 15)) + damaged(32, run(n, x, y, 1))[32:],
             "byte 40: a run whose primitive passes 4294967295"),
        ]
    for data, message in cases:
        with pytest.raises(ValueError, match=message):
            rastrules.read_fragments_binary(data)
    # The single-sample (vectorised) reader refuses the same damage.
    plain = subprocess.run([CLI, "render", str(scene_file(tmp_path, BINARY_SCENES["triangles"])),
                            "--fragments", "-", "--fragments-format",
                            "binary" if version == 2 else "binary-v1"],
                           capture_output=True, check=True).stdout
    for cut in range(0, len(plain), 7):
        with pytest.raises(ValueError, match=r"^byte \d+: "):
            rastrules.read_fragments_binary(plain[:cut])
    if version == 2:
        w = int.from_bytes(plain[32:40], "little")
        n, x, y = w & 0x7FFF, (w >> 15) & 0x3FFF, (w >> 29) & 0x3FFF
        for data, message in [
            (plain[:32] + u64(9 << 15) + plain[40:], "byte 32: a control word of unknown kind 9"),
            (plain[:32] + u64(n | (x << 15) | (12 << 29)) + plain[40:], "byte 32: row 12"),
            (plain[:32] + u64((0xFFFFFFFF << 32) | (1 << 15)) +
             u64(n | (x << 15) | (y << 29) | (1 << 43)) + plain[40:],
             "byte 40: a run whose primitive passes 4294967295"),
            (plain[:-24], "the file ends before the end record"),
            # Runs alone whose steps of 2^21 - 1 pass 2^32 - 1 at the 2049th.
            (plain[:32] + b"".join(u64(1 | ((2**21 - 1) << 43)) for _ in range(2049)) +
             u64(3 << 15) + u64(2049) + u64(2049),
             f"byte {32 + 2048 * 8}: a run whose primitive passes 4294967295"),
        ]:
            with pytest.raises(ValueError, match=message):
                rastrules.read_fragments_binary(data)
