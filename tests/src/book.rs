//! Checks on the book's sources that mdBook does not make: mdBook prints an empty block for an
//! `{{#include file:anchor}}` whose anchor is missing, and the rest of the file when `ANCHOR_END` is
//! missing, without failing. Every screenshot it shows must come from the catalogue.

use std::path::{Path, PathBuf};

/// Every problem in the Markdown files under `src`, one line each.
pub fn problems(src: &Path) -> Vec<String> {
    let mut problems = Vec::new();
    for page in markdown_files(src) {
        let text = match std::fs::read_to_string(&page) {
            Ok(text) => text,
            Err(error) => {
                problems.push(format!("{}: cannot read: {error}", page.display()));
                continue;
            }
        };
        let dir = page.parent().unwrap_or(src);
        for (line_number, line) in text.lines().enumerate() {
            let at = format!("{}:{}", page.display(), line_number + 1);
            // A tab in a page is almost always a `\t` that lost its backslash (`\text` in math).
            if line.contains('\t') {
                problems.push(format!(
                    "{at}: a tab character (a lost backslash, as in \\text?)"
                ));
            }
            for include in includes(line) {
                if let Err(problem) = check_include(dir, &include) {
                    problems.push(format!("{at}: {{{{#{include}}}}}: {problem}"));
                }
            }
            for image in images(line) {
                let path = dir.join(&image);
                if !path.exists() {
                    problems.push(format!("{at}: image {image} does not exist"));
                }
                let name = Path::new(&image).file_stem().and_then(|s| s.to_str());
                let from_catalogue = name.is_some_and(catalogued);
                if image.starts_with("images/") && !from_catalogue {
                    problems.push(format!(
                        "{at}: image {image} is not made by `cargo screenshots` (add it to the catalogue)"
                    ));
                }
            }
        }
    }
    problems
}

/// Whether `cargo screenshots` makes the image `images/<name>.png`: a screenshot, or a pair's
/// enlarged crop or difference image. (The step strips' images are in the strips' HTML.)
fn catalogued(name: &str) -> bool {
    use crate::shots::{PAIRS, SHOTS};
    SHOTS.iter().any(|shot| shot.name == name)
        || PAIRS
            .iter()
            .any(|pair| pair.zoom_name() == name || pair.difference_name() == name)
}

fn markdown_files(dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return files;
    };
    let mut entries: Vec<_> = entries.flatten().map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files.extend(markdown_files(&path));
        } else if path.extension().is_some_and(|e| e == "md") {
            files.push(path);
        }
    }
    files
}

/// The `include ...` / `rustdoc_include ...` directives on a line, without the braces.
fn includes(line: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = line;
    while let Some(start) = rest.find("{{#") {
        let after = &rest[start + 3..];
        let Some(end) = after.find("}}") else { break };
        let directive = after[..end].trim();
        if directive.starts_with("include ") || directive.starts_with("rustdoc_include ") {
            found.push(directive.to_string());
        }
        rest = &after[end + 2..];
    }
    found
}

/// The targets of `![alt](target)` on a line.
fn images(line: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = line;
    while let Some(start) = rest.find("![") {
        let after = &rest[start + 2..];
        let Some(close) = after.find("](") else { break };
        let target = &after[close + 2..];
        let Some(end) = target.find(')') else { break };
        found.push(target[..end].trim().to_string());
        rest = &target[end..];
    }
    found
}

/// Checks one directive: the file exists; a named anchor has both `ANCHOR:` and `ANCHOR_END:` lines,
/// in that order, with something between them; a line range lies inside the file.
fn check_include(dir: &Path, directive: &str) -> Result<(), String> {
    let argument = directive
        .split_once(' ')
        .map(|(_, a)| a.trim())
        .unwrap_or("");
    let mut parts = argument.splitn(2, ':');
    let file = parts.next().unwrap_or("");
    let selector = parts.next();
    let path = dir.join(file);
    let text = std::fs::read_to_string(&path)
        .map_err(|error| format!("cannot read {}: {error}", path.display()))?;
    let Some(selector) = selector else {
        return Ok(());
    };
    let lines: Vec<&str> = text.lines().collect();
    if selector
        .chars()
        .next()
        .is_some_and(|c| c.is_ascii_digit() || c == ':')
    {
        let numbers: Vec<usize> = selector
            .split(':')
            .filter(|s| !s.is_empty())
            .map(|s| {
                s.parse()
                    .map_err(|_| format!("bad line range `{selector}`"))
            })
            .collect::<Result<_, _>>()?;
        if numbers.iter().any(|&n| n == 0 || n > lines.len()) {
            return Err(format!(
                "line range `{selector}` is outside the file ({} lines)",
                lines.len()
            ));
        }
        return Ok(());
    }
    let marker = |kind: &str| {
        lines.iter().position(|line| {
            line.trim_end()
                .strip_suffix(selector)
                .is_some_and(|head| head.trim_end().ends_with(kind))
        })
    };
    let start = marker("ANCHOR:").ok_or_else(|| format!("anchor `{selector}` is missing"))?;
    let end = marker("ANCHOR_END:").ok_or_else(|| format!("ANCHOR_END: {selector} is missing"))?;
    if end <= start + 1 {
        return Err(format!(
            "anchor `{selector}` is empty or ends before it starts"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_directives_and_images() {
        assert_eq!(
            includes("a {{#include ../x.rs:knobs}} b {{#title t}} {{#rustdoc_include y.rs}}"),
            ["include ../x.rs:knobs", "rustdoc_include y.rs"]
        );
        assert_eq!(
            images("![a](images/x.png) and ![b](y.png)"),
            ["images/x.png", "y.png"]
        );
    }

    #[test]
    fn catches_missing_files_anchors_and_ends() {
        let dir = std::env::temp_dir().join(format!("book-check-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("code.rs"),
            "// ANCHOR: good\nfn a() {}\n// ANCHOR_END: good\n// ANCHOR: open\nfn b() {}\n",
        )
        .unwrap();
        assert!(check_include(&dir, "include code.rs:good").is_ok());
        assert!(check_include(&dir, "include code.rs").is_ok());
        assert!(check_include(&dir, "include code.rs:2:3").is_ok());
        assert!(check_include(&dir, "include code.rs:9").is_err());
        assert!(
            check_include(&dir, "include code.rs:missing")
                .unwrap_err()
                .contains("missing")
        );
        assert!(
            check_include(&dir, "include code.rs:open")
                .unwrap_err()
                .contains("ANCHOR_END")
        );
        assert!(check_include(&dir, "include nothing.rs:good").is_err());
        // "good" must not match the anchor "not-good".
        std::fs::write(
            dir.join("other.rs"),
            "// ANCHOR: not-good\nx\n// ANCHOR_END: not-good\n",
        )
        .unwrap();
        assert!(check_include(&dir, "include other.rs:good").is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
