#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks `rastrules fuzz` as a CI service runs it.

  ci_results.py lavapipe RASTRULES SPEC     the golden command of spec/known-lavapipe.json exits
                                            0 on lavapipe and 1 on the imprecise driver (77: no
                                            lavapipe, skipped)
"""
# rule: FUZZ.BASELINE

import os
import subprocess
import sys


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def expect(cond, what):
    if not cond:
        print("FAIL:", what)
        sys.exit(1)


def lavapipe(rastrules, spec):
    known = os.path.join(spec, "known-lavapipe.json")
    golden = ["fuzz", "--profile", "vulkan", "--mode", "legal", "--baseline", known,
              "--no-progress"]
    rc, out, err = run([rastrules, *golden, "--driver", "lavapipe"])
    if rc == 2 and "--driver:" in err:
        print("no lavapipe:", err.strip())
        sys.exit(77)
    expect(rc == 0, f"lavapipe with its baseline exits 0, got {rc}:\n{out}{err}")
    rc, out, err = run([rastrules, *golden, "--driver", "imprecise"])
    expect(rc == 1, f"the imprecise driver with lavapipe's baseline exits 1, got {rc}:\n{out}{err}")
    print("ok")


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "lavapipe":
        lavapipe(sys.argv[2], sys.argv[3])
    else:
        print(__doc__)
        sys.exit(2)
