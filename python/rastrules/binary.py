# SPDX-License-Identifier: MIT
"""The binary fragment list (SCENE.OUTPUT.BINARY) read with NumPy.

``rastrules render SCENE.json --fragments OUT.bin`` writes it; ``read_fragments_binary`` reads
it into a NumPy structured array with the fields ``prim``, ``x``, ``y``, ``mask`` and ``seg``
(-1 for none), checking what the C++ reader checks (``rastrules::io::read_fragment_binary``):
the magic, the version, the header, every run inside the target, nonzero masks inside the
sample count, zero padding, the (prim, y, x, seg) order, the end record's counts and nothing
after it. This is a second reader written from the spec, not a binding of the C++ one.
"""

import os

import numpy as np

MAGIC = bytes([0x89, 0x52, 0x52, 0x46, 0x0D, 0x0A, 0x1A, 0x0A])
_END = 0xFFFFFFFF
_NO_SEG = 0xFFFFFFFF
_HEADER = 32
_RUN = 20
_END_BYTES = 24
_MAX_SIDE = 16384

DTYPE = np.dtype(
    [("prim", "<u4"), ("x", "<i4"), ("y", "<i4"), ("mask", "<u4"), ("seg", "<i4")]
)


def _fail(offset, problem):
    raise ValueError(f"byte {offset}: {problem}")


def _u32(b, at):
    return int.from_bytes(b[at : at + 4], "little")


def read_fragments_binary(source, max_fragments=1 << 26):
    """Reads a binary fragment list from a path or from bytes. Returns (header, fragments):
    header a dict with width, height, samples, mask_bytes and runs; fragments a structured
    array (DTYPE) in the file's order. Raises ValueError("byte N: problem") on anything the
    format does not allow, or more than max_fragments fragments."""
    if isinstance(source, (str, os.PathLike)):
        with open(source, "rb") as f:
            data = f.read()
    else:
        data = bytes(source)
    if len(data) < _HEADER:
        _fail(len(data), "the file ends inside the 32-byte header")
    if data[:8] != MAGIC:
        _fail(0, "not a rastrules binary fragment list (wrong magic bytes)")
    version, width, height, samples, mask_bytes, reserved = (
        _u32(data, at) for at in range(8, 32, 4)
    )
    if version != 1:
        _fail(8, f"version {version} is not 1")
    if not 1 <= width <= _MAX_SIDE:
        _fail(12, f"width {width} is outside [1, {_MAX_SIDE}]")
    if not 1 <= height <= _MAX_SIDE:
        _fail(16, f"height {height} is outside [1, {_MAX_SIDE}]")
    if not 1 <= samples <= 16:
        _fail(20, f"samples {samples} is outside [1, 16]")
    if mask_bytes not in (0, 2):
        _fail(24, f"mask bytes {mask_bytes} is neither 0 nor 2")
    if mask_bytes == 0 and samples != 1:
        _fail(24, f"mask bytes 0 (no masks) with {samples} samples")
    if reserved != 0:
        _fail(28, "the reserved field is not 0")

    # The runs: their offsets first (fixed 20 bytes without masks; a walk with them).
    starts = []
    masks = []
    at = _HEADER
    total = 0
    if mask_bytes == 0:
        body = len(data) - _HEADER - _END_BYTES
        count = max(body, 0) // _RUN
        if count > 0:
            table = np.frombuffer(data, dtype="<u4", count=count * 5, offset=_HEADER)
            table = table.reshape(count, 5)
            ends = np.nonzero(table[:, 0] == _END)[0]
            if ends.size:
                count = int(ends[0])  # an end record inside: everything after is checked below
                table = table[:count]
        else:
            table = np.zeros((0, 5), dtype="<u4")
        at = _HEADER + count * _RUN
    else:
        rows = []
        while len(data) - at >= 4 and _u32(data, at) != _END:
            if len(data) - at < _RUN:
                _fail(len(data), "the file ends inside a run")
            run = [_u32(data, at + 4 * i) for i in range(5)]
            n = run[4]
            block = (n * 2 + 3) // 4 * 4
            if n < 1:
                _fail(at + 16, f"a run of {n} pixels from column {run[3]} does not fit a row of {width}")
            if len(data) - at - _RUN < block:
                _fail(len(data), "the file ends inside a run's masks")
            m = np.frombuffer(data, dtype="<u2", count=n, offset=at + _RUN)
            if block > n * 2 and any(data[at + _RUN + n * 2 : at + _RUN + block]):
                _fail(at + _RUN + n * 2, "a run's padding is not 0")
            bad = np.nonzero((m == 0) | (m >= (1 << samples)))[0]
            if bad.size:
                _fail(at + _RUN + 2 * int(bad[0]),
                      f"mask {int(m[bad[0]])} is not a nonzero mask of {samples} samples")
            rows.append(run)
            masks.append(m)
            starts.append(at)
            total += n
            if total > max_fragments:
                _fail(at + 16, f"more than {max_fragments} fragments")
            at += _RUN + block
        table = np.array(rows, dtype="<u4").reshape(len(rows), 5)
    count = table.shape[0]
    run_at = (
        _HEADER + np.arange(count, dtype=np.int64) * _RUN
        if mask_bytes == 0
        else np.array(starts, dtype=np.int64)
    )

    prim, seg, y, x, n = (table[:, i].astype(np.int64) for i in range(5))
    for name, offset, bad in (
        ("row", 8, y >= height),
        ("column", 12, x >= width),
    ):
        idx = np.nonzero(bad)[0]
        if idx.size:
            i = int(idx[0])
            value = int(y[i] if name == "row" else x[i])
            limit = height if name == "row" else width
            _fail(int(run_at[i]) + offset, f"{name} {value} is outside the target's {limit}")
    idx = np.nonzero((n < 1) | (x + n > width))[0]
    if idx.size:
        i = int(idx[0])
        _fail(int(run_at[i]) + 16,
              f"a run of {int(n[i])} pixels from column {int(x[i])} does not fit a row of {width}")
    if int(n.sum()) > max_fragments:
        _fail(int(run_at[-1]) + 16, f"more than {max_fragments} fragments")
    seg_key = np.where(seg == _NO_SEG, -1, seg)
    if count > 1:
        # Run i's first fragment after run i-1's last: (prim, y, x, seg) lexicographic.
        p0, y0, x0, s0 = prim[:-1], y[:-1], x[:-1] + n[:-1] - 1, seg_key[:-1]
        p1, y1, x1, s1 = prim[1:], y[1:], x[1:], seg_key[1:]
        after = (p1 > p0) | ((p1 == p0) & ((y1 > y0) | ((y1 == y0) & (
            (x1 > x0) | ((x1 == x0) & (s1 > s0))))))
        idx = np.nonzero(~after)[0]
        if idx.size:
            _fail(int(run_at[int(idx[0]) + 1]),
                  "a run that does not come after the previous one in (prim, y, x, seg) order")

    if len(data) - at < 4:
        _fail(len(data), "the file ends before the end record")
    if len(data) - at < _END_BYTES:
        _fail(len(data), "the file ends inside the end record")
    if _u32(data, at) != _END:
        _fail(len(data), "the file ends inside a run")
    if _u32(data, at + 4) != 0:
        _fail(at + 4, "the end record's reserved field is not 0")
    fragments_total = int(n.sum())
    counted = int.from_bytes(data[at + 8 : at + 16], "little")
    if counted != fragments_total:
        _fail(at + 8, f"the end record counts {counted} fragments, the runs hold {fragments_total}")
    runs = int.from_bytes(data[at + 16 : at + 24], "little")
    if runs != count:
        _fail(at + 16, f"the end record counts {runs} runs, the file holds {count}")
    if at + _END_BYTES != len(data):
        _fail(at + _END_BYTES, "bytes after the end record")

    out = np.empty(fragments_total, dtype=DTYPE)
    first = np.repeat(np.cumsum(n) - n, n)
    out["prim"] = np.repeat(prim, n)
    out["y"] = np.repeat(y, n)
    out["x"] = np.repeat(x, n) + (np.arange(fragments_total) - first)
    out["seg"] = np.repeat(seg_key, n)
    out["mask"] = np.concatenate(masks) if mask_bytes and masks else 1
    header = {"width": width, "height": height, "samples": samples, "mask_bytes": mask_bytes,
              "runs": count}
    return header, out
