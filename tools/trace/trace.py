#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Rule traceability check for rastrules (Python 3 standard library only).

Reads the rule registry (level-3 headings `### <ID> — <title>` in spec/**/*.md and the
`- key: value` lines under them), scans the source tree for citation tags (a comment line
`// rule: ID[, ID ...]`, or with `#` or `;`), and checks that

  * every rule ID is defined once, has a valid kind, and depends only on defined IDs;
  * every cited ID exists and every tag is well formed;
  * every rule ID in a string literal of runtime code (kernel/, check/, tools/, bench/, fuzz/:
    what users see printed) is defined, or names a family as "ID.*";
  * every entry of the rule-ID table (kernel/include/rastrules/rules.hpp, the IDs the kernel's
    decision records name and the tools print) is defined, once, whatever its area;
  * every normative rule has an implementation site (kernel/, bench/, tools/ except tools/trace/)
    and an example test (tests/).

  * every normative or derived rule of the strict rule families (STRICT_AREAS: TRI, SNAP,
    FIX, RASTER, POINT, LINE, MSAA, FAST) has a property (properties/) or a proof (proofs/);
    the oracle (oracle/) is evidence of its own kind.

Other normative and derived rules with neither a property nor a proof are reported as
warnings, so the gap stays visible. The matrix of rule to
evidence is written as Markdown to --matrix.

Exit status: 0 no errors, 1 errors found, 2 usage error (e.g. no spec/ under --root).
"""

import argparse
import os
import re
import sys

ID_RE = r"[A-Z][A-Z0-9_]*(?:\.[A-Z0-9_]+)+"
HEADING_RE = re.compile(r"^###\s+(" + ID_RE + r")\s+—\s+(\S.*)$")
# A level-3 heading that starts like a rule ID but does not have the registry's form.
ID_LIKE_HEADING_RE = re.compile(r"^###\s+[A-Z][A-Z0-9_]*\.[A-Z0-9_.]")
SECTION_END_RE = re.compile(r"^#{1,3}\s")
KEY_RE = re.compile(r"^-\s+([a-z][a-z0-9_-]*):\s*(.*)$")
TAG_RE = re.compile(r"^\s*(?://+|#+|;+)\s*rule:(.*)$")
FULL_ID_RE = re.compile(r"^" + ID_RE + r"$")

KINDS = ("normative", "derived", "informative")
SOURCE_EXTS = (".hpp", ".cpp", ".h", ".cc", ".hh", ".py", ".cmake", ".smt2")
SKIP_DIRS = {".git", "__pycache__", "node_modules"}

# Evidence categories, in matrix column order.
CATEGORIES = ("implementation", "example", "property", "proof", "oracle")


class Rule:
    def __init__(self, rule_id, title, path, line):
        self.id = rule_id
        self.title = title
        self.path = path
        self.line = line
        self.keys = {}
        self.evidence = {c: [] for c in CATEGORIES}

    @property
    def kind(self):
        return self.keys.get("kind", "")

    def id_list(self, key):
        value = self.keys.get(key, "")
        return [t.strip() for t in value.split(",") if t.strip()]


class Report:
    def __init__(self):
        self.errors = []
        self.warnings = []

    def error(self, where, message):
        self.errors.append(f"{where}: {message}" if where else message)

    def warn(self, where, message):
        self.warnings.append(f"{where}: {message}" if where else message)


def rel(root, path):
    return os.path.relpath(path, root).replace(os.sep, "/")


def walk_files(base, exts):
    """Yields files under base with one of the extensions, in a stable order."""
    for dirpath, dirnames, filenames in os.walk(base):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("build"))
        for name in sorted(filenames):
            if name.endswith(exts):
                yield os.path.join(dirpath, name)


def read_lines(path, report, root):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read().splitlines()
    except (OSError, UnicodeDecodeError) as e:
        report.error(rel(root, path), f"cannot read: {e}")
        return []


def parse_spec(root, report):
    """Returns {id: Rule} from spec/**/*.md; records duplicates and malformed headings."""
    rules = {}
    spec_dir = os.path.join(root, "spec")
    for path in walk_files(spec_dir, (".md",)):
        where_file = rel(root, path)
        current = None
        in_fence = False
        for number, text in enumerate(read_lines(path, report, root), start=1):
            if text.startswith("```"):
                in_fence = not in_fence
                continue
            if in_fence:
                continue
            m = HEADING_RE.match(text)
            if m:
                rule_id, title = m.group(1), m.group(2).strip()
                if rule_id in rules:
                    first = rules[rule_id]
                    report.error(f"{where_file}:{number}",
                                 f"duplicate rule ID {rule_id} (first defined at {first.path}:{first.line})")
                    current = None
                    continue
                current = Rule(rule_id, title, where_file, number)
                rules[rule_id] = current
                continue
            if ID_LIKE_HEADING_RE.match(text):
                report.error(f"{where_file}:{number}",
                             f"malformed rule heading (expected '### AREA.TOPIC.NAME — Title'): {text.strip()}")
                current = None
                continue
            if SECTION_END_RE.match(text):
                current = None
                continue
            if current is not None:
                k = KEY_RE.match(text)
                if k:
                    key, value = k.group(1), k.group(2).strip()
                    if key in current.keys:
                        report.error(f"{where_file}:{number}", f"{current.id}: key '{key}' given twice")
                    current.keys[key] = value
    return rules


def check_registry(rules, report):
    for rule in rules.values():
        where = f"{rule.path}:{rule.line}"
        if "kind" not in rule.keys:
            report.error(where, f"{rule.id}: no '- kind:' line (one of {', '.join(KINDS)})")
        elif rule.kind not in KINDS:
            report.error(where, f"{rule.id}: unknown kind '{rule.kind}' (one of {', '.join(KINDS)})")
        for key in ("depends", "superseded-by"):
            for dep in rule.id_list(key):
                if not FULL_ID_RE.match(dep):
                    report.error(where, f"{rule.id}: malformed ID '{dep}' in '{key}'")
                elif dep not in rules:
                    report.error(where, f"{rule.id}: {key} on unknown rule ID {dep}")
                elif dep == rule.id:
                    report.error(where, f"{rule.id}: {key} on itself")


def category_of(relpath):
    """Returns the evidence category of a source file, or None if it is not scanned."""
    parts = relpath.split("/")
    top = parts[0]
    if top in ("kernel", "bench"):
        return "implementation"
    if top == "tools":
        return None if len(parts) > 1 and parts[1] == "trace" else "implementation"
    if top == "proofs":
        return "proof"
    if top == "properties":
        return "property"
    if top == "oracle":
        return "oracle"
    if top == "tests":
        return "example"
    return None


def scan_tags(root, rules, report):
    """Attaches every tag to its rules; records unknown IDs and malformed tags."""
    tags = 0
    for top in ("kernel", "bench", "tools", "proofs", "properties", "oracle", "tests"):
        base = os.path.join(root, top)
        if not os.path.isdir(base):
            continue
        for path in walk_files(base, SOURCE_EXTS):
            relpath = rel(root, path)
            category = category_of(relpath)
            if category is None:
                continue
            for number, text in enumerate(read_lines(path, report, root), start=1):
                m = TAG_RE.match(text)
                if not m:
                    continue
                tags += 1
                where = f"{relpath}:{number}"
                ids = [t.strip() for t in m.group(1).split(",")]
                if not any(ids):
                    report.error(where, "empty rule tag")
                    continue
                for rule_id in ids:
                    if not FULL_ID_RE.match(rule_id):
                        report.error(where, f"malformed rule tag (expected 'rule: ID[, ID ...]'): "
                                            f"'{rule_id}' in: {text.strip()}")
                    elif rule_id not in rules:
                        report.error(where, f"unknown rule ID {rule_id} cited")
                    else:
                        rules[rule_id].evidence[category].append((relpath, number))
    return tags


# Runtime code: what users see printed (error messages, explanations, reports). A rule ID in a
# string literal there must name a rule of the registry (or, followed by ".*", a family of
# them), so that renaming a rule cannot leave a stale ID in what the tool prints.
RUNTIME_TOPS = ("kernel", "check", "tools", "bench", "fuzz")
STRING_RE = re.compile(r'"(?:[^"\\\n]|\\.)*"')
LITERAL_ID_RE = re.compile(r"\b(" + ID_RE + r")\b")


def scan_runtime_strings(root, rules, report):
    """Reports rule IDs in runtime string literals that the registry does not define."""
    areas = {rule_id.split(".")[0] for rule_id in rules}
    families = {".".join(rule_id.split(".")[:n]) for rule_id in rules
                for n in range(1, rule_id.count(".") + 1)}
    found = 0
    for top in RUNTIME_TOPS:
        base = os.path.join(root, top)
        if not os.path.isdir(base):
            continue
        for path in walk_files(base, (".hpp", ".cpp", ".h", ".cc", ".hh")):
            relpath = rel(root, path)
            if category_of(relpath) is None or relpath == RULE_TABLE:
                continue  # the rule-ID table has its own, stricter check
            for number, text in enumerate(read_lines(path, report, root), start=1):
                if TAG_RE.match(text):
                    continue
                for literal in STRING_RE.findall(text):
                    for m in LITERAL_ID_RE.finditer(literal):
                        token = m.group(1)
                        if token.split(".")[0] not in areas:
                            continue  # "D3D11.3", "VK_..." and the like
                        found += 1
                        family = literal[m.end():m.end() + 2] == ".*"
                        if token in rules or (family and token in families):
                            continue
                        report.error(f"{relpath}:{number}",
                                     f"unknown rule ID {token} printed at run time (a string "
                                     f"literal; the registry has no such rule)")
    return found


# The rule-ID table: the constants the kernel's decision records carry and the tools print.
# Every entry must name a rule of the registry whatever its area (the string scan above skips
# tokens of areas the registry does not know, such as "D3D11.3"; the table admits none), each
# ID and each name once. A line that declares a RuleId constant in another form is an error,
# so that no entry escapes the check.
RULE_TABLE = "kernel/include/rastrules/rules.hpp"
TABLE_ENTRY_RE = re.compile(r'^\s*inline\s+constexpr\s+RuleId\s+(k[A-Za-z0-9_]*)\s*'
                            r'\{\s*"([^"\\]*)"\s*\}\s*;\s*(?://.*)?$')
TABLE_LIKE_RE = re.compile(r"\bconstexpr\s+RuleId\b")


def check_rule_table(root, rules, report):
    """Checks the rule-ID table; returns the number of entries (0 when there is no table)."""
    path = os.path.join(root, *RULE_TABLE.split("/"))
    if not os.path.isfile(path):
        return 0
    names, ids = {}, {}
    for number, text in enumerate(read_lines(path, report, root), start=1):
        where = f"{RULE_TABLE}:{number}"
        m = TABLE_ENTRY_RE.match(text)
        if not m:
            if TABLE_LIKE_RE.search(text) and not text.lstrip().startswith("//"):
                report.error(where, "malformed rule table entry (expected "
                                    "'inline constexpr RuleId kName{\"ID\"};' on one line): "
                                    f"{text.strip()}")
            continue
        name, rule_id = m.groups()
        if name in names:
            report.error(where, f"rule table name {name} already declared at line {names[name]}")
        if rule_id in ids:
            report.error(where, f"rule table ID {rule_id} already named {ids[rule_id][0]} at "
                                f"line {ids[rule_id][1]}")
        if not FULL_ID_RE.match(rule_id) or rule_id not in rules:
            report.error(where, f"rule table entry {name} names {rule_id}, which spec/ does not "
                                f"define")
        names.setdefault(name, number)
        ids.setdefault(rule_id, (name, number))
    return len(names)


# Rule areas whose normative and derived rules must have a property or a proof.
STRICT_AREAS = ("TRI.", "SNAP.", "FIX.", "RASTER.", "POINT.", "LINE.", "MSAA.", "FAST.")


def check_evidence(rules, report):
    for rule in rules.values():
        where = f"{rule.path}:{rule.line}"
        ev = rule.evidence
        if rule.kind == "normative":
            if not ev["implementation"]:
                report.error(where, f"normative rule {rule.id} has no implementation site "
                                    f"(a 'rule: {rule.id}' tag under kernel/ or tools/)")
            if not ev["example"]:
                report.error(where, f"normative rule {rule.id} has no example test "
                                    f"(a 'rule: {rule.id}' tag under tests/)")
        if rule.kind in ("normative", "derived") and not ev["property"] and not ev["proof"]:
            message = f"{rule.kind} rule {rule.id} has neither a property nor a proof"
            if rule.id.startswith(STRICT_AREAS):
                report.error(where, message)
            else:
                report.warn(where, message)


def link(path, line, matrix_dir, root):
    target = os.path.relpath(os.path.join(root, path), matrix_dir).replace(os.sep, "/")
    return f"[{path}:{line}]({target}#L{line})"


def write_matrix(rules, matrix_path, root, report):
    matrix_dir = os.path.dirname(os.path.abspath(matrix_path))
    os.makedirs(matrix_dir, exist_ok=True)
    out = ["# Rule traceability matrix", "",
           "Generated by tools/trace/trace.py from spec/ and the `rule:` tags in the sources; do not edit.",
           "",
           f"{len(rules)} rules, {len(report.errors)} errors, {len(report.warnings)} warnings.", "",
           "| rule | kind | " + " | ".join(CATEGORIES) + " |",
           "| --- | --- | " + " | ".join("---" for _ in CATEGORIES) + " |"]
    for rule in sorted(rules.values(), key=lambda r: r.id):
        cells = [f"[{rule.id}]({os.path.relpath(os.path.join(root, rule.path), matrix_dir).replace(os.sep, '/')}#L{rule.line})"
                 f" — {rule.title}", rule.kind or "?"]
        for c in CATEGORIES:
            sites = rule.evidence[c]
            cells.append("<br>".join(link(p, n, matrix_dir, root) for p, n in sites) if sites else "—")
        out.append("| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |")
    if report.errors or report.warnings:
        out += ["", "## Problems", ""]
        out += [f"- error: {e}" for e in report.errors]
        out += [f"- warning: {w}" for w in report.warnings]
    with open(matrix_path, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")


def main(argv=None):
    parser = argparse.ArgumentParser(description="Check rule traceability and write the matrix.")
    parser.add_argument("--root", required=True, help="source tree (with spec/)")
    parser.add_argument("--matrix", help="where to write the Markdown matrix")
    args = parser.parse_args(argv)

    root = os.path.abspath(args.root)
    if not os.path.isdir(os.path.join(root, "spec")):
        print(f"trace: error: no spec/ folder under {root}", file=sys.stderr)
        return 2

    report = Report()
    rules = parse_spec(root, report)
    if not rules:
        report.error("spec/", "no rules found")
    check_registry(rules, report)
    tags = scan_tags(root, rules, report)
    printed = scan_runtime_strings(root, rules, report)
    table = check_rule_table(root, rules, report)
    check_evidence(rules, report)
    if args.matrix:
        write_matrix(rules, args.matrix, root, report)

    for e in report.errors:
        print(f"trace: error: {e}")
    for w in report.warnings:
        print(f"trace: warning: {w}")
    print(f"trace: {len(rules)} rules, {len(report.errors)} errors, {len(report.warnings)} warnings"
          f" ({tags} tags, {printed} rule IDs printed at run time, {table} in the rule table"
          + (f"; matrix: {args.matrix})" if args.matrix else ")"))
    return 1 if report.errors else 0


if __name__ == "__main__":
    sys.exit(main())
