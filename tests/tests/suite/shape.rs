//! The code's shape, kept: the framework's modules import one another one way only (no circle),
//! and no function in the framework, the web edition or the lessons runs over 80 lines.
//!
//! Both tests read the sources as text, as the team's `long-functions.py` does (`../shared/tools/`
//! beside the repository; its numbers and these agree): no compiler, no dependency, a few hundred
//! milliseconds in a debug build. The reading is rough (a path is a run of `name::name` words, a
//! function ends where its braces balance), so its parts are tested on small samples below.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The longest a function may be, in lines from its `fn` (or `function`) line to its closing brace.
const LONGEST: usize = 80;

/// Functions allowed to run longer: `(file, function, why)`. Only a declarative table belongs here
/// (a list that reads top to bottom, which splitting would only scatter), never steps of work. None
/// today; the test fails on an exception that is no longer needed, so the list cannot go stale.
const ALLOWED: &[(&str, &str, &str)] = &[];

/// Where the functions are measured: the framework, the web edition's Rust and the lessons (their
/// `src`, `examples` and `tests`). The web edition's JavaScript is `book/web/*.js`.
const MEASURED: &[&str] = &["shared/src", "book/web", "chapters"];

/// Folders never measured, as in long-functions.py: build output and generated files.
const SKIPPED: &[&str] = &["target", "node_modules", "build", "live"];

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// No import circle among the framework's modules: its parts build on one another one way (math,
/// then gpu, room, lesson, and app with book beside it). Only the files of one module split up may
/// use one another both ways (see [`module_graph`]).
#[test]
fn the_framework_s_modules_import_one_another_without_a_circle() {
    let src = repo().join("shared/src");
    let edges = module_graph(&src);
    assert!(
        edges.len() > 20,
        "read too few imports from {}: {edges:?}",
        src.display()
    );
    let circles = circles(&edges);
    assert!(
        circles.is_empty(),
        "shared/src's modules import one another in a circle: no module of a circle can be read, \
         tested or moved without all the others. Break it by moving what the lower module takes from \
         the higher one into a module of its own (as `say` went to app::output).\n\n{}",
        describe(&circles, &edges)
    );
}

/// The framework's parts, lowest first: each imports only from the ones before it. `book` stands
/// beside `app` (the panel compares with the book; `--check` runs the app's headless runner).
const LAYERS: &[&[&str]] = &[
    &["math"],
    &["gpu"],
    &["room"],
    &["lesson"],
    &["app", "book"],
];

/// The parts build on one another one way, as `shared/README.md` draws them: a lower part never
/// imports a higher one (the room knows no lesson, the GPU's recipes know no room).
#[test]
fn the_framework_s_parts_import_only_the_parts_below_them() {
    let edges = module_graph(&repo().join("shared/src"));
    let layer = |module: &Module| {
        let part = module.first().map(String::as_str).unwrap_or_default();
        LAYERS.iter().position(|layer| layer.contains(&part))
    };
    let upward: Vec<String> = edges
        .iter()
        .flat_map(|(from, to)| to.iter().map(move |(to, place)| (from, to, place)))
        .filter(|(from, to, _)| matches!((layer(from), layer(to)), (Some(a), Some(b)) if b > a))
        .map(|(from, to, place)| format!("  {} -> {}   ({place})", show(from), show(to)))
        .collect();
    assert!(
        upward.is_empty(),
        "a lower part of the framework imports a higher one (the parts, lowest first: math, gpu, \
         room, lesson, app and book): move what it takes down, or the code up.\n{}",
        upward.join("\n")
    );
}

/// No function over [`LONGEST`] lines but the [`ALLOWED`] ones.
#[test]
fn no_function_runs_over_80_lines() {
    let all = measured_functions(&repo());
    assert!(all.len() > 500, "found only {} functions", all.len());
    let allowed = |f: &Function| {
        ALLOWED
            .iter()
            .any(|&(file, name, _)| f.file == file && f.name == name)
    };
    let long: Vec<&Function> = all
        .iter()
        .filter(|f| f.lines > LONGEST && !allowed(f))
        .collect();
    let stale: Vec<_> = ALLOWED
        .iter()
        .filter(|&&(file, name, _)| {
            !all.iter()
                .any(|f| f.file == file && f.name == name && f.lines > LONGEST)
        })
        .collect();
    assert!(
        long.is_empty(),
        "{} function(s) over {LONGEST} lines (counted from the `fn` line to the closing brace, as \
         long-functions.py counts): split each into named steps.\n{}",
        long.len(),
        long.iter()
            .map(|f| format!("{:5}  {}:{}  {}\n", f.lines, f.file, f.line, f.name))
            .collect::<String>()
    );
    assert!(
        stale.is_empty(),
        "allowed but no longer over {LONGEST} lines: {stale:?}"
    );
}

// ---------------------------------------------------------------------------------------------
// Source text

/// The source with comments and string and character literals blanked (newlines kept, so lines
/// still count): what is left is code. A lifetime (`'a`) stays.
fn code_only(source: &str) -> String {
    let s: Vec<char> = source.chars().collect();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < s.len() {
        let end = match (s[i], s.get(i + 1).copied()) {
            ('/', Some('/')) => (i..s.len()).find(|&k| s[k] == '\n'),
            ('/', Some('*')) => Some(block_comment_end(&s, i)),
            ('"', _) => Some(string_end(&s, i + 1, None)),
            ('\'', _) => char_literal_end(&s, i),
            _ => raw_string_start(&s, i)
                .map(|(quote, hashes)| string_end(&s, quote + 1, Some(hashes))),
        };
        let Some(end) = end else {
            out.push(s[i]);
            i += 1;
            continue;
        };
        out.extend(s[i..end].iter().map(|&c| if c == '\n' { c } else { ' ' }));
        i = end;
    }
    out
}

/// Just past the `*/` that closes the block comment opened at `i` (they nest).
fn block_comment_end(s: &[char], i: usize) -> usize {
    let (mut depth, mut k) = (0, i);
    while k < s.len() {
        match (s[k], s.get(k + 1).copied()) {
            ('/', Some('*')) => (depth, k) = (depth + 1, k + 2),
            ('*', Some('/')) => (depth, k) = (depth - 1, k + 2),
            _ => k += 1,
        }
        if depth == 0 {
            return k;
        }
    }
    s.len()
}

/// Just past the closing quote of a string whose text begins at `k`: a plain string (its escapes
/// skipped), or a raw one closed by `"` and `raw` times `#`.
fn string_end(s: &[char], mut k: usize, raw: Option<usize>) -> usize {
    let hashes = raw.unwrap_or(0);
    while k < s.len() {
        match s[k] {
            '\\' if raw.is_none() => k += 2,
            '"' if (1..=hashes).all(|h| s.get(k + h) == Some(&'#')) => return k + 1 + hashes,
            _ => k += 1,
        }
    }
    s.len()
}

/// `r"`, `r#"`, `br"`... starting at `i`: where its opening quote is, and how many `#` close it.
fn raw_string_start(s: &[char], i: usize) -> Option<(usize, usize)> {
    if i > 0 && is_word(s[i - 1]) {
        return None;
    }
    let r = if s[i] == 'b' { i + 1 } else { i };
    if s.get(r) != Some(&'r') {
        return None;
    }
    let hashes = s[r + 1..].iter().take_while(|&&c| c == '#').count();
    (s.get(r + 1 + hashes) == Some(&'"')).then_some((r + 1 + hashes, hashes))
}

/// Just past a character literal opening at `i` (`'x'`, `'\n'`, `'\u{7f}'`); `None` for a lifetime.
fn char_literal_end(s: &[char], i: usize) -> Option<usize> {
    if s.get(i + 1) == Some(&'\\') {
        return (i + 3..s.len()).find(|&k| s[k] == '\'').map(|k| k + 1);
    }
    (s.get(i + 2) == Some(&'\'')).then_some(i + 3)
}

/// The code with every `#[cfg(test)]` item blanked (a test module, a test-only `use`): tests may
/// reach anywhere. An item ends at its first `;` outside braces or where its first brace closes.
fn without_test_items(code: &str) -> String {
    let test_only: Vec<char> = "#[cfg(test)]".chars().collect();
    let mut out: Vec<char> = code.chars().collect();
    let mut at = 0;
    while let Some(found) = out[at..]
        .windows(test_only.len())
        .position(|w| w == test_only)
    {
        let start = at + found;
        let (mut k, mut depth) = (start + test_only.len(), 0);
        while k < out.len() {
            match out[k] {
                ';' if depth == 0 => break,
                '{' => depth += 1,
                '}' if depth == 1 => break,
                '}' => depth -= 1,
                _ => {}
            }
            k += 1;
        }
        at = (k + 1).min(out.len());
        for c in &mut out[start..at] {
            if *c != '\n' {
                *c = ' ';
            }
        }
    }
    out.into_iter().collect()
}

fn is_word(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// A word, `::`, or one other character of code, with its line (from 1).
#[derive(Debug)]
struct Token {
    text: String,
    line: usize,
}

fn tokens(code: &str) -> Vec<Token> {
    let mut out = Vec::new();
    let mut line = 1;
    let mut chars = code.chars().peekable();
    while let Some(c) = chars.next() {
        let mut text = c.to_string();
        if is_word(c) {
            while let Some(&next) = chars.peek().filter(|&&n| is_word(n)) {
                text.push(next);
                chars.next();
            }
        } else if c == ':' && chars.peek() == Some(&':') {
            text.push(chars.next().unwrap());
        } else if c.is_whitespace() {
            line += usize::from(c == '\n');
            continue;
        }
        out.push(Token { text, line });
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Paths

/// A path as written (`crate::gpu::Gpu`, `super::panel::Cost`), the name it is known by in its
/// module (its last part, or what `as` renames it to) and the line it is on.
#[derive(Debug, PartialEq)]
struct Written {
    path: Vec<String>,
    name: String,
    line: usize,
}

/// Every path the code names: each one a `use` brings in (its tree spelled out), and every other
/// run of `name::name...` that does not follow a `::`.
fn paths(code: &str) -> Vec<Written> {
    let t = tokens(code);
    let text = |k: usize| t.get(k).map_or("", |t| t.text.as_str());
    let mut out = Vec::new();
    let mut k = 0;
    while k < t.len() {
        if text(k) == "use" {
            k += 1;
            use_tree(&t, &mut k, &[], &mut out);
            continue;
        }
        let starts =
            is_word(text(k).chars().next().unwrap_or(' ')) && text(k.wrapping_sub(1)) != "::";
        if starts && text(k + 1) == "::" {
            let mut path = vec![t[k].text.clone()];
            while text(k + 1) == "::" && text(k + 2).starts_with(is_word) {
                path.push(t[k + 2].text.clone());
                k += 2;
            }
            let name = path.last().cloned().unwrap_or_default();
            out.push(Written {
                path,
                name,
                line: t[k].line,
            });
        }
        k += 1;
    }
    out
}

/// Spells out one `use` tree from token `k` (`a::{b::{self, C}, d as e, *}`) into its paths, each
/// after `prefix`, and leaves `k` past it.
fn use_tree(t: &[Token], k: &mut usize, prefix: &[String], out: &mut Vec<Written>) {
    let text = |k: usize| t.get(k).map_or("", |t| t.text.as_str());
    let mut path = prefix.to_vec();
    while *k < t.len() {
        let line = t[*k].line;
        match text(*k) {
            "{" => {
                *k += 1;
                while *k < t.len() && text(*k) != "}" {
                    let before = *k;
                    use_tree(t, k, &path, out);
                    if text(*k) == "," || *k == before {
                        *k += 1;
                    }
                }
                *k += 1;
                return;
            }
            // `a::{self}` and `a::*` name `a` itself.
            "*" | "self" if !path.is_empty() => *k += 1,
            word if word.starts_with(is_word) => {
                path.push(word.to_string());
                *k += 1;
                if text(*k) == "::" {
                    *k += 1;
                    continue;
                }
            }
            _ => return,
        }
        let mut name = path.last().cloned().unwrap_or_default();
        if text(*k) == "as" {
            name = text(*k + 1).to_string();
            *k += 2;
        }
        out.push(Written { path, name, line });
        return;
    }
}

// ---------------------------------------------------------------------------------------------
// The module graph

/// A module by its path in the crate, `["app", "cli"]` for `crate::app::cli`; the root is empty.
type Module = Vec<String>;

fn show(module: &[String]) -> String {
    if module.is_empty() {
        "crate".to_string()
    } else {
        module.join("::")
    }
}

/// Which module imports which, with where it first does (`shared/src/app/cli.rs:71`).
type Edges = BTreeMap<Module, BTreeMap<Module, String>>;

/// Reads every module of the crate at `src` (`lib.rs`, `a/mod.rs`, `a/b.rs`) and links each to the
/// modules its code (not its comments, not its tests) names. A name the crate root re-exports
/// (`crate::Gpu`) counts as an import of the module that defines it; the root itself, a façade that
/// names everything, is left out. So is a part's import of the module it is part of (`use
/// super::Workbench` in `app/workbench/frame.rs`): a module split over files is one module, its
/// parts use the whole and the whole its parts. A part's import of a sibling (`super::panel`) or of
/// anything outside counts.
fn module_graph(src: &Path) -> Edges {
    let mut code = BTreeMap::new();
    let mut modules = BTreeMap::new();
    for file in files(src, &|p| p.extension().is_some_and(|e| e == "rs")) {
        let relative = file.strip_prefix(src).unwrap();
        let mut module: Module = relative
            .with_extension("")
            .iter()
            .map(|part| part.to_string_lossy().into_owned())
            .collect();
        if matches!(module.last().map(String::as_str), Some("mod" | "lib")) {
            module.pop();
        }
        let text = fs::read_to_string(&file).unwrap();
        code.insert(module.clone(), without_test_items(&code_only(&text)));
        modules.insert(module, format!("shared/src/{}", relative.display()));
    }
    let root_names: BTreeMap<String, Vec<String>> = paths(&code[&Module::new()])
        .into_iter()
        .map(|w| {
            (
                w.name,
                w.path.into_iter().skip_while(|p| p == "crate").collect(),
            )
        })
        .collect();
    let mut edges = Edges::new();
    for (module, code) in code.iter().filter(|(m, _)| !m.is_empty()) {
        for written in paths(code) {
            let Some(target) = resolve(module, &written.path, &modules, &root_names) else {
                continue;
            };
            if !module.starts_with(&target) {
                let place = format!("{}:{}", modules[module], written.line);
                edges
                    .entry(module.clone())
                    .or_default()
                    .entry(target)
                    .or_insert(place);
            }
        }
    }
    edges
}

/// The module a path written in `module` leads into: the longest start of it that is a module.
/// `crate::`, `super::`, `self::` and a child module's name begin a path into this crate; any other
/// path (`wgpu::`, `std::`, a local type's) is not ours.
fn resolve(
    module: &[String],
    path: &[String],
    modules: &BTreeMap<Module, String>,
    root_names: &BTreeMap<String, Vec<String>>,
) -> Option<Module> {
    let first = path.first()?.as_str();
    let absolute: Vec<String> = match first {
        "crate" => path[1..].to_vec(),
        "self" => [module, &path[1..]].concat(),
        "super" => {
            let ups = path.iter().take_while(|p| *p == "super").count();
            let base = module.get(..module.len().checked_sub(ups)?)?;
            [base, &path[ups..]].concat()
        }
        _ if modules.contains_key(&[module, &path[..1]].concat()) => [module, path].concat(),
        _ => return None,
    };
    let longest = (0..=absolute.len())
        .rev()
        .find(|&n| modules.contains_key(&absolute[..n]))?;
    if longest > 0 {
        return Some(absolute[..longest].to_vec());
    }
    // `crate::Gpu`: the root's `pub use gpu::Gpu`.
    let target = root_names.get(absolute.first()?)?;
    (1..=target.len())
        .rev()
        .find(|&n| modules.contains_key(&target[..n]))
        .map(|n| target[..n].to_vec())
}

/// The graph's circles: each strongly connected set of two or more modules (Tarjan's algorithm).
fn circles(edges: &Edges) -> Vec<Vec<Module>> {
    struct Search<'a> {
        edges: &'a Edges,
        index: BTreeMap<&'a Module, usize>,
        stack: Vec<&'a Module>,
        found: Vec<Vec<Module>>,
    }
    impl<'a> Search<'a> {
        fn visit(&mut self, m: &'a Module) -> usize {
            let order = self.index.len();
            self.index.insert(m, order);
            self.stack.push(m);
            let mut low = order;
            let edges = self.edges;
            for next in edges.get(m).into_iter().flat_map(|e| e.keys()) {
                low = match self.index.get(next) {
                    None => low.min(self.visit(next)),
                    Some(&seen) if self.stack.contains(&next) => low.min(seen),
                    Some(_) => low,
                };
            }
            if low == order {
                let at = self.stack.iter().position(|s| *s == m).unwrap();
                let set: Vec<Module> = self.stack.drain(at..).cloned().collect();
                if set.len() > 1 {
                    self.found.push(set);
                }
            }
            low
        }
    }
    let mut search = Search {
        edges,
        index: BTreeMap::new(),
        stack: Vec::new(),
        found: Vec::new(),
    };
    for m in edges.keys() {
        if !search.index.contains_key(m) {
            search.visit(m);
        }
    }
    for set in &mut search.found {
        set.sort();
    }
    search.found.sort();
    search.found
}

/// Each circle: its modules, then the imports that close it, with where each is written.
fn describe(circles: &[Vec<Module>], edges: &Edges) -> String {
    let mut out = String::new();
    for set in circles {
        let names: Vec<String> = set.iter().map(|m| show(m)).collect();
        out += &format!("circle of {} modules: {}\n", set.len(), names.join(", "));
        let members: BTreeSet<&Module> = set.iter().collect();
        for from in set {
            for (to, place) in edges.get(from).into_iter().flatten() {
                if members.contains(to) {
                    out += &format!("  {} -> {}   ({place})\n", show(from), show(to));
                }
            }
        }
    }
    out
}

// ---------------------------------------------------------------------------------------------
// Function lengths

/// A function as long-functions.py measures it.
#[derive(Debug, PartialEq)]
struct Function {
    lines: usize,
    file: String,
    line: usize,
    name: String,
}

/// Every function of the measured folders, longest first.
fn measured_functions(repo: &Path) -> Vec<Function> {
    let mut all = Vec::new();
    let web = repo.join("book/web");
    let wanted = |p: &Path| match p.extension().and_then(|e| e.to_str()) {
        Some("rs") => true,
        Some("js") => p.parent() == Some(web.as_path()),
        _ => false,
    };
    for folder in MEASURED {
        for file in files(&repo.join(folder), &wanted) {
            let text = String::from_utf8_lossy(&fs::read(&file).unwrap()).into_owned();
            let js = file.extension().is_some_and(|e| e == "js");
            let shown = file.strip_prefix(repo).unwrap().display().to_string();
            all.extend(
                functions(&text, js)
                    .into_iter()
                    .map(|(lines, line, name)| Function {
                        lines,
                        file: shown.clone(),
                        line,
                        name,
                    }),
            );
        }
    }
    all.sort_by(|a, b| (b.lines, &a.file, a.line).cmp(&(a.lines, &b.file, b.line)));
    all
}

/// The files under `dir` that `wanted` takes, skipping the [`SKIPPED`] folders, in a fixed order.
fn files(dir: &Path, wanted: &dyn Fn(&Path) -> bool) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        if path.is_dir() && !SKIPPED.contains(&name.as_ref()) {
            out.extend(files(&path, wanted));
        } else if path.is_file() && wanted(&path) {
            out.push(path);
        }
    }
    out
}

/// `(length, first line, name)` of each function in `text`: from the line that opens it to the
/// line where its braces balance, braces after a `//` not counted. A `fn` line that ends in `;`
/// before any brace declares a function without a body (a trait's) and is not one.
fn functions(text: &str, js: bool) -> Vec<(usize, usize, String)> {
    let lines: Vec<&str> = text.split('\n').collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let name = if js {
            js_function(line)
        } else {
            rust_function(line)
        };
        let Some(name) = name else { continue };
        let (mut depth, mut started) = (0i64, false);
        for (j, line) in lines.iter().enumerate().skip(i) {
            let code = line.find("//").map_or(*line, |at| &line[..at]);
            if !started && code.trim_end().ends_with(';') {
                break;
            }
            for c in code.chars() {
                match c {
                    '{' => (depth, started) = (depth + 1, true),
                    '}' => depth -= 1,
                    _ => {}
                }
            }
            if started && depth <= 0 {
                out.push((j - i + 1, i + 1, name));
                break;
            }
        }
    }
    out
}

/// The text after `word` and the blanks that must follow it.
fn keyword<'a>(s: &'a str, word: &str) -> Option<&'a str> {
    let rest = s.strip_prefix(word)?;
    rest.starts_with(char::is_whitespace)
        .then(|| rest.trim_start())
}

/// The leading word characters of `s` (maybe none), and the rest.
fn word(s: &str) -> (&str, &str) {
    s.split_at(s.find(|c| !is_word(c)).unwrap_or(s.len()))
}

/// The name of the Rust function a line opens: `[pub[(...)]] [const] [async] [unsafe]
/// [extern "abi"] fn name`, as long-functions.py's pattern reads it.
fn rust_function(line: &str) -> Option<String> {
    let mut s = line.trim_start();
    if let Some(rest) = s.strip_prefix("pub") {
        let rest = match rest.strip_prefix('(') {
            Some(inner) => &inner[inner.find(')')? + 1..],
            None => rest,
        };
        s = rest
            .starts_with(char::is_whitespace)
            .then(|| rest.trim_start())?;
    }
    for qualifier in ["const", "async", "unsafe"] {
        s = keyword(s, qualifier).unwrap_or(s);
    }
    if let Some(rest) = keyword(s, "extern") {
        let abi = rest.strip_prefix('"')?;
        s = keyword(&abi[abi.find('"')?..], "\"")?;
    }
    let (name, _) = word(keyword(s, "fn")?);
    (!name.is_empty()).then(|| name.to_string())
}

/// The name of the JavaScript function a line opens: `[async] function [name]`, or `const name =
/// [async] function` / `const name = (...) =>` (or `let`), as long-functions.py's pattern reads it.
fn js_function(line: &str) -> Option<String> {
    let s = line.trim_start();
    let plain = keyword(s, "async").unwrap_or(s);
    if let Some(rest) = plain.strip_prefix("function") {
        let (name, _) = word(rest.trim_start());
        return Some(if name.is_empty() { "(anonymous)" } else { name }.to_string());
    }
    let rest = keyword(s, "const").or_else(|| keyword(s, "let"))?;
    let (name, rest) = word(rest);
    let rest = rest.trim_start().strip_prefix('=')?.trim_start();
    let rest = rest.strip_prefix("async").map_or(rest, str::trim_start);
    let arrow = || {
        let inner = rest.strip_prefix('(')?;
        inner[inner.find(')')? + 1..]
            .trim_start()
            .strip_prefix("=>")
    };
    let opens = rest.starts_with("function") || arrow().is_some();
    (!name.is_empty() && opens).then(|| name.to_string())
}

// ---------------------------------------------------------------------------------------------
// The reading, on small samples

#[test]
fn code_only_blanks_comments_and_literals_and_keeps_lines() {
    let source = "let a = \"crate::x {\"; // crate::y {\n/* crate::z /* { */ } */ let c = '{';\n\
                  fn f<'a>(s: &'a str) -> char { r#\"crate::w \" {\"# ; '\\'' }\n";
    let code = code_only(source);
    assert_eq!(code.lines().count(), source.lines().count());
    assert!(!code.contains("crate::"), "{code}");
    assert_eq!(code.matches('{').count(), 1, "{code}");
    assert!(code.contains("fn f<'a>(s: &'a str)"), "{code}");
}

#[test]
fn test_items_are_left_out() {
    let code = "use crate::a;\n#[cfg(test)]\nmod tests {\n    use super::*;\n    fn t() { crate::b::f(); }\n}\n\
                #[cfg(test)]\nuse crate::c;\nfn g() { crate::d::h() }\n";
    let kept = without_test_items(code);
    let named: Vec<_> = paths(&kept)
        .into_iter()
        .map(|w| (w.path.join("::"), w.line))
        .collect();
    assert_eq!(
        named,
        [("crate::a".to_string(), 1), ("crate::d::h".to_string(), 9)]
    );
}

#[test]
fn use_trees_are_spelled_out_and_other_paths_read_whole() {
    let code = "pub use crate::a::{b::{self, C}, d as e, f::*};\nuse super::{G, h};\n\
                fn x() { crate::gpu::views::V::new::<T>(); winit::window::W; panel::show(); }";
    let found: Vec<_> = paths(code)
        .into_iter()
        .map(|w| format!("{} as {} @{}", w.path.join("::"), w.name, w.line))
        .collect();
    assert_eq!(
        found,
        [
            "crate::a::b as b @1",
            "crate::a::b::C as C @1",
            "crate::a::d as e @1",
            "crate::a::f as f @1",
            "super::G as G @2",
            "super::h as h @2",
            "crate::gpu::views::V::new as new @3",
            "winit::window::W as W @3",
            "panel::show as show @3",
        ]
    );
}

#[test]
fn paths_lead_into_the_longest_module_they_name() {
    let module = |s: &str| -> Module {
        s.split("::")
            .filter(|p| !p.is_empty())
            .map(String::from)
            .collect()
    };
    let modules: BTreeMap<Module, String> = [
        "",
        "app",
        "app::bench",
        "app::bench::panel",
        "gpu",
        "gpu::views",
    ]
    .iter()
    .map(|m| (module(m), m.to_string()))
    .collect();
    let root_names = BTreeMap::from([("Gpu".to_string(), module("gpu::Gpu"))]);
    let here = module("app::bench");
    let lead = |p: &str| resolve(&here, &module(p), &modules, &root_names).map(|m| show(&m));
    assert_eq!(
        lead("crate::gpu::views::V::new").as_deref(),
        Some("gpu::views")
    );
    assert_eq!(lead("crate::gpu::f").as_deref(), Some("gpu"));
    assert_eq!(lead("crate::Gpu").as_deref(), Some("gpu"));
    assert_eq!(lead("super::X").as_deref(), Some("app"));
    assert_eq!(lead("panel::show").as_deref(), Some("app::bench::panel"));
    assert_eq!(
        lead("self::panel::show").as_deref(),
        Some("app::bench::panel")
    );
    assert_eq!(lead("views::V"), None, "not a child of app::bench");
    assert_eq!(lead("super::super::super::X"), None, "above the root");
}

#[test]
fn circles_are_found_with_their_modules() {
    let m = |s: &str| -> Module { vec![s.to_string()] };
    let mut edges = Edges::new();
    for (from, to) in [
        ("a", "b"),
        ("b", "c"),
        ("c", "a"),
        ("c", "d"),
        ("d", "e"),
        ("e", "d"),
        ("f", "a"),
    ] {
        edges
            .entry(m(from))
            .or_default()
            .insert(m(to), String::new());
    }
    assert_eq!(
        circles(&edges),
        [vec![m("a"), m("b"), m("c")], vec![m("d"), m("e")]]
    );
    edges.get_mut(&m("c")).unwrap().remove(&m("a"));
    edges.get_mut(&m("e")).unwrap().clear();
    assert!(circles(&edges).is_empty());
}

#[test]
fn functions_are_measured_as_long_functions_py_measures_them() {
    let rust = "trait T {\n    fn declared(&self);\n}\npub(crate) const fn f() {\n    // }\n    if x {\n\
                }\n}\n    pub async unsafe extern \"C\" fn g() { }\nlet fn_ptr = 1;\nfn\nh() {}\n";
    assert_eq!(
        functions(rust, false),
        [(5, 4, "f".to_string()), (1, 9, "g".to_string())]
    );
    let js = "function build(a) {\n  if (a) {\n  }\n}\nasync function () {}\n\
              const run = async (x, y) => {\n};\nlet n = (x) => x + 1;\nconst v = 3;\n";
    assert_eq!(
        functions(js, true),
        [
            (4, 1, "build".to_string()),
            (1, 5, "(anonymous)".to_string()),
            (2, 6, "run".to_string())
        ]
    );
}
