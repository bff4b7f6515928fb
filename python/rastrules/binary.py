# SPDX-License-Identifier: MIT
"""The binary fragment list (SCENE.OUTPUT.BINARY) read with NumPy.

``rastrules render SCENE.json --fragments OUT.bin`` writes it; ``read_fragments_binary`` reads
it into a NumPy structured array with the fields ``prim``, ``x``, ``y``, ``mask`` and ``seg``
(-1 for none), checking what the C++ reader checks (``rastrules::io::read_fragment_binary``):
the magic, the version (2, a 64-bit word a run, which the command line writes; or 1, 20 bytes
a run), the header, every run inside the target, nonzero masks inside the sample count, zero
padding, the (prim, y, x, seg) order, version 2's control words, the end record's counts and
nothing after it. This is a second reader written from the spec, not a binding of the C++ one.
"""

import os

import numpy as np

MAGIC = bytes([0x89, 0x52, 0x52, 0x46, 0x0D, 0x0A, 0x1A, 0x0A])
_END = 0xFFFFFFFF
_NO_SEG = 0xFFFFFFFF
_HEADER = 32
_RUN = 20
_END_BYTES = 24
_WORD = 8  # version 2
_PRIM, _SEG, _STOP = 1, 2, 3  # version 2's control words
_MAX_SIDE = 16384

DTYPE = np.dtype(
    [("prim", "<u4"), ("x", "<i4"), ("y", "<i4"), ("mask", "<u4"), ("seg", "<i4")]
)


def _fail(offset, problem):
    raise ValueError(f"byte {offset}: {problem}")


def _u32(b, at):
    return int.from_bytes(b[at : at + 4], "little")


def _runs_v1(data, width, samples, mask_bytes, max_fragments):
    """Version 1's 20-byte runs: (prim, seg, y, x, n, run_at, masks, at), seg 0xFFFFFFFF for
    none, at the end record's offset (checked by the caller)."""
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
    return prim, seg, y, x, n, run_at, masks, at


def _check_masks(data, at, n, samples, unit):
    """A run's n masks at `at` and their zero padding to a multiple of `unit` bytes; returns
    (masks, bytes taken)."""
    block = (n * 2 + unit - 1) // unit * unit
    if len(data) - at < block:
        _fail(len(data), "the file ends inside a run's masks")
    m = np.frombuffer(data, dtype="<u2", count=n, offset=at)
    if block > n * 2 and any(data[at + n * 2 : at + block]):
        _fail(at + n * 2, "a run's padding is not 0")
    bad = np.nonzero((m == 0) | (m >= (1 << samples)))[0]
    if bad.size:
        _fail(at + 2 * int(bad[0]),
              f"mask {int(m[bad[0]])} is not a nonzero mask of {samples} samples")
    return m, block


def _runs_v2(data, width, height, samples, mask_bytes, max_fragments):
    """Version 2's 64-bit words: (prim, seg, y, x, n, run_at, masks, at) as _runs_v1 returns
    them. A word with n = 0 is a control word: kind 1 sets prim (no segment), 2 sets seg, 3
    starts the end record; a run's step moves prim on and ends the segment."""
    masks = []
    if mask_bytes == 0:
        count = (len(data) - _HEADER) // _WORD
        w = np.frombuffer(data, dtype="<u8", count=count, offset=_HEADER)
        n = (w & np.uint64(0x7FFF)).astype(np.int64)
        kind = ((w >> np.uint64(15)) & np.uint64(0x1FFFF)).astype(np.int64)
        stops = np.nonzero((n == 0) & (kind == _STOP))[0]
        if not stops.size:
            _fail(len(data), "the file ends before the end record")
        end = int(stops[0])
        w, n, kind = w[:end], n[:end], kind[:end]
        at = _HEADER + end * _WORD
        control = n == 0
        unknown = np.nonzero(control & (kind != _PRIM) & (kind != _SEG))[0]
        if unknown.size:
            i = int(unknown[0])
            _fail(_HEADER + i * _WORD, f"a control word of unknown kind {int(kind[i])}")
        index = np.arange(end, dtype=np.int64)
        field = lambda w, shift: ((w >> np.uint64(shift)) & np.uint64(0x3FFF)).astype(np.int64)
        if not control.any():
            # Runs alone (every list of triangles whose primitives step by less than 2^21): prim
            # is the sum of the steps, and no run has a segment.
            prim = np.cumsum((w >> np.uint64(43)).astype(np.int64))
            over = np.nonzero(prim > 0xFFFFFFFF)[0]
            if over.size:
                _fail(_HEADER + int(over[0]) * _WORD, "a run whose primitive passes 4294967295")
            seg = np.full(end, _NO_SEG, dtype=np.int64)
            return prim, seg, field(w, 29), field(w, 15), n, _HEADER + index * _WORD, masks, at
        value = (w >> np.uint64(32)).astype(np.int64)
        step = np.where(control, 0, (w >> np.uint64(43)).astype(np.int64))
        sets = control & (kind == _PRIM)
        # prim: the last control word's value, plus the steps since.
        moved = np.cumsum(step)
        last_set = np.maximum.accumulate(np.where(sets, index, -1)) if end else index
        base = np.where(last_set >= 0,
                        value[np.maximum(last_set, 0)] - moved[np.maximum(last_set, 0)], 0)
        prim = base + moved
        # seg: the last seg word's value if no primitive was set or stepped to since.
        resets = sets | (step != 0)
        last_seg = np.maximum.accumulate(np.where(control & (kind == _SEG), index, -1)) \
            if end else index
        last_reset = np.maximum.accumulate(np.where(resets, index, -1)) if end else index
        seg = np.where(last_seg > last_reset, value[np.maximum(last_seg, 0)], _NO_SEG)
        runs = ~control
        over = np.nonzero(runs & (prim > 0xFFFFFFFF))[0]
        if over.size:
            _fail(_HEADER + int(over[0]) * _WORD, "a run whose primitive passes 4294967295")
        run_at = _HEADER + index[runs] * _WORD
        w = w[runs]
        return prim[runs], seg[runs], field(w, 29), field(w, 15), n[runs], run_at, masks, at
    # With masks: a walk, word by word.
    rows = []
    starts = []
    at = _HEADER
    prim, seg, total = 0, _NO_SEG, 0
    while True:
        if len(data) - at < _WORD:
            _fail(len(data), "the file ends before the end record")
        w = int.from_bytes(data[at : at + _WORD], "little")
        n = w & 0x7FFF
        if n == 0:
            kind, value = (w >> 15) & 0x1FFFF, w >> 32
            if kind == _STOP:
                break
            if kind == _PRIM:
                prim, seg = value, _NO_SEG
            elif kind == _SEG:
                seg = value
            else:
                _fail(at, f"a control word of unknown kind {kind}")
            at += _WORD
            continue
        step = w >> 43
        if step:
            if prim + step > 0xFFFFFFFF:
                _fail(at, "a run whose primitive passes 4294967295")
            prim, seg = prim + step, _NO_SEG
        x, y = (w >> 15) & 0x3FFF, (w >> 29) & 0x3FFF
        if y >= height:
            _fail(at, f"row {y} is outside the target's {height}")
        if x >= width:
            _fail(at, f"column {x} is outside the target's {width}")
        if x + n > width:
            _fail(at, f"a run of {n} pixels from column {x} does not fit a row of {width}")
        m, block = _check_masks(data, at + _WORD, n, samples, 8)
        rows.append((prim, seg, y, x, n))
        masks.append(m)
        starts.append(at)
        total += n
        if total > max_fragments:
            _fail(at, f"more than {max_fragments} fragments")
        at += _WORD + block
    table = np.array(rows, dtype=np.int64).reshape(len(rows), 5)
    prim, seg, y, x, n = (table[:, i] for i in range(5))
    return prim, seg, y, x, n, np.array(starts, dtype=np.int64), masks, at


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
    if version not in (1, 2):
        _fail(8, f"version {version} is neither 1 nor 2")
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

    if version == 1:
        prim, seg, y, x, n, run_at, masks, at = _runs_v1(data, width, samples, mask_bytes,
                                                         max_fragments)
        offsets = (8, 12, 16)
    else:
        prim, seg, y, x, n, run_at, masks, at = _runs_v2(data, width, height, samples,
                                                         mask_bytes, max_fragments)
        offsets = (0, 0, 0)
    count = len(prim)
    for name, offset, bad in (
        ("row", offsets[0], y >= height),
        ("column", offsets[1], x >= width),
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
        _fail(int(run_at[i]) + offsets[2],
              f"a run of {int(n[i])} pixels from column {int(x[i])} does not fit a row of {width}")
    if int(n.sum()) > max_fragments:
        _fail(int(run_at[-1]) + offsets[2], f"more than {max_fragments} fragments")
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

    if version == 1:
        if len(data) - at < 4:
            _fail(len(data), "the file ends before the end record")
        if len(data) - at < _END_BYTES:
            _fail(len(data), "the file ends inside the end record")
        if _u32(data, at) != _END:
            _fail(len(data), "the file ends inside a run")
        if _u32(data, at + 4) != 0:
            _fail(at + 4, "the end record's reserved field is not 0")
    else:
        if len(data) - at < _END_BYTES:
            _fail(len(data), "the file ends inside the end record")
        if _u32(data, at + 4) != 0:
            _fail(at + 4, "the end record's value is not 0")
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
    header = {"version": version, "width": width, "height": height, "samples": samples,
              "mask_bytes": mask_bytes, "runs": count}
    return header, out
