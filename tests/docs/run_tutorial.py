#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs a tutorial of docs/ as written and checks what it promises.

usage: run_tutorial.py TUTORIAL.md BUILD_DIR PYTHON

Every ```sh block of the tutorial runs, in order, in one bash process whose working directory
is a fresh temporary directory that looks like the top of the repository (examples/ and spec/
linked from the source tree, build/ linked to BUILD_DIR), so what the reader types is what runs.
After each block the comments name what it must do:
    # expect exit N              the block's last command exits with status N
    # expect output: TEXT        TEXT appears in the block's standard output or error
PYTHON (the interpreter the module was built for) is what `python3` names there. Exits 1 on the
first unmet expectation, printing the block and its output.
"""

import os
import pathlib
import re
import subprocess
import sys
import tempfile


def blocks(markdown):
    """The ```sh blocks: (commands, expected exit status or None, [texts])."""
    out = []
    for body in re.findall(r"^```sh\n(.*?)^```", markdown, flags=re.M | re.S):
        status, texts = None, []
        for line in body.splitlines():
            m = re.match(r"# expect exit (\d+)$", line.strip())
            if m:
                status = int(m.group(1))
            m = re.match(r"# expect output: (.*)$", line.strip())
            if m:
                texts.append(m.group(1))
        out.append((body, status, texts))
    return out


def main(argv):
    if len(argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    tutorial, build, python = pathlib.Path(argv[1]), pathlib.Path(argv[2]), argv[3]
    root = tutorial.resolve().parent.parent
    todo = blocks(tutorial.read_text())
    if not todo:
        print(f"run_tutorial: no ```sh block in {tutorial}", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory(prefix="rastrules-tutorial-") as tmp:
        work = pathlib.Path(tmp)
        for name in ("examples", "spec"):
            (work / name).symlink_to(root / name)
        (work / "build").symlink_to(build.resolve())
        bindir = work / ".bin"
        bindir.mkdir()
        (bindir / "python3").symlink_to(python)
        script = []
        for i, (body, _, _) in enumerate(todo):
            script.append(f"exec >{work}/.out{i} 2>&1\n{body}\necho $? >{work}/.status{i}\n")
        env = dict(os.environ, PATH=f"{bindir}:{os.environ.get('PATH', '')}")
        env.pop("PYTHONPATH", None)  # the tutorial sets it
        subprocess.run(["bash", "-c", "".join(script)], cwd=work, env=env, check=False,
                       timeout=600)
        for i, (body, status, texts) in enumerate(todo):
            out = (work / f".out{i}").read_text(errors="replace")
            got = (work / f".status{i}").read_text().strip() if (work / f".status{i}").exists() else "?"
            bad = []
            if status is not None and got != str(status):
                bad.append(f"exit status {got}, expected {status}")
            bad += [f"no {t!r} in the output" for t in texts if t not in out]
            if bad:
                print(f"run_tutorial: {tutorial.name}, block {i + 1}: " + "; ".join(bad))
                print("---- block\n" + body + "---- output (last 60 lines)")
                print("\n".join(out.splitlines()[-60:]))
                return 1
            print(f"block {i + 1}: ok (exit {got}, {len(texts)} text(s) found)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
