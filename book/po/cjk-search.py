#!/usr/bin/env python3
"""Makes a Chinese (or Japanese, Korean) book's search find its own words.

Usage: cjk-search.py HTML_DIR

mdBook's search index (HTML_DIR/searchindex-HASH.js, elasticlunr's serialized index) is made of the
words between spaces, and Chinese writes none: a sentence is one word, which mdBook drops when it is
longer than 80 bytes, and which elasticlunr's trimmer (it keeps [A-Za-z0-9_] at a word's ends) would
empty anyway. So 模板缓冲区 finds nothing. This rewrites the index, in the same file and format, from
the sections' text that the index keeps (its document store):

- a run of CJK characters is indexed as its characters and its overlapping pairs (模板缓冲区: 模, 板,
  缓, 冲, 区, 模板, 板缓, 缓冲, 冲区); the page (web/search.js) splits a query's runs into the same pairs
  (a single character stays one), so 模板缓冲区 finds the sections that hold those four pairs, best
  those that hold them all;
- the rest of a word that holds CJK characters (`StencilFaceState`的, “stencil，depth”) is cut at them
  and at CJK punctuation, and each piece is a word as mdBook indexes words;
- a word without CJK characters is indexed exactly as mdBook does: its tokenizer (split at
  whitespace and `-`, lowercase, at most 80 bytes) and elasticlunr's English pipeline (trimmer, stop
  words, Porter stemmer), as elasticlunr-rs 3.0.2 runs them for mdBook 0.5.3, which this ports.

Term frequencies (the square root of a count), document frequencies and field lengths are
recomputed for every word, the way elasticlunr-rs computes them (including its habit of counting a
section's title words again in its body and its breadcrumbs fields), so elasticlunr.js scores the
new words as it scores the old. Before it writes, the script rebuilds the index without the CJK
rule and checks that it is the index mdBook wrote, word for word and number for number: if mdBook
ever indexes otherwise, the build says so rather than mix two ways of indexing. A second run on an
index this script wrote leaves it as it is.
"""

import glob
import json
import math
import os
import re
import sys

# Characters that are words by themselves (no spaces between them): kana, CJK ideographs (the
# unified block, extension A and the compatibility ideographs) and Hangul syllables. The Basic
# Multilingual Plane only: elasticlunr.js walks its index by UTF-16 code unit.
CJK = "\u3040-\u30ff\u3400-\u4dbf\u4e00-\u9fff\uf900-\ufaff\uac00-\ud7af"
# Punctuation that parts words inside a word that has CJK characters: general punctuation (dashes,
# quotes, the ellipsis), CJK symbols and punctuation, the vertical and the full-width forms.
SEPARATORS = "\u2010-\u2027\u2030-\u205e\u3000-\u303f\ufe10-\ufe1f\ufe30-\ufe4f\uff00-\uffef"
HAS_CJK = re.compile(f"[{CJK}]")
PIECES = re.compile(f"([{CJK}]+)|[{SEPARATORS}]+")

# mdBook's tokenizer (mdbook-html 0.5.3, search.rs): split at Rust's char::is_whitespace (Unicode's
# White_Space) and at `-`, lowercase, and words of more than 80 bytes dropped.
WHITESPACE = "\t\n\x0b\x0c\r \x85\xa0\u1680\u2000-\u200a\u2028\u2029\u202f\u205f\u3000"
SPLIT = re.compile(f"[{WHITESPACE}-]")
MAX_WORD_LENGTH_TO_INDEX = 80

PREFIX = "window.search = Object.assign(window.search, JSON.parse('"
SUFFIX = "'));"

# elasticlunr-rs's English stop words (lang/en.rs), the same as elasticlunr.js's.
STOP_WORDS = set(
    """a able about across after all almost also am among an and any are as at be because been
    but by can cannot could dear did do does either else ever every for from get got had has have
    he her hers him his how however i if in into is it its just least let like likely may me might
    most must my neither no nor not of off often on only or other our own rather said say says she
    should since so some than that the their them then there these they this tis to too twas us
    wants was we were what when where which while who whom why will with would yet you your""".split()
) | {""}


def trimmer(token):
    """elasticlunr-rs's trimmer: off both ends, all but ASCII letters, digits and `_`."""
    start, end = 0, len(token)
    keep = lambda c: c == "_" or ("0" <= c <= "9") or ("a" <= c <= "z") or ("A" <= c <= "Z")
    while start < end and not keep(token[start]):
        start += 1
    while end > start and not keep(token[end - 1]):
        end -= 1
    return token[start:end]


class Stemmer:
    """elasticlunr-rs's Porter stemmer (lang/en.rs), itself a port of elasticlunr.js's."""

    V = "[aeiouy]"
    CS = "[^aeiou][^aeiouy]*"
    VS = "[aeiouy][aeiou]*"
    STEP_2 = dict(
        ational="ate", tional="tion", enci="ence", anci="ance", izer="ize", bli="ble", alli="al",
        entli="ent", eli="e", ousli="ous", ization="ize", ation="ate", ator="ate", alism="al",
        iveness="ive", fulness="ful", ousness="ous", aliti="al", iviti="ive", biliti="ble",
        logi="log",
    )
    STEP_3 = dict(icate="ic", ative="", alize="al", iciti="ic", ical="ic", ful="", ness="")

    def __init__(self):
        c = re.compile
        cs, vs, v = self.CS, self.VS, self.V
        self.mgr0 = c(f"^({cs})?{vs}{cs}")
        self.meq1 = c(f"^({cs})?{vs}{cs}({vs})?$")
        self.mgr1 = c(f"^({cs})?{vs}{cs}{vs}{cs}")
        self.s_v = c(f"^({cs})?{v}")
        self.re_1a = c(r"^(.+?)(ss|i)es$")
        self.re2_1a = c(r"^(.+?)([^s])s$")
        self.re_1b = c(r"^(.+?)eed$")
        self.re2_1b = c(r"^(.+?)(ed|ing)$")
        self.re2_1b_2 = c(r"(at|bl|iz)$")
        self.re3_1b_2 = c(r"([^aeiouylsz]{2})$")
        self.re4_1b_2 = c(f"^{cs}{v}[^aeiouwxy]$")
        self.re_1c = c(r"^(.+?[^aeiou])y$")
        self.re_2 = c(f"^(.+?)({'|'.join(self.STEP_2)})$")
        self.re_3 = c(f"^(.+?)({'|'.join(self.STEP_3)})$")
        self.re_4 = c(
            r"^(.+?)(al|ance|ence|er|ic|able|ible|ant|ement|ment|ent|ou|ism|ate|iti|ous|ive|ize)$"
        )
        self.re2_4 = c(r"^(.+?)(s|t)(ion)$")
        self.re_5 = c(r"^(.+?)e$")
        self.re3_5 = c(f"^{cs}{v}[^aeiouwxy]$")
        self.cache = {}

    def __call__(self, w):
        if w not in self.cache:
            self.cache[w] = self.stem(w)
        return self.cache[w]

    def stem(self, w):
        # Rust's String::len: bytes.
        if len(w.encode()) < 3:
            return w
        starts_with_y = w[0] == "y"
        if starts_with_y:
            w = "Y" + w[1:]
        # Step 1a
        if m := self.re_1a.match(w):
            w = m[1] + m[2]
        if m := self.re2_1a.match(w):
            w = m[1] + m[2]
        # Step 1b
        if m := self.re_1b.match(w):
            if self.mgr0.match(m[1]):
                w = w[:-1]
        elif m := self.re2_1b.match(w):
            stem = m[1]
            if self.s_v.match(stem):
                w = stem
                doubled = False
                if self.re2_1b_2.search(w):
                    w += "e"
                elif (m := self.re3_1b_2.search(w)) and m[1][0] == m[1][1]:
                    doubled = True
                    w = w[:-1]
                if not doubled and self.re4_1b_2.match(w):
                    w += "e"
        # Step 1c
        if m := self.re_1c.match(w):
            w = m[1] + "i"
        # Step 2
        if (m := self.re_2.match(w)) and self.mgr0.match(m[1]):
            w = m[1] + self.STEP_2[m[2]]
        # Step 3
        if (m := self.re_3.match(w)) and self.mgr0.match(m[1]):
            w = m[1] + self.STEP_3[m[2]]
        # Step 4
        if m := self.re_4.match(w):
            if self.mgr1.match(m[1]):
                w = m[1]
        elif m := self.re2_4.match(w):
            if self.mgr1.match(m[1] + m[2]):
                w = m[1] + m[2]
        # Step 5
        if m := self.re_5.match(w):
            stem = m[1]
            if self.mgr1.match(stem) or (self.meq1.match(stem) and not self.re3_5.match(stem)):
                w = stem
        if w.endswith("ll") and self.mgr1.match(w):
            w = w[:-1]
        if starts_with_y:
            w = "y" + w[1:]
        return w


STEM = Stemmer()


def pipeline(word):
    """A word through the index's pipeline (trimmer, stopWordFilter, stemmer), or None."""
    word = trimmer(word)
    if word in STOP_WORDS:
        return None
    return STEM(word)


def latin(word, tokens):
    """A word as mdBook indexes it, onto `tokens`."""
    if len(word.encode()) <= MAX_WORD_LENGTH_TO_INDEX:
        token = pipeline(word)
        if token is not None:
            tokens.append(token)


def tokenize(text, cjk):
    """A field's text as indexed: mdBook's words, with (if `cjk`) their CJK runs in characters and
    pairs of characters."""
    tokens = []
    for word in SPLIT.split(text):
        if not word:
            continue
        word = word.lower()
        if not cjk or not HAS_CJK.search(word):
            latin(word, tokens)
            continue
        for i, piece in enumerate(PIECES.split(word)):
            if not piece:
                continue
            if i % 2:  # a run of CJK characters (PIECES's group)
                tokens.extend(piece)
                tokens.extend(piece[j : j + 2] for j in range(len(piece) - 1))
            else:
                latin(piece, tokens)
    return tokens


def node():
    return {"docs": {}, "df": 0}


def build(fields, docs, cjk):
    """The inverted index of every field and the fields' lengths, as elasticlunr-rs's
    Index::add_doc makes them (its count of a section's words goes on from field to field)."""
    index = {field: {"root": node()} for field in fields}
    doc_info = {}
    for ref, doc in docs.items():
        counts = {}
        info = doc_info[ref] = {}
        for field in fields:
            tokens = tokenize(doc[field], cjk)
            info[field] = len(tokens)
            for token in tokens:
                counts[token] = counts.get(token, 0) + 1
            root = index[field]["root"]
            for token, count in counts.items():
                item = root
                for character in token:
                    item = item.setdefault(character, node())
                if ref not in item["docs"]:
                    item["df"] += 1
                item["docs"][ref] = {"tf": math.sqrt(count)}
    return index, doc_info


def first_difference(a, b, path="index"):
    """Where two JSON values first differ, for the error message."""
    if isinstance(a, dict) and isinstance(b, dict):
        for key in sorted(set(a) | set(b)):
            if key not in a or key not in b:
                return f"{path}/{key}: only in {'mdBook' if key in a else 'the rebuild'}'s"
            if a[key] != b[key]:
                return first_difference(a[key], b[key], f"{path}/{key}")
    return f"{path}: {json.dumps(a, ensure_ascii=False)[:80]} against {json.dumps(b, ensure_ascii=False)[:80]}"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2])
    html = sys.argv[1]
    found = glob.glob(os.path.join(html, "searchindex-*.js"))
    if len(found) != 1:
        sys.exit(f"cjk-search: {len(found)} searchindex-*.js in {html}, not one")
    path = found[0]
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if not (text.startswith(PREFIX) and text.endswith(SUFFIX)):
        sys.exit(f"cjk-search: {path} is not mdBook 0.5's `{PREFIX}...{SUFFIX}`")
    # mdBook escaped `\` and `'` of the JSON for the JavaScript string; nothing else.
    literal = text[len(PREFIX) : -len(SUFFIX)]
    config = json.loads(re.sub(r"\\(.)", r"\1", literal, flags=re.S))
    index = config["index"]
    store = index["documentStore"]
    if not store["save"] or index["pipeline"] != ["trimmer", "stopWordFilter", "stemmer"]:
        sys.exit(f"cjk-search: {path}: no document store, or a pipeline other than English's")
    fields, docs = index["fields"], store["docs"]

    before = len(text.encode())
    plain = build(fields, docs, cjk=False)
    split = build(fields, docs, cjk=True)
    written = (index["index"], store["docInfo"])
    if written == split:
        print(f"cjk-search: {path} already indexes CJK characters and pairs")
        return
    if written != plain:
        if written[0] != plain[0]:
            where = first_difference(written[0], plain[0])
        else:
            where = first_difference(written[1], plain[1], "docInfo")
        sys.exit(
            f"cjk-search: {path}: rebuilt from its documents, the index differs from mdBook's "
            f"(first at {where}): mdBook indexes otherwise than book/po/cjk-search.py thinks"
        )
    index["index"], store["docInfo"] = split
    out = json.dumps(config, ensure_ascii=False, sort_keys=True, separators=(",", ":"))
    out = PREFIX + out.replace("\\", "\\\\").replace("'", "\\'") + SUFFIX
    with open(path, "w", encoding="utf-8") as f:
        f.write(out)
    words = lambda tree: sum(
        (1 if node["df"] else 0) + words({k: v for k, v in node.items() if len(k) == 1})
        for node in tree.values()
    )
    count = lambda built: words({"": built[0]["body"]["root"]})
    print(
        f"cjk-search: {path}: {len(docs)} sections, {count(plain)} words in their "
        f"bodies as mdBook indexes them, {count(split)} with CJK characters and pairs; "
        f"{before // 1024} KB → {len(out.encode()) // 1024} KB"
    )


if __name__ == "__main__":
    main()
