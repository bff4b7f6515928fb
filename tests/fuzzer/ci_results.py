#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the machine-readable results of `rastrules fuzz` as a CI service reads them.

  ci_results.py results RASTRULES SCRATCH   JUnit XML parsed back (xml.etree), the JSON summary,
                                            the baseline's exit status, shards merged by
                                            `rastrules fuzz-merge` equal to the whole campaign
  ci_results.py lavapipe RASTRULES SPEC     the golden command of spec/known-lavapipe.json exits
                                            0 on lavapipe and 1 on the imprecise driver (77: no
                                            lavapipe, skipped)
"""
# rule: FUZZ.RESULTS, FUZZ.BASELINE, FUZZ.SHARD, FUZZ.MERGE

import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


def expect(cond, what):
    if not cond:
        print("FAIL:", what)
        sys.exit(1)


def junit(path):
    root = ET.parse(path).getroot()
    expect(root.tag == "testsuites", f"{path}: root is <testsuites>")
    suites = root.findall("testsuite")
    expect(len(suites) == 1, f"{path}: one <testsuite>")
    suite = suites[0]
    cases = suite.findall("testcase")
    for el in (root, suite):
        expect(int(el.get("tests")) == len(cases), f"{path}: tests= counts the test cases")
        expect(int(el.get("failures")) == sum(1 for c in cases if c.find("failure") is not None),
               f"{path}: failures= counts the failures")
        expect(int(el.get("skipped")) == sum(1 for c in cases if c.find("skipped") is not None),
               f"{path}: skipped= counts the skipped")
    return suite, cases


def results(rastrules, scratch):
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    at = lambda name: os.path.join(scratch, name)
    base = [rastrules, "fuzz", "--driver", "imprecise", "--cases", "60", "--no-progress"]
    # Without a baseline: every group fails.
    rc, out, err = run(base + ["--junit", at("all.xml"), "--summary-json", at("all.json")])
    expect(rc == 1, f"differences exit 1, got {rc}: {err}")
    summary = json.load(open(at("all.json")))
    groups = summary["groups"]
    expect(len(groups) >= 2, "the imprecise driver gives at least two groups")
    expect(summary["result"] == "fail", "result fail")
    expect(sum(g["count"] for g in groups) == summary["mismatches"], "groups count the mismatches")
    expect(summary["cases"] + summary["skipped"]["cases"] == 60, "cases run and skipped are 60")
    suite, cases = junit(at("all.xml"))
    findings = [c for c in cases if c.get("classname") == "findings"]
    expect(sorted(c.get("name") for c in findings) ==
           sorted(f"{g['rule']}, {g['class']}" for g in groups), "one test case per group")
    expect(all(c.find("failure") is not None for c in findings), "every group fails")
    expect(any("minimal scene" in (c.find("failure").text or "") for c in findings),
           "a failure holds the minimal scene")
    families = [c for c in cases if c.get("classname") == "families"]
    expect({c.get("name") for c in families} >= set(summary["families"]), "a test case per family")
    # A baseline knowing the first group: the others fail.
    known = {"version": 1, "known": [{"rule": groups[0]["rule"], "class": groups[0]["class"],
                                      "finding": "FINDING.PLANTED"}]}
    json.dump(known, open(at("one.json"), "w"))
    rc, out, err = run(base + ["--baseline", at("one.json"), "--junit", at("one.xml"),
                               "--summary-json", at("one.json.out")])
    expect(rc == 1, f"unknown groups exit 1, got {rc}")
    s1 = json.load(open(at("one.json.out")))
    expect(s1["baseline"]["known_groups"] == 1, "one group known")
    expect(s1["baseline"]["new_groups"] == len(groups) - 1, "the others are new")
    _, cases1 = junit(at("one.xml"))
    name0 = f"{groups[0]['rule']}, {groups[0]['class']}"
    c0 = [c for c in cases1 if c.get("name") == name0][0]
    expect(c0.find("failure") is None and "FINDING.PLANTED" in c0.find("system-out").text,
           "the known group passes and names its finding")
    # A baseline knowing every group: exit 0, no failure.
    json.dump({"version": 1, "known": [{"rule": g["rule"], "class": g["class"]} for g in groups]},
              open(at("every.json"), "w"))
    rc, out, err = run(base + ["--baseline", at("every.json"), "--junit", at("every.xml"),
                               "--summary-json", at("every.json.out")])
    expect(rc == 0, f"only known groups exit 0, got {rc}: {out}{err}")
    suite, _ = junit(at("every.xml"))
    expect(suite.get("failures") == "0", "no failure")
    expect(json.load(open(at("every.json.out")))["result"] == "pass", "result pass")
    # A bad baseline: exit 2 and one error line, before any case.
    open(at("bad.json"), "w").write('{"version": 1, "known": [{"rule": "X"}]}')
    rc, out, err = run(base + ["--baseline", at("bad.json")])
    expect(rc == 2 and "known[0].class: missing" in err and out == "", f"bad baseline: {rc} {err}")
    rc, out, err = run(base + ["--shard", "4/4"])
    expect(rc == 2 and "--shard" in err, f"bad shard: {rc} {err}")
    # Four shards through the command line, merged: the whole campaign's summary and JUnit.
    rc, _, err = run(base + ["--out", at("whole"), "--summary-json", at("whole.json"),
                             "--junit", at("whole.xml")])
    expect(rc == 1, "the whole campaign differs")
    dirs = []
    for k in range(4):
        dirs.append(at(f"shard{k}"))
        rc, _, err = run(base + ["--shard", f"{k}/4", "--out", dirs[-1]])
        expect(rc in (0, 1), f"shard {k}: {err}")
    rc, out, err = run([rastrules, "fuzz-merge", *dirs, "--out", at("merged"), "--summary-json",
                        at("merged.json"), "--junit", at("merged.xml")])
    expect(rc == 1, f"the merge differs as the whole does, got {rc}: {err}")
    whole, merged = json.load(open(at("whole.json"))), json.load(open(at("merged.json")))
    for s in (whole, merged):
        del s["seconds"]
        for g in s["groups"]:
            g.pop("picture", None)
    expect(whole == merged, "merged summary equals the whole campaign's")
    strip = lambda f: {k: v for k, v in f.items() if k not in ("scene", "shrunk_scene", "picture",
                                                                "report")}
    fw = [strip(f) for f in json.load(open(at("whole/report.json")))["findings"]]
    fm = [strip(f) for f in json.load(open(at("merged/report.json")))["findings"]]
    expect(fw == fm, "merged findings equal the whole campaign's, finding for finding")
    _, cw = junit(at("whole.xml"))
    _, cm = junit(at("merged.xml"))
    expect([ET.tostring(c) for c in cw] == [ET.tostring(c) for c in cm], "same JUnit test cases")
    rc, _, err = run([rastrules, "fuzz-merge", *dirs[:3]])
    expect(rc == 2 and "missing" in err, f"a missing shard: {rc} {err}")
    print("ok")


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
    if len(sys.argv) == 4 and sys.argv[1] == "results":
        results(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "lavapipe":
        lavapipe(sys.argv[2], sys.argv[3])
    else:
        print(__doc__)
        sys.exit(2)
