#!/usr/bin/env python3
"""The few words of the book that gettext cannot see, translated: an mdBook preprocessor.

mdbook-gettext translates the Markdown as written; it skips raw HTML blocks, and it runs before
`links`, so it never sees what an include brings in. Two kinds of words live there:

- the labels of the `<details>` blocks: `<summary>Answer</summary>`, `Hint`, `Solution` and
  `Speaker notes · N minutes`;
- the step strips that `cargo screenshots` writes (images/steps/*/strip.html): the table's header
  (Step, Colour, Depth, Stencil) and each picture's alt text ("colour after step 2, draw the room").
  The step names themselves are the program's words and stay as it prints them.

This runs after `links`, in a translated build only. A label it has no translation for fails the
build, naming it, so a new label cannot slip into the Chinese book in English: add it to LABELS.
The English build passes through untouched.
"""
import json
import re
import sys

# Language -> English label -> translation. `{n}` is a number kept from the English.
LABELS = {
    "zh-CN": {
        "summary": {
            "Answer": "答案",
            "Hint": "提示",
            "Solution": "解答",
            "Speaker notes · {n} minutes": "讲稿 · {n} 分钟",
        },
        "strip header": {
            "Step": "步骤",
            "Colour": "颜色",
            "Depth": "深度",
            "Stencil": "模板",
        },
        # "colour after step 2, draw the room"
        "strip alt": {
            "colour": "第 {n} 步“{step}”之后的颜色",
            "depth": "第 {n} 步“{step}”之后的深度",
            "stencil": "第 {n} 步“{step}”之后的模板",
        },
    }
}

SUMMARY = re.compile(r"<summary>([^<]*)</summary>")
STRIP_HEADER = re.compile(r'(<table class="steps">\s*<thead><tr>)(.*?)(</tr></thead>)', re.S)
HEADER_CELL = re.compile(r"<th>([^<]*)</th>")
STRIP_ALT = re.compile(r'alt="(colour|depth|stencil) after step (\d+), ([^"]*)"')


class Missing(Exception):
    pass


def translate(content, table, where):
    def summary(match):
        label = match.group(1)
        number = re.search(r"\d+", label)
        key = re.sub(r"\d+", "{n}", label)
        if key not in table["summary"]:
            raise Missing(f"{where}: no translation for the label <summary>{label}</summary>")
        text = table["summary"][key].replace("{n}", number.group(0) if number else "")
        return f"<summary>{text}</summary>"

    def header(match):
        def cell(m):
            if m.group(1) not in table["strip header"]:
                raise Missing(f"{where}: no translation for the strip's header cell {m.group(1)!r}")
            return f"<th>{table['strip header'][m.group(1)]}</th>"

        return match.group(1) + HEADER_CELL.sub(cell, match.group(2)) + match.group(3)

    def alt(match):
        buffer, number, step = match.groups()
        text = table["strip alt"][buffer].replace("{n}", number).replace("{step}", step)
        return f'alt="{text}"'

    content = SUMMARY.sub(summary, content)
    content = STRIP_HEADER.sub(header, content)
    return STRIP_ALT.sub(alt, content)


def chapters(items):
    for item in items:
        chapter = item.get("Chapter") if isinstance(item, dict) else None
        if chapter:
            yield chapter
            yield from chapters(chapter.get("sub_items", []))


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "supports":
        sys.exit(0)
    context, book = json.load(sys.stdin)
    language = (context.get("config", {}).get("book", {}) or {}).get("language")
    table = LABELS.get(language)
    if table:
        items = book.get("items", book.get("sections", []))
        try:
            for chapter in chapters(items):
                where = chapter.get("source_path") or chapter.get("name")
                chapter["content"] = translate(chapter["content"], table, where)
        except Missing as missing:
            print(f"ERROR labels.py ({language}): {missing}", file=sys.stderr)
            sys.exit(1)
    json.dump(book, sys.stdout)


if __name__ == "__main__":
    main()
