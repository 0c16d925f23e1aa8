#!/usr/bin/env python3
"""The round trip: the English book against a build through gettext with every message empty.

usage: round_trip.py ENGLISH_HTML_DIR ROUND_TRIP_HTML_DIR

mdbook-gettext re-renders every page's Markdown even where nothing is translated, so this is what
shows that its re-rendering loses nothing: the two builds must hold the same pages, and each page
the same HTML once whitespace outside <pre> is normalised (gettext joins a paragraph's lines with
spaces, which HTML renders alike), the `lang` attribute and the search index's hashed name aside.
Every KaTeX formula is compared on its own too, to name the first that differs. Exits 1 on any
difference, naming it.
"""
import os
import re
import sys

PRE = re.compile(r"(<pre\b.*?</pre>)", re.S)
FORMULA_START = re.compile(r'<span class="katex-display">|<span class="katex">')
SPAN = re.compile(r"<span\b|</span>")


def formulas(text):
    """The HTML of each top-level KaTeX formula (display or inline), in order."""
    found, at = [], 0
    while (start := FORMULA_START.search(text, at)) is not None:
        depth, end = 0, len(text)
        for tag in SPAN.finditer(text, start.start()):
            depth += -1 if tag.group() == "</span>" else 1
            if depth == 0:
                end = tag.end()
                break
        found.append(text[start.start():end])
        at = end
    return found


def normalised(text):
    text = re.sub(r'<html lang="[^"]*"', '<html lang="X"', text)
    text = re.sub(r"searchindex-[0-9a-f]+\.js", "searchindex.js", text)
    parts = PRE.split(text)
    return "".join(p if p.startswith("<pre") else re.sub(r"\s+", " ", p) for p in parts)


def pages(root):
    return sorted(
        os.path.relpath(os.path.join(folder, name), root)
        for folder, _, names in os.walk(root)
        for name in names
        if name.endswith(".html") and not os.path.relpath(folder, root).startswith(("zh-CN", "live"))
    )


def main():
    english, other = sys.argv[1], sys.argv[2]
    problems, counted = [], 0
    theirs = set(pages(other))
    for page in pages(english):
        if page not in theirs:
            problems.append(f"{page}: missing from the round trip")
            continue
        a = open(os.path.join(english, page), encoding="utf-8").read()
        b = open(os.path.join(other, page), encoding="utf-8").read()
        fa, fb = formulas(a), formulas(b)
        counted += len(fa)
        for i, (x, y) in enumerate(zip(fa, fb)):
            if x != y:
                problems.append(f"{page}: formula {i + 1} differs: {x[:200]!r}\n    became {y[:200]!r}")
                break
        if len(fa) != len(fb):
            problems.append(f"{page}: {len(fa)} formulas in English, {len(fb)} after the round trip")
        na, nb = normalised(a), normalised(b)
        if na != nb:
            at = next(i for i, (x, y) in enumerate(zip(na, nb)) if x != y) if any(
                x != y for x, y in zip(na, nb)) else min(len(na), len(nb))
            problems.append(f"{page}: differs at {na[max(0, at - 80):at + 80]!r}\n    became {nb[max(0, at - 80):at + 80]!r}")
    for problem in problems:
        print(f"round trip: {problem}", file=sys.stderr)
    if problems:
        print(f"round trip: {len(problems)} differences: the translation toolchain changes the English (po/TOOLCHAIN.md)", file=sys.stderr)
        sys.exit(1)
    print(f"round trip: {len(pages(english))} pages and {counted} formulas came back unchanged through gettext")


if __name__ == "__main__":
    main()
