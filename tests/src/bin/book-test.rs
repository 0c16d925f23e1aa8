//! `cargo book-test [--screenshots DIR]`: the built book's translations in headless Chromium.
//!
//! Serves the built book (`book/build.sh` first) on 127.0.0.1 and opens every page in English and
//! in each translation (`book/build/html/<language>/`), as a reader's browser draws them. Each
//! translated page must:
//!
//! - render its math: no KaTeX error, and as many formulas as the English page;
//! - show its listings: the same code blocks as the English page, character for character but
//!   for the comments of commands (`cargo run  # a window`), which are prose; the included listings
//!   are included after translation: they are the real code in every language;
//! - show its figures: as many images as the English page, every one loaded;
//! - be in its language: `<html lang>` says so, and its text is (Chinese characters in the page);
//! - link the glossary only to terms it has.
//!
//! Then, on a lesson page, the language picker in the menu bar goes to the same page in the other
//! language and back, and the search speaks the page's language: it finds an English word, and
//! where mdBook's search cannot find a Chinese word (it splits the text at spaces) it says what to
//! use instead. `--screenshots DIR` writes the picker open on both (default:
//! `target/book-test/`).

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, Result, bail};
use clap::Parser;
use workbook_tests::browser::{self, BookPage, WebBackend, WebBrowser};
use workbook_tests::workspace;

#[derive(Parser)]
#[command(
    name = "book-test",
    about = "The built book's translations in headless Chromium"
)]
struct Args {
    /// Where to write the language picker's screenshots.
    #[arg(long, value_name = "DIR")]
    screenshots: Option<PathBuf>,
}

/// The translations `book/build.sh` builds, with the characters their text must show (CJK).
const TRANSLATIONS: [(&str, std::ops::RangeInclusive<char>); 1] =
    [("zh-CN", '\u{4e00}'..='\u{9fff}')];

/// The lesson page the picker is tried on.
const PICKER_PAGE: &str = "mark-mirror.html";

/// What a page shows, as the browser drew it (one line of JSON from `INSPECT`).
const INSPECT: &str = r#"new Promise((resolve) => {
    const images = [...document.querySelectorAll('main img')];
    Promise.all(images.map((i) => i.complete ? null :
        new Promise((r) => { i.addEventListener('load', r); i.addEventListener('error', r); })))
    .then(() => resolve(JSON.stringify({
        lang: document.documentElement.lang,
        katexErrors: document.querySelectorAll('.katex-error').length,
        formulas: document.querySelectorAll('main .katex').length,
        listings: [...document.querySelectorAll('main pre code')].map((c) => c.textContent),
        images: images.map((i) => [i.getAttribute('src'), i.naturalWidth > 0]),
        text: document.querySelector('main').innerText,
        glossary: [...document.querySelectorAll('main a[href*="glossary.html#"]')]
            .map((a) => a.getAttribute('href').split('#')[1]),
        ids: [...document.querySelectorAll('[id]')].map((e) => e.id),
    })));
})"#;

struct Shown {
    lang: String,
    katex_errors: usize,
    formulas: usize,
    listings: Vec<String>,
    /// Each image's `src`, and whether it loaded.
    images: Vec<(String, bool)>,
    text: String,
    glossary: Vec<String>,
    ids: Vec<String>,
}

fn inspect(page: &BookPage) -> Result<Shown> {
    use serde_json::Value;
    let json = page.evaluate(INSPECT)?;
    let value: Value =
        serde_json::from_str(&json).with_context(|| format!("the page said {json:.200}"))?;
    let text = |key: &str| value[key].as_str().unwrap_or_default().to_string();
    let count = |key: &str| value[key].as_u64().unwrap_or_default() as usize;
    let texts = |key: &str| -> Vec<String> {
        value[key]
            .as_array()
            .map(|items| {
                items
                    .iter()
                    .map(|item| item.as_str().unwrap_or_default().to_string())
                    .collect()
            })
            .unwrap_or_default()
    };
    let images = value["images"]
        .as_array()
        .map(|items| {
            items
                .iter()
                .map(|pair| {
                    let src = pair[0].as_str().unwrap_or_default().to_string();
                    (src, pair[1].as_bool().unwrap_or(false))
                })
                .collect()
        })
        .unwrap_or_default();
    Ok(Shown {
        lang: text("lang"),
        katex_errors: count("katexErrors"),
        formulas: count("formulas"),
        listings: texts("listings"),
        images,
        text: text("text"),
        glossary: texts("glossary"),
        ids: texts("ids"),
    })
}

fn main() -> ExitCode {
    match run() {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::FAILURE,
        Err(error) => {
            eprintln!("book-test: {error:#}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<bool> {
    let args = Args::parse();
    let root = workspace();
    let site_root = root.join("book/build/html");
    // The book's pages, in the order of the English build (every chapter, and the print page).
    let mut pages: Vec<String> = std::fs::read_dir(&site_root)
        .with_context(|| format!("no book in {}: run book/build.sh", site_root.display()))?
        .filter_map(|entry| entry.ok()?.file_name().into_string().ok())
        .filter(|name| name.ends_with(".html") && !matches!(name.as_str(), "404.html" | "toc.html"))
        .collect();
    pages.sort();
    let site = browser::serve(&site_root)?;
    let chrome = WebBrowser::launch(WebBackend::WebGl2)?;
    let mut failures = Vec::new();
    for (language, script) in &TRANSLATIONS {
        if !site_root.join(language).join("index.html").exists() {
            bail!(
                "no {language} book in {}: run book/build.sh",
                site_root.display()
            );
        }
        let glossary = inspect(&chrome.page(&format!("{site}/{language}/glossary.html"))?)?.ids;
        let (mut formulas, mut listings, mut images) = (0, 0, 0);
        for page in &pages {
            let english = inspect(&chrome.page(&format!("{site}/{page}"))?)?;
            let translated = inspect(&chrome.page(&format!("{site}/{language}/{page}"))?)?;
            let mut fail = |what: String| failures.push(format!("{language}/{page}: {what}"));
            if translated.lang != *language {
                fail(format!("<html lang=\"{}\">", translated.lang));
            }
            if !translated.text.chars().any(|c| script.contains(&c)) {
                fail(format!("no {language} text in the page"));
            }
            if translated.katex_errors > 0 {
                fail(format!("{} KaTeX errors", translated.katex_errors));
            }
            if translated.formulas != english.formulas {
                fail(format!(
                    "{} formulas, the English page {}",
                    translated.formulas, english.formulas
                ));
            }
            if comments_aside(&translated.listings) != comments_aside(&english.listings) {
                let first = translated
                    .listings
                    .iter()
                    .zip(&english.listings)
                    .position(|(a, b)| a != b);
                fail(format!(
                    "its listings differ from the English page's ({} against {}; first different: {first:?})",
                    translated.listings.len(),
                    english.listings.len()
                ));
            }
            if translated.images.len() != english.images.len() {
                fail(format!(
                    "{} images, the English page {}",
                    translated.images.len(),
                    english.images.len()
                ));
            }
            for (src, loaded) in &translated.images {
                if !loaded {
                    fail(format!("the image {src} did not load"));
                }
            }
            for id in &translated.glossary {
                if !glossary.contains(id) {
                    fail(format!(
                        "a link to glossary.html#{id}, which has no such term"
                    ));
                }
            }
            formulas += translated.formulas;
            listings += translated.listings.len();
            images += translated.images.len();
        }
        println!(
            "{language}: {} pages, {formulas} formulas, {listings} listings and {images} images as in English",
            pages.len()
        );
        picker(&chrome, &site, language, &args, &mut failures)?;
        search(&chrome, &site, language, &mut failures)?;
    }
    for failure in &failures {
        eprintln!("book-test: {failure}");
    }
    if failures.is_empty() {
        println!("book-test: every translated page renders its math, listings and figures");
    }
    Ok(failures.is_empty())
}

/// The search box of a translated lesson page, asked for an English word and for a Chinese one
/// (through `?search=`, as mdBook's own links to results do): its results header, in the page's
/// language.
fn search(
    chrome: &WebBrowser,
    site: &str,
    language: &str,
    failures: &mut Vec<String>,
) -> Result<()> {
    // What the header must say: results for an English word; for a word inside Chinese sentences,
    // none, and the way to find it (the print page and the browser's find).
    let cases = [("stencil", "找到"), ("模板缓冲区", "Ctrl+F")];
    for (term, expected) in cases {
        let query: String = term.bytes().map(|b| format!("%{b:02X}")).collect();
        let page = chrome.page(&format!("{site}/{language}/{PICKER_PAGE}?search={query}"))?;
        let header = page.evaluate(
            r"new Promise((resolve) => {
                 const t0 = performance.now();
                 (function poll() {
                     const h = document.getElementById('mdbook-searchresults-header');
                     const text = h ? h.textContent : '';
                     if (/[\u4e00-\u9fff]/.test(text) || performance.now() - t0 > 20000) resolve(text);
                     else setTimeout(poll, 50);
                 })();
             })",
        )?;
        if !header.contains(expected) {
            failures.push(format!(
                "{language}/{PICKER_PAGE}?search={term}: the results header says {header:?}"
            ));
        } else {
            println!("search for {term:?}: {header}");
        }
    }
    Ok(())
}

/// The listings with their shell comments taken out: a command's comment (`cargo run  # a window`)
/// is prose, and translated; the commands and the included code are not.
fn comments_aside(listings: &[String]) -> Vec<String> {
    listings
        .iter()
        .map(|listing| {
            listing
                .lines()
                .map(|line| match line.find(" # ") {
                    Some(at) => line[..at].trim_end(),
                    None => line,
                })
                .collect::<Vec<_>>()
                .join("\n")
        })
        .collect()
}

/// The language picker on a lesson page: English → `language` → English, the same page each time,
/// with a screenshot of the picker open on both.
fn picker(
    chrome: &WebBrowser,
    site: &str,
    language: &str,
    args: &Args,
    failures: &mut Vec<String>,
) -> Result<()> {
    let dir = args
        .screenshots
        .clone()
        .unwrap_or_else(|| workspace().join("target/book-test"));
    std::fs::create_dir_all(&dir)?;
    let page = chrome.page(&format!("{site}/{PICKER_PAGE}"))?;
    let steps = [("en", language), (language, "en")];
    for (from, to) in steps {
        let opened = page.evaluate(
            "(() => { const b = document.getElementById('language-toggle');
                      if (!b) return 'no language picker in the menu bar';
                      b.click();
                      const list = document.getElementById('language-list');
                      return getComputedStyle(list).display === 'none' ? 'the list did not open' : 'ok'; })()",
        )?;
        if opened != "ok" {
            failures.push(format!("{from} {PICKER_PAGE}: {opened}"));
            return Ok(());
        }
        let shot = dir.join(format!("picker-{from}.png"));
        std::fs::write(&shot, page.screenshot()?)?;
        println!("wrote {}", shot.display());
        let now = page.follow(&format!(
            "document.querySelector('#language-list a[lang=\"{to}\"]').click()"
        ))?;
        let expected = match to {
            "en" => format!("{site}/{PICKER_PAGE}"),
            _ => format!("{site}/{to}/{PICKER_PAGE}"),
        };
        let lang = page.evaluate("document.documentElement.lang")?;
        if now != expected || lang != to {
            failures.push(format!(
                "the picker on the {from} {PICKER_PAGE} led to {now} (lang {lang}), not {expected}"
            ));
            return Ok(());
        }
    }
    println!("the picker: {PICKER_PAGE} → {language} → English, the same page each time");
    Ok(())
}
