#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Checks the HTML pages the command line writes (spec/driver.md FUZZ.REPORT.HTML).

  check_html.py --cli PATH --work DIR            well-formed pages, every link resolves
  check_html.py --cli PATH --work DIR --browser  the same pages loaded in headless Chromium

Writes a fuzz campaign (the imprecise driver: findings), a check of one of its findings, a
campaign without findings and the showcase into DIR, then checks each DIR/*/index.html:
balanced elements, unique ids, every src and href a relative path to a file that exists (or an
#id of the page), no external script, style sheet or frame, no http(s) URL. With --browser it
loads the campaign's and the showcase's pages in Chromium (--headless=new --dump-dom) and reads what the page's self-check
script wrote into <body>: every image loaded and no script error; a copy of a page with one
picture removed must be reported broken, so that the check is seen to fail. Exits 77 (CTest's
SKIP_RETURN_CODE) when --browser is given and Chromium is not installed.
"""
# rule: FUZZ.REPORT.HTML
import argparse
import html.parser
import os
import re
import shutil
import subprocess
import sys

VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
        "track", "wbr"}
FORBIDDEN = {"link", "iframe", "object", "embed", "base", "frame"}


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.stack, self.errors, self.ids, self.refs, self.images = [], [], [], [], 0
        self.doctype = False

    def handle_decl(self, decl):
        self.doctype = self.doctype or decl.lower() == "doctype html"

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag in FORBIDDEN:
            self.errors.append(f"<{tag}> is not allowed (the page must be self-contained)")
        if tag == "script" and "src" in a:
            self.errors.append("external script " + str(a["src"]))
        if tag == "img":
            self.images += 1
        if "id" in a:
            self.ids.append(a["id"])
        for k in ("src", "href"):
            if k in a:
                self.refs.append(a[k] or "")
        if tag not in VOID:
            self.stack.append((tag, self.getpos()))

    def handle_startendtag(self, tag, attrs):
        self.handle_starttag(tag, attrs)
        if tag not in VOID:
            self.stack.pop()

    def handle_endtag(self, tag):
        if tag in VOID:
            self.errors.append(f"end tag </{tag}> of a void element")
            return
        if not self.stack or self.stack[-1][0] != tag:
            top = self.stack[-1] if self.stack else ("nothing", (0, 0))
            self.errors.append(f"</{tag}> at line {self.getpos()[0]} closes <{top[0]}> "
                               f"of line {top[1][0]}")
            return
        self.stack.pop()


def check_page(path):
    """Returns the problems of one page (empty: well formed, every link resolves)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    p = Page()
    p.feed(text)
    p.close()
    errors = list(p.errors)
    if not p.doctype:
        errors.append("no <!DOCTYPE html>")
    errors += [f"<{t}> of line {pos[0]} is never closed" for t, pos in p.stack]
    dup = {i for i in p.ids if p.ids.count(i) > 1}
    if dup:
        errors.append("ids used twice: " + ", ".join(sorted(dup)))
    if re.search(r"(?i)\b(https?:|ftp:)|url\(", text):
        errors.append("a network URL or a CSS url(): the page must not fetch anything")
    base = os.path.dirname(path)
    for ref in p.refs:
        if ref.startswith("#"):
            if ref[1:] not in p.ids:
                errors.append(f"link {ref} names no element of the page")
        elif ref == "" or "://" in ref or ref.startswith("/") or ref.startswith("//"):
            errors.append(f"link {ref!r} is not a relative path")
        elif not os.path.isfile(os.path.join(base, ref)):
            errors.append(f"link {ref!r}: no such file")
    return errors, p.images


def run(cli, args, expect):
    r = subprocess.run([cli] + args, capture_output=True, text=True, timeout=120)
    if r.returncode not in expect:
        sys.exit(f"FAIL: rastrules {' '.join(args)} exited {r.returncode}:\n{r.stderr}")


def make_pages(cli, work):
    if os.path.isdir(work):
        shutil.rmtree(work)
    os.makedirs(work)
    fuzz = os.path.join(work, "fuzz")
    run(cli, ["fuzz", "--driver", "imprecise", "--cases", "40", "--seed", "7", "--out", fuzz,
              "--no-progress"], {1})
    first = sorted(f for f in os.listdir(fuzz) if f.endswith(".min.json"))[0]
    run(cli, ["check", os.path.join(fuzz, first), "--driver", "imprecise", "--out",
              os.path.join(work, "check")], {1})
    run(cli, ["fuzz", "--driver", "reference", "--cases", "5", "--out",
              os.path.join(work, "clean"), "--no-progress"], {0})
    run(cli, ["showcase", "--out", os.path.join(work, "showcase")], {0})
    return [os.path.join(work, d, "index.html") for d in ("fuzz", "check", "clean", "showcase")]


def body_attrs(dom):
    m = re.search(r"<body([^>]*)>", dom)
    if not m:
        return None
    return dict(re.findall(r'([a-z-]+)="([^"]*)"', m.group(1)))


def load_in_browser(browser, pages, work):
    """Loads the pages in Chromium, one process each, all at once (a browser's start-up is
    most of the time); returns per page <body>'s attributes (None: no <body>)."""
    procs = []
    for k, page in enumerate(pages):
        profile = os.path.join(work, f"chromium-profile-{k}")
        cmd = [browser, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
               "--disable-extensions", "--disable-background-networking", "--disable-sync",
               "--user-data-dir=" + profile, "--virtual-time-budget=1000", "--dump-dom",
               "file://" + os.path.abspath(page)]
        procs.append(subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                      text=True))
    out = []
    for page, proc in zip(pages, procs):
        try:
            dom, err = proc.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            proc.kill()
            sys.exit(f"FAIL: {browser} did not finish loading {page} within 60 s")
        if proc.returncode != 0:
            sys.exit(f"FAIL: {browser} exited {proc.returncode} on {page}:\n{err[-2000:]}")
        out.append(body_attrs(dom))
    return out


def browser_problems(attrs, images):
    if attrs is None:
        return ["the dumped DOM has no <body>"]
    if "data-images" not in attrs:
        return ["the self-check script did not run (no data-images on <body>)"]
    out = []
    if "data-script-error" in attrs:
        out.append("script error: " + attrs["data-script-error"])
    if attrs["data-images"] != str(images):
        out.append(f"the browser saw {attrs['data-images']} images, the page has {images}")
    if attrs.get("data-images-broken") != "0":
        out.append(f"{attrs.get('data-images-broken')} image(s) did not load")
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cli", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--browser", action="store_true")
    a = ap.parse_args()
    browser = None
    if a.browser:
        browser = shutil.which("chromium") or shutil.which("chromium-browser")
        if browser is None:
            print("SKIP: Chromium is not installed (Debian package chromium; scripts/deps "
                  "installs it): the pages were not loaded in a browser")
            return 77
    pages = make_pages(a.cli, a.work)
    failed = False
    images = {}
    for page in pages:
        errors, images[page] = check_page(page)
        for e in errors:
            print(f"FAIL: {page}: {e}")
        failed = failed or bool(errors)
        if not errors:
            print(f"ok: {page}: well formed, {images[page]} images, every link resolves")
    if browser and not failed:
        # The check must be able to fail: a copy of the campaign's page with a picture gone.
        broken_dir = os.path.join(a.work, "broken")
        shutil.copytree(os.path.dirname(pages[0]), broken_dir)
        os.remove(os.path.join(broken_dir, sorted(f for f in os.listdir(broken_dir)
                                                  if f.endswith(".png"))[0]))
        broken = os.path.join(broken_dir, "index.html")
        # The campaign's and the showcase's pages (the check and clean pages are made by the
        # same code as the campaign's): three browsers keep the test to seconds.
        shown = [pages[0], pages[-1]]
        attrs = load_in_browser(browser, shown + [broken], a.work)
        for page, got in zip(shown, attrs):
            problems = browser_problems(got, images[page])
            for e in problems:
                print(f"FAIL: {page} in {browser}: {e}")
            failed = failed or bool(problems)
            if not problems:
                print(f"ok: {page}: {images[page]} images loaded in {browser}, no script error")
        if attrs[-1] is None or attrs[-1].get("data-images-broken") != "1":
            print(f"FAIL: a missing picture was not reported broken: {attrs[-1]}")
            failed = True
        else:
            print("ok: a page with a missing picture is reported broken")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
