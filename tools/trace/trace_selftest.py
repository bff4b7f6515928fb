#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Self-test of trace.py: runs it on small fake source trees built here, in a temporary
folder, and checks that it fails (naming every problem) or passes as it should.

Usage: trace_selftest.py PATH/TO/trace.py
"""

import os
import subprocess
import sys
import tempfile

# Comment markers are assembled at run time so that no line of this file is itself a tag.
CPP = "/" + "/ rule: "
PY = "#" + " rule: "
SMT = ";" + " rule: "


def write(root, relpath, lines):
    path = os.path.join(root, relpath)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def spec_rule(rule_id, title, kind, depends=None):
    lines = [f"### {rule_id} — {title}", "", "Text of the rule.", "", f"- kind: {kind}"]
    if depends:
        lines.append(f"- depends: {depends}")
    lines.append("- source: self-test")
    return lines + [""]


def good_tree(root):
    """A tree in which every rule is satisfied."""
    write(root, "spec/rules/demo.md",
          ["# Demo rules", ""]
          + spec_rule("DEMO.EDGE.ONE", "First rule", "normative")
          + spec_rule("DEMO.EDGE.TWO", "Second rule", "normative", "DEMO.EDGE.ONE")
          + spec_rule("DEMO.EDGE.DERIVED", "A consequence", "derived", "DEMO.EDGE.ONE, DEMO.EDGE.TWO")
          + spec_rule("DEMO.NOTE.INFO", "Informative", "informative"))
    write(root, "kernel/include/demo.hpp",
          ["#pragma once", CPP + "DEMO.EDGE.ONE, DEMO.EDGE.TWO", "int f();"])
    write(root, "tests/demo/demo_test.cpp",
          [CPP + "DEMO.EDGE.ONE", "TEST(A, B) {}", CPP + "DEMO.EDGE.TWO", "TEST(A, C) {}"])
    write(root, "proofs/demo/proof.smt2", [SMT + "DEMO.EDGE.ONE, DEMO.EDGE.TWO, DEMO.EDGE.DERIVED"])
    write(root, "properties/demo/demo_props.cpp", [CPP + "DEMO.EDGE.DERIVED"])
    write(root, "tools/gen.py", [PY + "DEMO.EDGE.ONE", "print(1)"])


def run(trace, root):
    matrix = os.path.join(root, "out", "matrix.md")
    p = subprocess.run([sys.executable, trace, "--root", root, "--matrix", matrix],
                       capture_output=True, text=True, check=False)
    return p.returncode, p.stdout + p.stderr, matrix


def run_on_good_tree(trace, files):
    """Runs trace.py on the clean tree plus `files` ({relpath: lines}); returns the exit code,
    the output and its lines."""
    with tempfile.TemporaryDirectory() as root:
        good_tree(root)
        for relpath, lines in files.items():
            write(root, relpath, lines)
        rc, out, _ = run(trace, root)
    return rc, out, out.splitlines()


FAILURES = []


def expect(cond, what, output):
    if not cond:
        FAILURES.append(f"{what}\n--- trace.py output ---\n{output}")


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    trace = sys.argv[1]

    # 1. A clean tree passes and its matrix lists every rule with its evidence.
    with tempfile.TemporaryDirectory() as root:
        good_tree(root)
        rc, out, matrix = run(trace, root)
        expect(rc == 0, "clean tree: expected exit 0", out)
        expect("trace: 4 rules, 0 errors, 0 warnings" in out, "clean tree: summary line", out)
        text = open(matrix, encoding="utf-8").read() if os.path.exists(matrix) else ""
        expect("DEMO.EDGE.DERIVED" in text and "kernel/include/demo.hpp:2" in text
               and "proofs/demo/proof.smt2:1" in text and "tests/demo/demo_test.cpp:3" in text,
               "clean tree: matrix lists rules and file:line evidence", text or out)

    # 2. The brief's case: an untested normative rule and an unknown ID in a tag.
    with tempfile.TemporaryDirectory() as root:
        good_tree(root)
        write(root, "spec/rules/more.md", spec_rule("DEMO.EDGE.UNTESTED", "No example", "normative"))
        write(root, "kernel/src/more.cpp", [CPP + "DEMO.EDGE.UNTESTED", "int g() { return 0; }"])
        write(root, "tests/demo/more_test.cpp", ["#include <x>", CPP + "DEMO.EDGE.NOPE", "TEST(A, D) {}"])
        rc, out, _ = run(trace, root)
        expect(rc == 1, "untested + unknown: expected exit 1", out)
        expect(any("DEMO.EDGE.UNTESTED" in l and "no example test" in l for l in out.splitlines()),
               "untested + unknown: the untested rule is named", out)
        expect(any("unknown rule ID DEMO.EDGE.NOPE" in l and "tests/demo/more_test.cpp:2" in l
                   for l in out.splitlines()),
               "untested + unknown: the unknown ID is named with file:line", out)
        expect("2 errors" in out, "untested + unknown: exactly two errors", out)

    # 3. Registry problems: duplicate ID, depends on an unknown ID, missing implementation,
    #    bad kind, malformed tag; and the warning for a rule with no property or proof.
    with tempfile.TemporaryDirectory() as root:
        good_tree(root)
        write(root, "spec/rules/bad.md",
              spec_rule("DEMO.EDGE.ONE", "Again", "normative")
              + spec_rule("DEMO.EDGE.DEP", "Bad dependency", "informative", "DEMO.EDGE.GHOST")
              + spec_rule("DEMO.EDGE.NOIMPL", "Tested only", "normative")
              + spec_rule("DEMO.EDGE.ODD", "Odd kind", "sometimes"))
        write(root, "tests/demo/bad_test.cpp", [CPP + "DEMO.EDGE.NOIMPL", CPP + "see DEMO.EDGE.ONE"])
        write(root, "tools/trace/ignored.py", [PY + "DEMO.EDGE.IGNORED_BY_DESIGN"])
        rc, out, _ = run(trace, root)
        lines = out.splitlines()
        expect(rc == 1, "registry problems: expected exit 1", out)
        expect(any("duplicate rule ID DEMO.EDGE.ONE" in l for l in lines), "duplicate ID named", out)
        expect(any("unknown rule ID DEMO.EDGE.GHOST" in l and "depends" in l for l in lines),
               "unknown dependency named", out)
        expect(any("DEMO.EDGE.NOIMPL" in l and "no implementation site" in l for l in lines),
               "missing implementation named", out)
        expect(any("unknown kind 'sometimes'" in l for l in lines), "bad kind named", out)
        expect(any("malformed rule tag" in l and "bad_test.cpp:2" in l for l in lines),
               "malformed tag named", out)
        expect(not any("IGNORED_BY_DESIGN" in l for l in lines), "tools/trace/ is not scanned", out)
        expect(any(l.startswith("trace: warning:") and "DEMO.EDGE.NOIMPL" in l
                   and "neither a property nor a proof" in l for l in lines),
               "warning for a rule with no property or proof", out)

    # 4. Rule IDs printed at run time: a renamed rule left in a message is an error; a family
    #    ("DEMO.EDGE.*"), a defined ID, a non-rule token and a comment are not.
    rc, out, lines = run_on_good_tree(trace, {"tools/cli/messages.cpp": [
        'const char* a = "is NaN (DEMO.EDGE.ONE)";',
        'const char* b = "see DEMO.EDGE.* and D3D11.3 15.4";',
        '// a comment naming DEMO.EDGE.OLD is not printed',
        'const char* c = "a stale DEMO.EDGE.OLD";']})
    expect(rc == 1, "stale printed ID: expected exit 1", out)
    expect(any("unknown rule ID DEMO.EDGE.OLD printed at run time" in l
               and "tools/cli/messages.cpp:4" in l for l in lines),
           "stale printed ID named with file:line", out)
    expect("1 errors" in out, "stale printed ID: exactly one error", out)

    # 5. The rule-ID table: a defined ID passes; an undefined ID of a known area, an ID of an
    #    area the registry does not know (which the string scan would skip), a duplicate ID and
    #    a malformed entry are errors, each named with file:line.
    table = "kernel/include/rastrules/rules.hpp"
    rc, out, lines = run_on_good_tree(trace, {table: [
        "struct RuleId { const char* id; };",
        'inline constexpr RuleId kDemoOne{"DEMO.EDGE.ONE"};',
        'inline constexpr RuleId kDemoGone{"DEMO.EDGE.GONE"};',
        'inline constexpr RuleId kOther{"OTHER.AREA.RULE"};',
        'inline constexpr RuleId kDemoAgain{"DEMO.EDGE.ONE"};',
        'constexpr RuleId kDemoBad = {"DEMO.EDGE.TWO"};']})
    expect(rc == 1, "rule table: expected exit 1", out)
    expect(not any(f"{table}:2" in l for l in lines), "rule table: a defined ID passes", out)
    expect(any(f"{table}:3" in l and "DEMO.EDGE.GONE" in l and "does not define" in l
               for l in lines), "rule table: undefined ID named with file:line", out)
    expect(any(f"{table}:4" in l and "OTHER.AREA.RULE" in l for l in lines),
           "rule table: an ID of an unknown area is an error", out)
    expect(any(f"{table}:5" in l and "already named kDemoOne" in l for l in lines),
           "rule table: duplicate ID named", out)
    expect(any(f"{table}:6" in l and "malformed rule table entry" in l for l in lines),
           "rule table: malformed entry named", out)
    expect("4 errors" in out and "4 in the rule table" in out,
           "rule table: exactly four errors, four entries", out)

    # 6. Usage error: no spec/ folder.
    with tempfile.TemporaryDirectory() as root:
        rc, out, _ = run(trace, root)
        expect(rc == 2, "no spec/: expected exit 2", out)

    for f in FAILURES:
        print("FAILED:", f, file=sys.stderr)
    print(f"trace.selftest: 6 scenarios, {len(FAILURES)} failed checks")
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
