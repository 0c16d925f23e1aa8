//! Reads the lessons from this crate's Cargo.toml, the lines `NAME = { path = "../NN-NAME" }` of its
//! `[dependencies]` in the book's order, and writes them for `src/lib.rs` as one call of its
//! `lessons!` macro: each lesson's name, crate, type and exercise solutions.
//!
//! The file is read line by line (a TOML parser would lose the order of the table's keys, which is
//! the book's order, or be one more dependency for a dozen lines).

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    println!("cargo::rerun-if-changed=Cargo.toml");
    let dir = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let dir = Path::new(&dir);
    let manifest =
        std::fs::read_to_string(dir.join("Cargo.toml")).expect("chapters/lessons/Cargo.toml");
    let mut out = String::from("lessons! {\n");
    let chapters = dir.parent().expect("chapters/");
    for (name, folder) in
        lessons(&manifest).unwrap_or_else(|e| panic!("chapters/lessons/Cargo.toml: {e}"))
    {
        let folder = chapters.join(folder);
        // A lesson's exercises come and go with its folder's files.
        println!("cargo::rerun-if-changed={}", folder.display());
        let exercises = exercises(&folder.join("examples"))
            .unwrap_or_else(|e| panic!("{}: {e}", folder.display()));
        let krate = name.replace('-', "_");
        let lesson: String = name.split('-').map(upper_first).collect();
        write!(out, "    {name:?} {krate} {lesson} [").unwrap();
        for (number, file) in exercises {
            write!(
                out,
                " exercise_{number} {:?}",
                file.to_str().expect("a UTF-8 path")
            )
            .unwrap();
        }
        out += " ],\n";
    }
    out += "}\n";
    let generated =
        Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("lessons.rs");
    std::fs::write(&generated, out).expect("the generated list of lessons");
}

/// The lessons of the manifest's `[dependencies]`, in order: each name and its folder in chapters/
/// (`NN-NAME`).
/// A dependency given by `path` is a lesson, and must be written as one.
fn lessons(manifest: &str) -> Result<Vec<(String, String)>, String> {
    let mut lines = manifest.lines().enumerate();
    lines
        .by_ref()
        .find(|(_, line)| line.trim() == "[dependencies]")
        .ok_or("no [dependencies]")?;
    let mut lessons = Vec::new();
    for (index, line) in lines {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.starts_with('[') {
            break;
        }
        if !line.contains("path") {
            continue;
        }
        let lesson = lesson(line).ok_or_else(|| {
            format!(
                "line {}: `{line}` is not a lesson's line, `NAME = {{ path = \"../NN-NAME\" }}`",
                index + 1
            )
        })?;
        lessons.push(lesson);
    }
    Ok(lessons)
}

/// `NAME = { path = "../NN-NAME" }`: the name and the folder, `NN-NAME`.
fn lesson(line: &str) -> Option<(String, String)> {
    let (name, value) = line.split_once('=')?;
    let name = name.trim();
    let value = value.trim().strip_prefix('{')?.strip_suffix('}')?;
    let (key, folder) = value.split_once('=')?;
    let folder = folder.trim().strip_prefix('"')?.strip_suffix('"')?;
    let folder = folder.strip_prefix("../")?;
    let (number, folder_name) = folder.split_once('-')?;
    let fits = key.trim() == "path"
        && number.len() == 2
        && number.bytes().all(|b| b.is_ascii_digit())
        && folder_name == name
        && !name.is_empty()
        && name
            .bytes()
            .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-');
    fits.then(|| (name.to_string(), folder.to_string()))
}

/// The solutions in `examples`, `exercise-N-K.rs`, by K.
fn exercises(examples: &Path) -> Result<Vec<(u32, std::path::PathBuf)>, String> {
    let mut exercises = Vec::new();
    let Ok(entries) = std::fs::read_dir(examples) else {
        return Ok(exercises);
    };
    for entry in entries {
        let path = entry.map_err(|e| e.to_string())?.path();
        let Some(stem) = path
            .file_name()
            .and_then(|n| n.to_str()?.strip_suffix(".rs"))
        else {
            continue;
        };
        let Some(numbers) = stem.strip_prefix("exercise-") else {
            continue;
        };
        let number = numbers
            .split_once('-')
            .and_then(|(_, k)| k.parse().ok())
            .ok_or_else(|| format!("{}: not named exercise-N-K.rs", path.display()))?;
        exercises.push((number, path));
    }
    exercises.sort();
    if let Some(twice) = exercises.windows(2).find(|pair| pair[0].0 == pair[1].0) {
        return Err(format!("two exercises numbered {}", twice[0].0));
    }
    Ok(exercises)
}

fn upper_first(word: &str) -> String {
    let mut chars = word.chars();
    chars
        .next()
        .map(|first| first.to_ascii_uppercase().to_string() + chars.as_str())
        .unwrap_or_default()
}
