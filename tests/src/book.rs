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
            // Math is `$...$` (mdbook-katex's delimiters): `\(...\)` renders as parentheses.
            if line.contains("\\(") && !line.trim_start().starts_with("{{#") {
                problems.push(format!(
                    "{at}: `\\(` is not math here (write $...$ for inline math)"
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
                let name = image.strip_prefix("images/");
                let from_catalogue = name
                    .and_then(|file| file.strip_suffix(".png"))
                    .is_some_and(catalogued);
                let elsewhere = made_by_another_command(&image).is_some();
                if image.starts_with("images/") && !from_catalogue && !elsewhere {
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
        || crate::stories::STORIES
            .iter()
            .any(|story| story.image_name() == name)
        || PAIRS
            .iter()
            .any(|pair| pair.zoom_name() == name || pair.difference_name() == name)
}

/// The book's pictures of the web edition, and the commands that make them: a lesson's page (in
/// English and in Chinese), a pixel's story in a page, a page on a phone in both languages, and the
/// Chinese book's search.
pub const WEB_PAGE_SHOTS: [(&str, &str); 6] = [
    (
        "images/web/reflect-skull-page.png",
        "cargo web-test --page-screenshot book/src/images/web/reflect-skull-page.png",
    ),
    (
        "images/web/mark-mirror-page-story.png",
        "cargo web-test --story-screenshot book/src/images/web/mark-mirror-page-story.png",
    ),
    (
        "images/web/reflect-skull-page-zh-CN.png",
        "cargo web-test --page-screenshot book/src/images/web/reflect-skull-page-zh-CN.png zh-CN",
    ),
    (
        "images/web/mark-mirror-phone.png",
        "cargo web-test --phone-screenshot book/src/images/web/mark-mirror-phone.png",
    ),
    (
        "images/web/mark-mirror-phone-zh-CN.png",
        "cargo web-test --phone-screenshot book/src/images/web/mark-mirror-phone-zh-CN.png zh-CN",
    ),
    (
        "images/web/search-zh-CN.png",
        "cargo book-test --search-screenshot book/src/images/web/search-zh-CN.png",
    ),
];

/// The command that makes one of the book's images other than the screenshots: the windows'
/// pictures (`images/window/<lesson>.jpg`, and `<lesson>-pixel.jpg` with a pixel picked, by
/// `scripts/window-shots.sh`) and the web edition's page.
pub fn made_by_another_command(image: &str) -> Option<&'static str> {
    let window = image
        .strip_prefix("images/window/")
        .and_then(|file| file.strip_suffix(".jpg"))
        .map(|name| name.strip_suffix("-pixel").unwrap_or(name));
    if window.is_some_and(|lesson| crate::shots::LESSONS.contains(&lesson)) {
        return Some("scripts/window-shots.sh");
    }
    WEB_PAGE_SHOTS
        .iter()
        .find(|(shot, _)| *shot == image)
        .map(|(_, command)| *command)
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

/// One heading of a page and the lines under it, up to the next heading of any level. Lines in
/// fenced code blocks are never headings (a `# comment` in a shell block is not one).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Section {
    /// 1 for `#`, 2 for `##`, ...
    pub level: usize,
    pub title: String,
    pub lines: Vec<String>,
}

/// The sections of a page, in order; what comes before the first heading is a section of level 0
/// with an empty title.
pub fn sections(text: &str) -> Vec<Section> {
    let mut sections = vec![Section {
        level: 0,
        title: String::new(),
        lines: Vec::new(),
    }];
    let mut fence: Option<&str> = None;
    for line in text.lines() {
        let trimmed = line.trim_start();
        let marker = ["```", "~~~"].into_iter().find(|m| trimmed.starts_with(m));
        if let Some(marker) = marker {
            match fence {
                Some(open) if open == marker => fence = None,
                Some(_) => {}
                None => fence = Some(marker),
            }
        } else if fence.is_none() && line.starts_with('#') {
            let level = line.chars().take_while(|&c| c == '#').count();
            if line[level..].starts_with(' ') {
                sections.push(Section {
                    level,
                    title: line[level..].trim().to_string(),
                    lines: Vec::new(),
                });
                continue;
            }
        }
        if let Some(section) = sections.last_mut() {
            section.lines.push(line.to_string());
        }
    }
    sections
}

/// The lines of the section titled `title` (at `level`) and of its subsections; `None` when the page
/// has no such section.
pub fn section_text(text: &str, level: usize, title: &str) -> Option<Vec<String>> {
    let all = sections(text);
    let start = all
        .iter()
        .position(|s| s.level == level && s.title == title)?;
    let mut lines = all[start].lines.clone();
    for section in all[start + 1..].iter().take_while(|s| s.level > level) {
        lines.push(format!("{} {}", "#".repeat(section.level), section.title));
        lines.extend(section.lines.iter().cloned());
    }
    Some(lines)
}

/// The minutes of every speaker-notes summary on a page (`<summary>Speaker notes · N minutes</summary>`),
/// and one problem for each such summary that is malformed.
pub fn speaker_minutes(text: &str) -> Vec<Result<u32, String>> {
    let mut found = Vec::new();
    for line in text.lines() {
        let Some(start) = line.find("<summary>Speaker notes") else {
            continue;
        };
        let rest = &line[start + "<summary>".len()..];
        let parsed = rest
            .strip_prefix("Speaker notes · ")
            .and_then(|r| r.split_once(" minutes</summary>"))
            .and_then(|(n, _)| n.parse::<u32>().ok());
        found.push(parsed.ok_or_else(|| {
            format!(
                "`{}` is not `<summary>Speaker notes · N minutes</summary>`",
                line.trim()
            )
        }));
    }
    found
}

/// One question of a page's "Predict the picture": the command line shown, and the picture its
/// answer shows.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Prediction {
    /// The `cargo run -p ...` line of the shell block before the answer.
    pub command: String,
    /// The target of the first image inside the answer's `<details>`.
    pub image: Option<String>,
}

/// The questions of the page's `## Predict the picture` section: every `<summary>Answer</summary>`,
/// with the last `cargo run` line before it and the first image after it (before `</details>`).
pub fn predictions(text: &str) -> Vec<Prediction> {
    let Some(lines) = section_text(text, 2, "Predict the picture") else {
        return Vec::new();
    };
    let mut found = Vec::new();
    let mut command = String::new();
    let mut answer: Option<Prediction> = None;
    for line in &lines {
        let trimmed = line.trim();
        if trimmed.starts_with("cargo run ") {
            command = trimmed.to_string();
        }
        if trimmed.contains("<summary>Answer</summary>") {
            if let Some(open) = answer.take() {
                found.push(open);
            }
            answer = Some(Prediction {
                command: std::mem::take(&mut command),
                image: None,
            });
        }
        if let Some(open) = answer.as_mut() {
            if open.image.is_none() {
                open.image = images(line).into_iter().next();
            }
            if trimmed.contains("</details>") {
                found.extend(answer.take());
            }
        }
    }
    found.extend(answer);
    found
}

/// A lesson's command line as `(package, options)`: `cargo run -p NAME -- ARGS`, each option paired
/// with its value (`--camera=X` and `--camera X` alike), `--size` and `--screenshot` left out, sorted
/// so that the order of the options does not matter.
pub fn command_options(command: &str) -> Result<(String, Vec<(String, String)>), String> {
    let words: Vec<&str> = command.split_whitespace().collect();
    let (["cargo", "run", "-p", package], rest) = words.split_at(words.len().min(4)) else {
        return Err(format!(
            "`{command}` does not start with `cargo run -p NAME`"
        ));
    };
    let arguments = match rest {
        [] => &[][..],
        ["--", arguments @ ..] => arguments,
        _ => {
            return Err(format!(
                "`{command}`: the lesson's arguments must follow `--`"
            ));
        }
    };
    let mut options = Vec::new();
    let mut words = arguments.iter();
    while let Some(word) = words.next() {
        if !word.starts_with("--") {
            return Err(format!("`{command}`: `{word}` is not an option"));
        }
        let (flag, value) = match word.split_once('=') {
            Some((flag, value)) => (flag.to_string(), value.to_string()),
            None => {
                let value = words
                    .next()
                    .ok_or_else(|| format!("`{command}`: `{word}` has no value"))?;
                (word.to_string(), value.to_string())
            }
        };
        if flag != "--size" && flag != "--screenshot" {
            options.push((flag, value));
        }
    }
    options.sort();
    Ok((package.to_string(), options))
}

/// The options of a screenshot of the catalogue, as [`command_options`] gives them.
pub fn shot_options(shot: &crate::shots::Shot) -> Result<(String, Vec<(String, String)>), String> {
    let arguments = shot.arguments().map_err(|e| format!("{e:#}"))?;
    let command = format!("cargo run -p {} -- {}", shot.lesson, arguments.join(" "));
    command_options(&command)
}

/// One exercise of a page's `## Exercises` section: its heading, and the includes under it (before
/// the next heading).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Exercise {
    pub title: String,
    pub includes: Vec<String>,
}

/// The `### Exercise ...` headings of the page's `## Exercises` section and the includes under each.
pub fn exercises(text: &str) -> Vec<Exercise> {
    let all = sections(text);
    let Some(start) = all
        .iter()
        .position(|s| s.level == 2 && s.title == "Exercises")
    else {
        return Vec::new();
    };
    all[start + 1..]
        .iter()
        .take_while(|s| s.level > 2)
        .filter(|s| s.level == 3 && s.title.starts_with("Exercise"))
        .map(|s| Exercise {
            title: s.title.clone(),
            includes: s.lines.iter().flat_map(|line| includes(line)).collect(),
        })
        .collect()
}

/// One session of the teaching plan: a `### ... (N minutes)` heading and its table of parts.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Session {
    pub title: String,
    /// The minutes the heading names.
    pub minutes: Option<u32>,
    /// Each row but the total: the part's text, the page it links to (`name.md`), its minutes.
    pub parts: Vec<(String, Option<String>, u32)>,
    /// The `**Total**` row.
    pub total: Option<u32>,
}

/// The sessions of the teaching page: every `###` section whose heading ends in `(N minutes)`, with
/// the `| Part | Minutes |` table under it. A row whose minutes do not parse is an error.
pub fn sessions(text: &str) -> Result<Vec<Session>, String> {
    let mut found = Vec::new();
    for section in sections(text) {
        let Some(head) = section.title.strip_suffix(" minutes)") else {
            continue;
        };
        let Some((_, minutes)) = head.rsplit_once('(') else {
            continue;
        };
        let mut session = Session {
            title: section.title.clone(),
            minutes: minutes.trim().parse().ok(),
            parts: Vec::new(),
            total: None,
        };
        for line in &section.lines {
            let cells: Vec<&str> = line
                .trim()
                .trim_matches('|')
                .split('|')
                .map(str::trim)
                .collect();
            if !line.trim_start().starts_with('|') || cells.len() != 2 {
                continue;
            }
            if cells[0] == "Part" || cells[1].starts_with("---") {
                continue;
            }
            let number = cells[1].trim_matches('*');
            let minutes: u32 = number.parse().map_err(|_| {
                format!(
                    "{}: `{}` is not a number of minutes",
                    section.title, cells[1]
                )
            })?;
            if cells[0].trim_matches('*') == "Total" {
                session.total = Some(minutes);
                continue;
            }
            let page = cells[0]
                .split_once("](")
                .and_then(|(_, target)| target.split_once(')'))
                .map(|(target, _)| target.to_string());
            session.parts.push((cells[0].to_string(), page, minutes));
        }
        found.push(session);
    }
    Ok(found)
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
    fn reads_sections_predictions_and_sessions() {
        let page = "# T\n\nintro\n\n```sh\n# not a heading\n```\n\n## Predict the picture\n\n\
                    ```sh\ncargo run -p a -- --set k=v --camera=-1,2,3\n```\n\n\
                    <details><summary>Answer</summary>\n\n![x](images/a.png)\n\n</details>\n\n\
                    ### Sub\n\n```sh\ncargo run -p a\n```\n\n<details><summary>Answer</summary>\n\n\
                    no picture\n\n</details>\n\n## Exercises\n\n### Exercise 1: one\n\n\
                    {{#include ../x/examples/exercise-2-1.rs:solution}}\n\n## Next\n";
        let all = sections(page);
        assert_eq!(all.len(), 7, "{all:?}");
        assert_eq!(all[1].title, "T");
        let predicted = predictions(page);
        assert_eq!(predicted.len(), 2);
        assert_eq!(predicted[0].image.as_deref(), Some("images/a.png"));
        assert_eq!(predicted[1].image, None);
        assert_eq!(predicted[1].command, "cargo run -p a");
        let (package, options) = command_options(&predicted[0].command).unwrap();
        assert_eq!(package, "a");
        let spaced = command_options("cargo run -p a -- --camera -1,2,3 --size 8x8 --set k=v");
        assert_eq!(spaced.unwrap().1, options);
        assert!(command_options("cargo build -p a").is_err());
        let exercises = exercises(page);
        assert_eq!(exercises.len(), 1);
        assert_eq!(
            exercises[0].includes,
            ["include ../x/examples/exercise-2-1.rs:solution"]
        );
        let notes = "<details class=\"speaker-notes\"><summary>Speaker notes · 25 minutes</summary>\n\
                     <summary>Speaker notes · soon</summary>";
        let minutes = speaker_minutes(notes);
        assert_eq!(minutes[0], Ok(25));
        assert!(minutes[1].is_err());
        let plan = "### Day (30 minutes)\n\n| Part | Minutes |\n|---|---|\n| [L](l.md) | 20 |\n\
                    | Break | 10 |\n| **Total** | **30** |\n";
        let sessions = sessions(plan).unwrap();
        assert_eq!(sessions[0].minutes, Some(30));
        assert_eq!(sessions[0].total, Some(30));
        assert_eq!(sessions[0].parts[0].1.as_deref(), Some("l.md"));
        assert_eq!(sessions[0].parts[1], ("Break".to_string(), None, 10));
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
