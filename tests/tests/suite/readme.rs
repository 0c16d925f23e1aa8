//! The README and its Simplified Chinese translation, kept in step: `README.zh-CN.md` has the
//! headings of `README.md` (as many of each level, in the same order), its code blocks with the
//! same commands (comments may be translated), its tables with as many rows and columns and the
//! same code spans in each cell (in any order within the cell), the same link targets, the
//! language switcher under the title mirrored, and the glossary's Chinese
//! (`book/src/glossary.md`) wherever the English uses one of its terms.
//!
//! The Markdown is read roughly, by lines (a heading is a line of `#`s, a table a run of lines
//! starting with `|`, a code block what stands between two fences, anything else a paragraph up to
//! a blank line), which is all the READMEs use; the reading's parts are tested on small samples at
//! the end.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

const ENGLISH: &str = "README.md";
const CHINESE: &str = "README.zh-CN.md";

/// Glossary terms that are also everyday English words, not looked for in the README's prose.
const EVERYDAY_WORDS: &[&str] = &["clear"];

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// A Markdown file of the repository, read into blocks.
struct Doc {
    name: &'static str,
    blocks: Vec<Block>,
}

fn doc(name: &'static str) -> Doc {
    let path = repo().join(name);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    Doc {
        name,
        blocks: blocks(&text),
    }
}

/// A line with its number (from 1).
type Line = (usize, String);

/// A table's row with its line's number: its cells.
type Row = (usize, Vec<String>);

/// A block of a Markdown file; `line` is where it starts (from 1).
#[derive(Debug, Clone, PartialEq)]
enum Block {
    Heading {
        line: usize,
        level: usize,
        text: String,
    },
    /// A fenced code block: its info string and its lines, each with its number.
    Code {
        line: usize,
        info: String,
        lines: Vec<Line>,
    },
    /// A table's rows (the header first, without the delimiter row), each with its number.
    Table { line: usize, rows: Vec<Row> },
    /// A paragraph or a list item, its lines joined.
    Prose { line: usize, text: String },
}

/// Reads Markdown into blocks (see the module's comment for how roughly).
fn blocks(text: &str) -> Vec<Block> {
    let mut out = Vec::new();
    let mut lines = text.lines().enumerate().map(|(i, l)| (i + 1, l)).peekable();
    while let Some((n, line)) = lines.next() {
        let trimmed = line.trim_start();
        if let Some(fence) = fence(trimmed) {
            let mut body = Vec::new();
            for (m, inner) in lines.by_ref() {
                if inner.trim_start().starts_with(fence) {
                    break;
                }
                body.push((m, inner.to_string()));
            }
            let info = trimmed.trim_start_matches(fence).trim().to_string();
            out.push(Block::Code {
                line: n,
                info,
                lines: body,
            });
        } else if let Some(level) = heading_level(trimmed) {
            let text = trimmed[level..].trim().trim_end_matches('#').trim();
            out.push(Block::Heading {
                line: n,
                level,
                text: text.to_string(),
            });
        } else if trimmed.starts_with('|') {
            let mut rows = vec![(n, cells(trimmed))];
            while let Some((m, next)) = lines.next_if(|(_, l)| l.trim_start().starts_with('|')) {
                rows.push((m, cells(next.trim_start())));
            }
            rows.retain(|(_, row)| !is_delimiter_row(row));
            out.push(Block::Table { line: n, rows });
        } else if !trimmed.is_empty() {
            let mut text = line.trim().to_string();
            while let Some((_, next)) = lines.next_if(|(_, l)| continues_paragraph(l)) {
                text.push('\n');
                text.push_str(next.trim());
            }
            out.push(Block::Prose { line: n, text });
        }
    }
    out
}

/// The fence a line opens a code block with, if it does.
fn fence(trimmed: &str) -> Option<&'static str> {
    ["```", "~~~"].into_iter().find(|f| trimmed.starts_with(f))
}

fn heading_level(trimmed: &str) -> Option<usize> {
    let level = trimmed.bytes().take_while(|&b| b == b'#').count();
    let rest = &trimmed[level..];
    ((1..=6).contains(&level) && (rest.is_empty() || rest.starts_with(' '))).then_some(level)
}

/// Whether a line goes on with the paragraph above it: not blank, and no other block's start
/// (a list item starts a block of its own).
fn continues_paragraph(line: &str) -> bool {
    let t = line.trim_start();
    let list_item = t.starts_with("- ")
        || t.starts_with("* ")
        || t.split_once(". ")
            .is_some_and(|(n, _)| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()));
    !t.is_empty()
        && fence(t).is_none()
        && heading_level(t).is_none()
        && !t.starts_with('|')
        && !list_item
}

/// A table row's cells, split at the `|`s outside code spans.
fn cells(row: &str) -> Vec<String> {
    let row = row.trim();
    let row = row.strip_prefix('|').unwrap_or(row);
    let row = row.strip_suffix('|').unwrap_or(row);
    let mut out = vec![String::new()];
    let mut open: Option<usize> = None;
    let bytes = row.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        let run = bytes[i..].iter().take_while(|&&b| b == b'`').count();
        if run > 0 {
            open = match open {
                Some(n) if n == run => None,
                Some(n) => Some(n),
                None if row[i + run..].contains(&"`".repeat(run)) => Some(run),
                None => None,
            };
            out.last_mut().unwrap().push_str(&row[i..i + run]);
            i += run;
            continue;
        }
        let c = row[i..].chars().next().unwrap();
        if c == '|' && open.is_none() && !row[..i].ends_with('\\') {
            out.push(String::new());
        } else {
            out.last_mut().unwrap().push(c);
        }
        i += c.len_utf8();
    }
    out.into_iter().map(|c| c.trim().to_string()).collect()
}

fn is_delimiter_row(row: &[String]) -> bool {
    row.iter().all(|c| {
        let c = c.trim_matches(':');
        !c.is_empty() && c.bytes().all(|b| b == b'-')
    })
}

/// A text's code spans (their contents, trimmed), and the text with each span replaced by a space.
fn split_code(text: &str) -> (Vec<String>, String) {
    let mut spans = Vec::new();
    let mut rest = String::new();
    let mut i = 0;
    while i < text.len() {
        let run = text[i..].bytes().take_while(|&b| b == b'`').count();
        if run == 0 {
            let c = text[i..].chars().next().unwrap();
            rest.push(c);
            i += c.len_utf8();
            continue;
        }
        let ticks = "`".repeat(run);
        // The closing run: the same number of backticks, not part of a longer run.
        let mut from = i + run;
        let close = loop {
            match text[from..].find(&ticks) {
                None => break None,
                Some(at) => {
                    let at = from + at;
                    let len = text[at..].bytes().take_while(|&b| b == b'`').count();
                    if len == run {
                        break Some(at);
                    }
                    from = at + len;
                }
            }
        };
        match close {
            Some(end) => {
                spans.push(text[i + run..end].trim().to_string());
                rest.push(' ');
                i = end + run;
            }
            None => {
                rest.push_str(&ticks);
                i += run;
            }
        }
    }
    (spans, rest)
}

/// The link and image targets of a text outside its code spans: `[text](target "title")`,
/// `<https://…>` and reference definitions `[label]: target`.
fn link_targets(text: &str) -> Vec<String> {
    let (_, text) = split_code(text);
    let mut out = Vec::new();
    let mut rest = text.as_str();
    while let Some(at) = rest.find("](") {
        let after = &rest[at + 2..];
        let mut depth = 0;
        let end = after
            .char_indices()
            .find(|&(_, c)| {
                depth += match c {
                    '(' => 1,
                    ')' => -1,
                    _ => 0,
                };
                depth < 0
            })
            .map_or(after.len(), |(i, _)| i);
        let target = after[..end].trim();
        let target = target.split_once(" \"").map_or(target, |(t, _)| t);
        out.push(target.trim_matches(['<', '>']).to_string());
        rest = &after[end..];
    }
    for (i, _) in text.match_indices('<') {
        let after = &text[i + 1..];
        if ["http://", "https://", "mailto:"]
            .iter()
            .any(|s| after.starts_with(s))
            && let Some(end) = after.find('>')
        {
            out.push(after[..end].to_string());
        }
    }
    for line in text.lines() {
        let t = line.trim_start();
        if let Some((label, target)) = t.strip_prefix('[').and_then(|r| r.split_once("]:"))
            && !label.contains(']')
            && let Some(target) = target.split_whitespace().next()
        {
            out.push(target.trim_matches(['<', '>']).to_string());
        }
    }
    out
}

/// The commands of a code block's line: the line without its comment, trimmed, or `None` where
/// nothing is left. In a shell (or TOML) block a comment starts at a `#` at the line's start or
/// after a space, outside quotes; in Rust-like blocks at `//`. A block without a language is a
/// listing (a name or path, then what it is, continued on indented lines): its commands are the
/// first word of each line that is not indented.
fn command_part(info: &str, line: &str) -> Option<String> {
    let language = info.split([',', ' ']).next().unwrap_or("");
    let code = match language {
        "" | "text" | "txt" => {
            if line.starts_with([' ', '\t']) {
                ""
            } else {
                line.split_whitespace().next().unwrap_or("")
            }
        }
        "rust" | "rs" | "js" | "javascript" | "c" | "cpp" | "wgsl" => {
            line.find("//").map_or(line, |at| &line[..at])
        }
        _ => shell_comment(line).map_or(line, |at| &line[..at]),
    };
    let code = code.trim();
    (!code.is_empty()).then(|| code.to_string())
}

/// Where a shell line's comment starts.
fn shell_comment(line: &str) -> Option<usize> {
    let mut quote: Option<char> = None;
    let mut previous = ' ';
    for (i, c) in line.char_indices() {
        match quote {
            Some(q) if c == q => quote = None,
            Some(_) => {}
            None if c == '\'' || c == '"' => quote = Some(c),
            None if c == '#' && previous.is_whitespace() => return Some(i),
            None => {}
        }
        previous = c;
    }
    None
}

fn panic_on(problems: Vec<String>) {
    assert!(
        problems.is_empty(),
        "{CHINESE} has drifted from {ENGLISH}:\n  {}",
        problems.join("\n  ")
    );
}

fn headings(doc: &Doc) -> Vec<(usize, usize, &str)> {
    doc.blocks
        .iter()
        .filter_map(|b| match b {
            Block::Heading { line, level, text } => Some((*line, *level, text.as_str())),
            _ => None,
        })
        .collect()
}

/// A document's headings, one a line: `README.md:27 ## Quick start`.
fn outline(doc: &Doc, headings: &[(usize, usize, &str)]) -> String {
    let line = |(n, level, text): &(usize, usize, &str)| {
        format!("\n      {}:{n} {} {text}", doc.name, "#".repeat(*level))
    };
    headings.iter().map(line).collect()
}

/// The same headings: as many of each level, in the same order.
#[test]
fn the_translation_has_the_english_headings() {
    let (en, zh) = (doc(ENGLISH), doc(CHINESE));
    let (a, b) = (headings(&en), headings(&zh));
    let mut problems = Vec::new();
    for level in 1..=6 {
        let count = |h: &[(usize, usize, &str)]| h.iter().filter(|h| h.1 == level).count();
        if count(&a) != count(&b) {
            problems.push(format!(
                "{ENGLISH} has {} headings of level {level}, {CHINESE} has {}",
                count(&a),
                count(&b)
            ));
        }
    }
    let levels = |h: &[(usize, usize, &str)]| h.iter().map(|h| h.1).collect::<Vec<_>>();
    if levels(&a) != levels(&b) {
        let first = (0..a.len().max(b.len()))
            .find(|&i| a.get(i).map(|h| h.1) != b.get(i).map(|h| h.1))
            .unwrap_or(0);
        problems.push(format!(
            "the headings differ from heading {} on:{}\n    against:{}",
            first + 1,
            outline(&en, &a),
            outline(&zh, &b)
        ));
    }
    panic_on(problems);
}

/// The code blocks' commands: each line of each block without its comment, in order.
#[test]
fn the_translation_has_the_english_commands() {
    let (en, zh) = (doc(ENGLISH), doc(CHINESE));
    let code = |d: &Doc| -> Vec<(usize, String, Vec<Line>)> {
        let commands = |info: &str, lines: &[Line]| {
            let part = |(n, l): &Line| command_part(info, l).map(|c| (*n, c));
            lines.iter().filter_map(part).collect()
        };
        d.blocks
            .iter()
            .filter_map(|b| match b {
                Block::Code { line, info, lines } => {
                    Some((*line, info.clone(), commands(info, lines)))
                }
                _ => None,
            })
            .collect()
    };
    let (a, b) = (code(&en), code(&zh));
    let mut problems = Vec::new();
    if a.len() != b.len() {
        problems.push(format!(
            "{ENGLISH} has {} code blocks, {CHINESE} has {}",
            a.len(),
            b.len()
        ));
    }
    for (k, ((la, ia, ca), (lb, ib, cb))) in a.iter().zip(&b).enumerate() {
        let at = format!("code block {} ({ENGLISH}:{la}, {CHINESE}:{lb})", k + 1);
        if ia != ib {
            problems.push(format!("{at}: its language is `{ia}` against `{ib}`"));
        }
        for i in 0..ca.len().max(cb.len()) {
            let (x, y) = (ca.get(i), cb.get(i));
            if x.map(|c| &c.1) != y.map(|c| &c.1) {
                let show = |name: &str, c: Option<&Line>| {
                    c.map_or(format!("no command in {name}"), |(n, c)| {
                        format!("{name}:{n} `{c}`")
                    })
                };
                problems.push(format!(
                    "{at}: command {} differs: {} against {}",
                    i + 1,
                    show(ENGLISH, x),
                    show(CHINESE, y)
                ));
            }
        }
    }
    panic_on(problems);
}

fn tables(doc: &Doc) -> Vec<(usize, &[Row])> {
    doc.blocks
        .iter()
        .filter_map(|b| match b {
            Block::Table { line, rows } => Some((*line, rows.as_slice())),
            _ => None,
        })
        .collect()
}

/// One table against its translation: rows, columns, and the code spans cell by cell.
fn table_problems(k: usize, (la, ra): (usize, &[Row]), (lb, rb): (usize, &[Row])) -> Vec<String> {
    let at = format!("table {k} ({ENGLISH}:{la}, {CHINESE}:{lb})");
    let mut problems = Vec::new();
    if ra.len() != rb.len() {
        problems.push(format!(
            "{at}: {ENGLISH} has {} rows (with the header), {CHINESE} has {}",
            ra.len(),
            rb.len()
        ));
    }
    for ((na, a), (nb, b)) in ra.iter().zip(rb) {
        let before = problems.len();
        if a.len() != b.len() {
            problems.push(format!(
                "{at}: {ENGLISH}:{na} has {} columns, {CHINESE}:{nb} has {}",
                a.len(),
                b.len()
            ));
        }
        for (c, (x, y)) in a.iter().zip(b).enumerate() {
            // As many of each, in any order: Chinese word order may move a code span in a cell.
            let sorted = |cell: &str| {
                let mut spans = split_code(cell).0;
                spans.sort();
                spans
            };
            let (sx, sy) = (sorted(x), sorted(y));
            if sx != sy {
                problems.push(format!(
                    "{at}: column {} of {ENGLISH}:{na} has the code {sx:?}, \
                     of {CHINESE}:{nb} {sy:?}",
                    c + 1
                ));
            }
        }
        if ra.len() != rb.len() && problems.len() > before {
            // A row missing or added: the first row that differs says where; the rest only follow.
            break;
        }
    }
    problems
}

/// The tables: as many rows and columns, and the same code spans in each cell.
#[test]
fn the_translation_has_the_english_tables() {
    let (en, zh) = (doc(ENGLISH), doc(CHINESE));
    let (a, b) = (tables(&en), tables(&zh));
    let mut problems = Vec::new();
    if a.len() != b.len() {
        problems.push(format!(
            "{ENGLISH} has {} tables, {CHINESE} has {}",
            a.len(),
            b.len()
        ));
    }
    for (k, (x, y)) in a.into_iter().zip(b).enumerate() {
        problems.extend(table_problems(k + 1, x, y));
    }
    panic_on(problems);
}

/// Every link target of a document outside its code blocks, the other language's README named
/// as such (the language switcher links each README to the other).
fn links(doc: &Doc, other: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for block in &doc.blocks {
        let texts: Vec<&str> = match block {
            Block::Heading { text, .. } | Block::Prose { text, .. } => vec![text],
            Block::Table { rows, .. } => {
                rows.iter().flat_map(|r| &r.1).map(|c| c.as_str()).collect()
            }
            Block::Code { .. } => vec![],
        };
        for target in texts.into_iter().flat_map(link_targets) {
            let is_other = target == other;
            out.insert(if is_other {
                "(the other README)".to_string()
            } else {
                target
            });
        }
    }
    out
}

/// The same link targets.
#[test]
fn the_translation_has_the_english_links() {
    let (en, zh) = (doc(ENGLISH), doc(CHINESE));
    let (a, b) = (links(&en, CHINESE), links(&zh, ENGLISH));
    let mut problems = Vec::new();
    for missing in a.difference(&b) {
        problems.push(format!("{ENGLISH} links to {missing}, {CHINESE} does not"));
    }
    for extra in b.difference(&a) {
        problems.push(format!("{CHINESE} links to {extra}, {ENGLISH} does not"));
    }
    panic_on(problems);
}

/// The language switcher right under the title, mirrored: the same labels in the same order,
/// each README linking to the other and not to itself.
#[test]
fn the_language_switcher_is_mirrored() {
    let switcher = |doc: &Doc, other: &str| -> Result<String, String> {
        let (Some(Block::Heading { level: 1, .. }), Some(Block::Prose { line, text })) =
            (doc.blocks.first(), doc.blocks.get(1))
        else {
            return Err(format!(
                "{} does not start with a title and a line under it",
                doc.name
            ));
        };
        if link_targets(text) != [other] {
            return Err(format!(
                "{}:{line}: the language switcher `{text}` must link to {other} only",
                doc.name
            ));
        }
        let label = text.replace(&format!("]({other})"), "").replace('[', "");
        Ok(label)
    };
    match (
        switcher(&doc(ENGLISH), CHINESE),
        switcher(&doc(CHINESE), ENGLISH),
    ) {
        (Ok(a), Ok(b)) => assert_eq!(a, b, "the language switchers' labels differ"),
        (a, b) => panic_on([a.err(), b.err()].into_iter().flatten().collect()),
    }
}

/// The glossary's terms, (English, Chinese): each without what follows it in brackets, as
/// `book/po/check-terms.py` reads them ("pose (of the camera)" is "pose", and
/// "深度冲突（z-fighting）" asks for 深度冲突).
fn glossary() -> Vec<(String, String)> {
    let path = repo().join("book/src/glossary.md");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let strip_tags = |cell: &str| {
        let mut out = String::new();
        let mut in_tag = false;
        for c in cell.chars() {
            match c {
                '<' => in_tag = true,
                '>' => in_tag = false,
                c if !in_tag => out.push(c),
                _ => {}
            }
        }
        out.trim().to_string()
    };
    let mut terms = Vec::new();
    for block in blocks(&text) {
        let Block::Table { rows, .. } = block else {
            continue;
        };
        if rows
            .first()
            .is_none_or(|(_, h)| h.len() < 2 || h[0] != "English" || h[1] != "中文")
        {
            continue;
        }
        for (_, row) in &rows[1..] {
            let english = strip_tags(&row[0]);
            let english = english.split(" (").next().unwrap_or_default().trim();
            let chinese = row[1].split('（').next().unwrap_or_default().trim();
            if !EVERYDAY_WORDS.contains(&english) && !chinese.is_empty() {
                terms.push((english.to_string(), chinese.to_string()));
            }
        }
    }
    assert!(
        terms.len() > 20,
        "{}: too few terms read ({})",
        path.display(),
        terms.len()
    );
    terms
}

/// Whether English prose uses a term: the whole words, in any case, or their plural.
fn uses(prose: &str, term: &str) -> bool {
    let (prose, term) = (prose.to_lowercase(), term.to_lowercase());
    let word = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric());
    prose.match_indices(&term).any(|(at, _)| {
        let after = &prose[at + term.len()..];
        let after = after
            .strip_prefix("es")
            .or(after.strip_prefix('s'))
            .filter(|a| !word(a.chars().next()))
            .unwrap_or(after);
        !word(prose[..at].chars().next_back()) && !word(after.chars().next())
    })
}

/// A document's prose in units that a translation keeps: headings, paragraphs and table rows, by
/// section (a section starts at each heading). Code spans and link targets are left out.
fn sections(doc: &Doc) -> Vec<Vec<Line>> {
    let mut out: Vec<Vec<Line>> = vec![Vec::new()];
    for block in &doc.blocks {
        if matches!(block, Block::Heading { .. }) {
            out.push(Vec::new());
        }
        let prose = |line: usize, text: &str| {
            let (_, mut text) = split_code(text);
            for target in link_targets(&text) {
                text = text.replace(&format!("]({target})"), "]");
            }
            (line, text)
        };
        let units = out.last_mut().unwrap();
        match block {
            Block::Heading { line, text, .. } | Block::Prose { line, text } => {
                units.push(prose(*line, text));
            }
            Block::Table { rows, .. } => {
                units.extend(
                    rows.iter()
                        .map(|(line, cells)| prose(*line, &cells.join(" | "))),
                );
            }
            Block::Code { .. } => {}
        }
    }
    out
}

/// Wherever a README.md heading, paragraph or table row uses a glossary term, its translation (the
/// same unit of the same section; the whole section where the section's units do not pair up)
/// has the glossary's Chinese.
#[test]
fn the_translation_uses_the_glossary_s_terms() {
    let terms = glossary();
    let (en, zh) = (doc(ENGLISH), doc(CHINESE));
    let (a, mut b) = (sections(&en), sections(&zh));
    if a.len() != b.len() {
        // The headings test says how; here the whole document is one section.
        b = vec![b.concat()];
    }
    let mut problems = Vec::new();
    for (k, units) in a.iter().enumerate() {
        let theirs = &b[k.min(b.len() - 1)];
        let first = theirs.first().map_or(0, |u| u.0);
        for (i, (line, text)) in units.iter().enumerate() {
            let (at, counterpart) = match theirs.get(i) {
                Some((n, unit)) if units.len() == theirs.len() => {
                    (format!("{CHINESE}:{n}"), unit.clone())
                }
                _ => (
                    format!("its section ({CHINESE}:{first} on: the paragraphs do not pair up)"),
                    theirs.iter().map(|u| u.1.as_str()).collect(),
                ),
            };
            for (english, chinese) in &terms {
                if uses(text, english) && !counterpart.contains(chinese.as_str()) {
                    problems.push(format!(
                        "{ENGLISH}:{line} says \"{english}\" but its translation at {at} \
                         lacks \"{chinese}\" (book/src/glossary.md)"
                    ));
                }
            }
        }
    }
    panic_on(problems);
}

#[test]
fn the_reading_of_markdown_is_right_on_samples() {
    let text = "# T\n\nA *b*\nc.\n- item\n\n\
                | a | `x|y` |\n|---|:-:|\n| 1 | `p` and ``q`r`` |\n\n\
                ```sh\n# only a comment\ncargo run -p a   # run it\n```\n## S #\n";
    let b = blocks(text);
    assert_eq!(b.len(), 6, "{b:#?}");
    assert_eq!(
        b[1],
        Block::Prose {
            line: 3,
            text: "A *b*\nc.".into()
        }
    );
    assert_eq!(
        b[2],
        Block::Prose {
            line: 5,
            text: "- item".into()
        }
    );
    let Block::Table { rows, .. } = &b[3] else {
        panic!("{b:#?}")
    };
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0].1, ["a", "`x|y`"]);
    assert_eq!(split_code(&rows[1].1[1]).0, ["p", "q`r"]);
    let Block::Code { info, lines, .. } = &b[4] else {
        panic!("{b:#?}")
    };
    assert_eq!(info, "sh");
    let commands: Vec<_> = lines
        .iter()
        .filter_map(|(_, l)| command_part(info, l))
        .collect();
    assert_eq!(commands, ["cargo run -p a"]);
    assert_eq!(
        b[5],
        Block::Heading {
            line: 15,
            level: 2,
            text: "S".into()
        }
    );
    assert_eq!(
        command_part("sh", "echo 'a # b' # c").as_deref(),
        Some("echo 'a # b'")
    );
    assert_eq!(
        command_part("", "shared/           the crate").as_deref(),
        Some("shared/")
    );
    assert_eq!(command_part("", "                  more of it"), None);
}

#[test]
fn the_reading_of_links_and_terms_is_right_on_samples() {
    let text = "[a](x.md) ![b](img/c.png \"t\") [`d`](https://e.org/f_(g)) \
                `[h](not-a-link)` <https://i.org>\n[j]: k.md";
    assert_eq!(
        link_targets(text),
        [
            "x.md",
            "img/c.png",
            "https://e.org/f_(g)",
            "https://i.org",
            "k.md"
        ]
    );
    assert!(uses("the Depth buffers are", "depth buffer"));
    assert!(uses("depth buffer.", "depth buffer"));
    assert!(!uses("depth buffered", "depth buffer"));
    assert!(!uses("undepth buffer", "depth buffer"));
    let terms = glossary();
    let term = |english: &str| terms.iter().find(|t| t.0 == english).map(|t| t.1.as_str());
    assert_eq!(term("depth buffer"), Some("深度缓冲区"));
    assert_eq!(term("z-fighting"), Some("深度冲突"));
    assert_eq!(term("clear"), None, "an everyday word");
}
