#!/usr/bin/env python3
"""The translation speaks with one voice: checks a .po file against the book's glossary and its rules.

    python3 book/po/check-terms.py [book/po/zh-CN.po]

Fails (exit 1), one line per problem, naming the message by its first English words, when
- a term of the glossary (book/src/glossary.md: every table with an "English" and a "中文" column)
  appears in a message and its translation lacks the glossary's Chinese for it;
- a Chinese alt text (`![…](…)`) or figure caption puts an ASCII colon next to Chinese text, where
  Chinese punctuation (：) is due;
- a Chinese caption is emphasised `_…_`, which does not work next to Chinese characters (`*…*` does).

The English term is the first column without its `<span>` and without a parenthesis ("pose (of the
camera)" is "pose"); it matches as a word, in any case, with a plural or verb ending ("poses",
"clamped"), and a space in it also matches a hyphen ("back-face culling"). The Chinese is the second
column without its full-width parenthesis ("深度冲突（z-fighting）" asks for 深度冲突). Code spans,
math, link targets and HTML tags of the English do not count. Python 3, no dependencies.
"""
import re
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
GLOSSARY = HERE.parent / "src" / "glossary.md"

# Legitimate exceptions: (term, a regular expression the English message matches, why).
ALLOWED = [
    # "strip" is the glossary's strip of a frame's steps; lesson 7 also speaks of a thin strip of
    # the mirror above the water (and of bricks around it): that one is a 窄条.
    ("strip", r"lowest strip|strip above the water|strip of bricks", "a thin band of the picture"),
    # depth-test is also lesson 1's name, which cost.md times as a program: a name stays a name.
    ("depth test", r"depth-test(?: \d|,)", "the lesson depth-test"),
]

CJK = "\u3400-\u4dbf\u4e00-\u9fff"


def unquote(s):
    """The value of a PO string literal's body."""
    return re.sub(r'\\(.)', lambda m: {"n": "\n", "t": "\t"}.get(m.group(1), m.group(1)), s)


def messages(po_text):
    """(msgid, msgstr) of every live, translated, non-fuzzy message."""
    for block in po_text.split("\n\n"):
        lines = block.strip().split("\n")
        if any(l.startswith("#~") for l in lines) or any(l.startswith("#,") and "fuzzy" in l for l in lines):
            continue
        fields, current = {}, None
        for line in lines:
            m = re.match(r'^(msgid|msgstr|msgctxt|msgid_plural) "(.*)"$', line)
            if m:
                current = m.group(1)
                fields[current] = unquote(m.group(2))
            elif line.startswith('"') and current:
                fields[current] += unquote(line[1:-1])
        if fields.get("msgid") and fields.get("msgstr"):
            yield fields["msgid"], fields["msgstr"]


def split_row(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def glossary_terms(path=GLOSSARY):
    """[(english term, chinese term)] from every English/中文 table of the glossary."""
    terms, columns = [], None
    for line in path.read_text(encoding="utf-8").splitlines():
        if not line.startswith("|"):
            columns = None
            continue
        cells = split_row(line)
        if columns is None:
            columns = (cells.index("English"), cells.index("中文")) if "English" in cells and "中文" in cells else ()
            continue
        if not columns or set(line) <= set("|-: "):
            continue
        english = re.sub(r"<[^>]*>", "", cells[columns[0]])
        english = re.sub(r"\s*\([^)]*\)", "", english).strip()
        chinese = re.sub(r"（[^）]*）", "", cells[columns[1]]).strip()
        if english and chinese and english != chinese:
            terms.append((english, chinese))
    return terms


def term_pattern(english):
    """The term as a word: any case, a hyphen for a space, and the endings English gives it."""
    words = [re.escape(w) for w in re.split(r"[\s-]+", english)]
    last = english.lower()
    endings = ["s", "ing", "d" if last.endswith("e") else "ed"]
    if re.search(r"(?:s|x|z|ch|sh)$", last):
        endings.append("es")
    ending = "(?:" + "|".join(endings) + ")?"
    return re.compile(r"(?<![\w-])" + r"[\s-]+".join(words) + ending + r"(?![\w-])", re.IGNORECASE)


def prose(markdown):
    """The English a reader reads: no code spans, math, link targets, HTML tags or includes."""
    s = re.sub(r"\{\{#[^}]*\}\}", " ", markdown)
    s = re.sub(r"(`+).*?\1", " ", s)
    s = re.sub(r"\$\$.*?\$\$|\$[^$]*\$", " ", s)
    s = re.sub(r"\]\([^)]*\)", "]", s)
    s = re.sub(r"[\w-]+=[\w.,-]+", " ", s)  # a knob's setting (read-mask=0x01) is the program's word
    return re.sub(r"<[^>]*>", " ", s)


def first_words(msgid, n=8):
    words = msgid.split()
    return " ".join(words[:n]) + (" …" if len(words) > n else "")


def is_caption(msgid):
    return re.match(r"^[*_]Figure\b", msgid) is not None or re.match(r"^[*_][^*_].*[*_]$", msgid) is not None


def chinese_texts(msgid, msgstr):
    """The alt texts and captions of a translation: where Chinese punctuation is due."""
    texts = re.findall(r"!\[((?:[^\]\\]|\\.)*)\]\(", msgstr)
    if is_caption(msgid):
        texts.append(msgstr)
    return texts


def check(po_path):
    terms = [(e, c, term_pattern(e)) for e, c in glossary_terms()]
    allowed = [(t, re.compile(r, re.IGNORECASE)) for t, r, _ in ALLOWED]
    problems = []
    for msgid, msgstr in messages(Path(po_path).read_text(encoding="utf-8")):
        if msgstr == msgid:
            continue  # kept as it is: code, a name, the glossary's English column
        where = f'"{first_words(msgid)}"'
        english = prose(msgid)
        for term, chinese, pattern in terms:
            if pattern.search(english) and chinese not in msgstr:
                if any(t == term and r.search(english) for t, r in allowed):
                    continue
                problems.append(f"{where}: '{term}' is not translated {chinese} (glossary)")
        for text in chinese_texts(msgid, msgstr):
            bare = re.sub(r"(`+).*?\1|\$[^$]*\$", "`", text)
            if re.search(f"[{CJK}]", bare) and re.search(f"[{CJK}]\\s*:|:\\s*[{CJK}]", bare):
                problems.append(f"{where}: ASCII ':' in Chinese alt text or caption, write '：'")
        if is_caption(msgid) and re.match(r"^_.*_$", msgstr, re.S):
            problems.append(f"{where}: caption emphasised _…_, write *…* (po/README.md)")
    return problems


def main():
    po_path = sys.argv[1] if len(sys.argv) > 1 else HERE / "zh-CN.po"
    problems = check(po_path)
    for p in problems:
        print(f"check-terms: {Path(po_path).name}: {p}", file=sys.stderr)
    if problems:
        print(f"check-terms: {len(problems)} problems in {Path(po_path).name}: see book/po/README.md and book/src/glossary.md", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
