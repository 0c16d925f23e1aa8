//! `cargo book-test [--screenshots DIR]`: the built book's translations in headless Chromium.
//!
//! Serves the built book (`book/build.sh` first) on 127.0.0.1 and opens every page in English and
//! in each translation (`book/build/html/<language>/`), as a reader's browser draws them. Each
//! translated page must:
//!
//! - render its math: no KaTeX error, and the English page's formulas, paragraph by paragraph (a
//!   translated sentence may put its formulas in another order), so that a formula changed in
//!   translation is found (see [`Formula`]);
//! - show its listings: the same code blocks as the English page, character for character but
//!   for the comments of commands (`cargo run  # a window`), which are prose; the included listings
//!   are included after translation: they are the real code in every language;
//! - show its figures: as many images as the English page, every one loaded;
//! - be in its language: `<html lang>` says so, and its text is (Chinese characters in the page);
//! - link the glossary only to terms it has.
//!
//! The English pages are held to their Markdown: where a page's source in `book/src` has math (read
//! there, not from what KaTeX made of it: `$$`, or a `$...$` outside code), the page must show
//! formulas, so a book built without KaTeX fails rather than compare nothing with nothing.
//!
//! Then, on a lesson page, the language picker in the menu bar goes to the same page in the other
//! language and back, and the search speaks the page's language and finds it, as a reader asks it
//! (`?search=`):
//!
//! - in a translation, an English word finds pages, under a results header in the page's language,
//!   and a word that is nowhere gets the page's own "nothing found";
//! - in Chinese, the index holds the text's pairs of characters (`book/po/cjk-search.py`, which
//!   `book/build.sh` runs: an index without them fails here), and 模板缓冲区, 反射矩阵, 环绕顺序, the
//!   mixed "stencil 掩码" and the one character 镜 each find the page they name among the first
//!   results, the first result holding every word asked (see [`CHINESE_SEARCHES`]); also when the
//!   index came, and was searched, before `book/web/search.js` (which cuts the query into the same
//!   pairs) ran;
//! - English search is what mdBook made it: in every book, each of a dozen English queries gives the
//!   same results, pages, order and scores, through `web/search.js`'s tokenizer and pipeline as
//!   through elasticlunr's own (see [`ENGLISH_SEARCHES`]).
//!
//! `--screenshots DIR` writes the picker open on both books, and the Chinese search's results for
//! 模板缓冲区 (`search-zh.png`) (default: `target/book-test/`); `--search-screenshot FILE` writes
//! only the latter, for the book.

use std::path::{Path, PathBuf};
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
    /// Where to write the screenshots: the language picker, and the Chinese search's results.
    #[arg(long, value_name = "DIR")]
    screenshots: Option<PathBuf>,
    /// Only write the book's picture of the Chinese search (its results for 模板缓冲区) to FILE.
    #[arg(long, value_name = "FILE")]
    search_screenshot: Option<PathBuf>,
}

/// The translations `book/build.sh` builds, with the characters their text must show (CJK).
const TRANSLATIONS: [(&str, std::ops::RangeInclusive<char>); 1] =
    [("zh-CN", '\u{4e00}'..='\u{9fff}')];

/// The lesson page the picker is tried on.
const PICKER_PAGE: &str = "mark-mirror.html";

/// What a page shows, as the browser drew it (one line of JSON from `INSPECT`).
const INSPECT: &str = r#"new Promise((resolve) => {
    const paragraphs = new Map();
    const images = [...document.querySelectorAll('main img')];
    Promise.all(images.map((i) => i.complete ? null :
        new Promise((r) => { i.addEventListener('load', r); i.addEventListener('error', r); })))
    .then(() => resolve(JSON.stringify({
        lang: document.documentElement.lang,
        katexErrors: document.querySelectorAll('.katex-error').length,
        formulas: [...document.querySelectorAll('main .katex')].map((k) => {
            const tex = k.querySelector('annotation[encoding="application/x-tex"]');
            const source = k.closest('data.katex-src');
            const html = k.querySelector('.katex-html') || k;
            const paragraph = k.closest('p, li, td, th, h1, h2, h3, h4, h5, h6, dt, dd, figcaption, summary') || k;
            if (!paragraphs.has(paragraph)) paragraphs.set(paragraph, paragraphs.size);
            return [tex ? tex.textContent : source ? source.value : html.textContent, html.innerHTML,
                    paragraphs.get(paragraph)];
        }),
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
    /// The page's formulas, in order.
    formulas: Vec<Formula>,
    listings: Vec<String>,
    /// Each image's `src`, and whether it loaded.
    images: Vec<(String, bool)>,
    text: String,
    glossary: Vec<String>,
    ids: Vec<String>,
}

/// A formula as KaTeX drew it into a page. The book's KaTeX writes HTML alone (mdbook-katex's
/// default output), which keeps no TeX: the formula is compared by its HTML, which the same TeX
/// always makes alike, and named by its TeX where the page keeps it (KaTeX's MathML annotation, or
/// mdbook-katex's `include-src`), else by its text as drawn (`d(z)`).
#[derive(Debug, Clone)]
struct Formula {
    /// Its TeX, or its text as drawn.
    name: String,
    /// The HTML KaTeX made of it.
    html: String,
    /// Which of the page's paragraphs (or list items, table cells, headings) it is in, counted
    /// from 0 in the page's order.
    paragraph: u64,
}

impl Formula {
    /// Whether `other` is this formula: the same name and the same HTML, wherever it stands.
    fn same(&self, other: &Formula) -> bool {
        self.name == other.name && self.html == other.html
    }
}

/// What `page` shows (see [`INSPECT`]). A key missing from what the page said, or of another type,
/// is an error, not an empty value: an empty value would pass for an empty page.
fn inspect(page: &BookPage) -> Result<Shown> {
    use serde_json::Value;
    let json = page.evaluate(INSPECT)?;
    let value: Value =
        serde_json::from_str(&json).with_context(|| format!("the page said {json:.200}"))?;
    let field = |key: &str| -> Result<&Value> {
        value
            .get(key)
            .with_context(|| format!("the page's inspection has no `{key}`: {json:.200}"))
    };
    let text = |item: &Value, what: &str| -> Result<String> {
        item.as_str()
            .map(str::to_string)
            .with_context(|| format!("{what} is {item}, not text"))
    };
    let list = |key: &str| -> Result<&Vec<Value>> {
        field(key)?
            .as_array()
            .with_context(|| format!("`{key}` is not a list"))
    };
    let texts = |key: &str| -> Result<Vec<String>> {
        list(key)?
            .iter()
            .enumerate()
            .map(|(index, item)| text(item, &format!("`{key}` {}", index + 1)))
            .collect()
    };
    let images = list("images")?
        .iter()
        .map(|pair| {
            let loaded = pair[1]
                .as_bool()
                .context("an image's `loaded` is not true or false");
            Ok((text(&pair[0], "an image's src")?, loaded?))
        })
        .collect::<Result<_>>()?;
    let formulas = list("formulas")?
        .iter()
        .map(|pair| {
            Ok(Formula {
                name: text(&pair[0], "a formula's TeX")?,
                html: text(&pair[1], "a formula's HTML")?,
                paragraph: pair[2]
                    .as_u64()
                    .context("a formula's paragraph is not a number")?,
            })
        })
        .collect::<Result<_>>()?;
    let katex_errors = field("katexErrors")?
        .as_u64()
        .context("`katexErrors` is not a count")?;
    Ok(Shown {
        lang: text(field("lang")?, "`lang`")?,
        katex_errors: katex_errors as usize,
        formulas,
        listings: texts("listings")?,
        images,
        text: text(field("text")?, "`text`")?,
        glossary: texts("glossary")?,
        ids: texts("ids")?,
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
    let shots = (args.screenshots.clone()).unwrap_or_else(|| root.join("target/book-test"));
    std::fs::create_dir_all(&shots)?;
    let site = browser::serve(&site_root)?;
    let chrome = WebBrowser::launch(WebBackend::WebGl2)?;
    if let Some(file) = &args.search_screenshot {
        let at = format!("zh-CN/{PICKER_PAGE}");
        let (page, found) = searched(&chrome, &site, &at, CHINESE_SEARCHES[0].0)?;
        if found.results.is_empty() {
            bail!("{at}: no results for {}", CHINESE_SEARCHES[0].0);
        }
        std::fs::write(file, page.screenshot()?)
            .with_context(|| format!("cannot write {}", file.display()))?;
        println!("book-test: wrote {}", file.display());
        return Ok(true);
    }
    let mut failures = Vec::new();
    let english = (pages.iter())
        .map(|page| inspect(&chrome.page(&format!("{site}/{page}"))?))
        .collect::<Result<Vec<_>>>()?;
    let with_math = math_as_in_source(&root.join("book/src"), &pages, &english, &mut failures)?;
    println!(
        "English: {with_math} of {} pages have math in their source (book/src), {} formulas in all",
        pages.len(),
        english
            .iter()
            .map(|shown| shown.formulas.len())
            .sum::<usize>()
    );
    for (language, script) in &TRANSLATIONS {
        if !site_root.join(language).join("index.html").exists() {
            bail!(
                "no {language} book in {}: run book/build.sh",
                site_root.display()
            );
        }
        let glossary = inspect(&chrome.page(&format!("{site}/{language}/glossary.html"))?)?.ids;
        let (mut formulas, mut listings, mut images) = (0, 0, 0);
        for (page, english) in pages.iter().zip(&english) {
            let translated = inspect(&chrome.page(&format!("{site}/{language}/{page}"))?)?;
            let mut fail = |what: String| failures.push(format!("{language}/{page}: {what}"));
            if translated.lang != *language {
                fail(format!("<html lang=\"{}\">", translated.lang));
            }
            if !translated.text.chars().any(|c| script.contains(&c)) {
                fail(format!("no {language} text in the page"));
            }
            compare_page(english, &translated, &glossary, &mut fail);
            formulas += translated.formulas.len();
            listings += translated.listings.len();
            images += translated.images.len();
        }
        println!(
            "{language}: {} pages, {formulas} formulas (compared paragraph by paragraph), {listings} listings and {images} images as in English",
            pages.len()
        );
        picker(&chrome, &site, language, &shots, &mut failures)?;
        search(&chrome, &site, language, &shots, &mut failures)?;
        english_search_unchanged(&chrome, &site, &format!("{language}/"), &mut failures)?;
    }
    english_search_unchanged(&chrome, &site, "", &mut failures)?;
    for failure in &failures {
        eprintln!("book-test: {failure}");
    }
    if failures.is_empty() {
        println!(
            "book-test: every translated page renders its math, listings and figures, and the search finds both languages"
        );
    }
    Ok(failures.is_empty())
}

/// A translated page against its English page: its math (no KaTeX error, the same formulas), its
/// listings, its figures (as many, every one loaded) and its links into the glossary (whose terms
/// are `glossary`). Each fault goes to `fail`.
fn compare_page(
    english: &Shown,
    translated: &Shown,
    glossary: &[String],
    fail: &mut impl FnMut(String),
) {
    if translated.katex_errors > 0 {
        fail(format!("{} KaTeX errors", translated.katex_errors));
    }
    if let Some(difference) = formulas_differ(&english.formulas, &translated.formulas) {
        fail(difference);
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
}

/// A page's formulas by paragraph: those of each paragraph that has any, in the page's order,
/// each with its number in the page (from 0).
fn by_paragraph(formulas: &[Formula]) -> Vec<Vec<(usize, &Formula)>> {
    let mut paragraphs: Vec<Vec<(usize, &Formula)>> = Vec::new();
    for (index, formula) in formulas.iter().enumerate() {
        match paragraphs.last_mut() {
            Some(last) if last[0].1.paragraph == formula.paragraph => last.push((index, formula)),
            _ => paragraphs.push(vec![(index, formula)]),
        }
    }
    paragraphs
}

/// Where a translated page's formulas part from the English page's, if they do. Compared paragraph
/// by paragraph, each paragraph's formulas in any order (a translated sentence may put them in
/// another): the first formula of the English page that its translated paragraph lacks, by its
/// number, and what that paragraph has instead; else the counts.
fn formulas_differ(english: &[Formula], translated: &[Formula]) -> Option<String> {
    let (in_english, in_translation) = (by_paragraph(english), by_paragraph(translated));
    let of = english.len();
    for (mine, yours) in in_english.iter().zip(&in_translation) {
        let count = |list: &[(usize, &Formula)], formula: &Formula| {
            list.iter().filter(|(_, other)| other.same(formula)).count()
        };
        let differs =
            |(_, formula): &&(usize, &Formula)| count(mine, formula) != count(yours, formula);
        let lost = mine.iter().find(differs);
        let found = yours.iter().find(differs);
        let difference = match (lost, found) {
            (None, None) => continue,
            (Some((index, ours)), Some((_, theirs))) if ours.name == theirs.name => format!(
                "formula {} of {of}, {:?}, is drawn otherwise than the English page's",
                index + 1,
                ours.name
            ),
            (Some((index, ours)), Some((_, theirs))) => format!(
                "formula {} of {of} is {:?}, the English page's {:?}",
                index + 1,
                theirs.name,
                ours.name
            ),
            (Some((index, ours)), None) => format!(
                "formula {} of {of}, {:?}, is missing from its paragraph",
                index + 1,
                ours.name
            ),
            (None, Some((_, theirs))) => format!(
                "the paragraph of formula {} of {of} has one more, {:?}",
                mine[0].0 + 1,
                theirs.name
            ),
        };
        return Some(difference);
    }
    (in_english.len() != in_translation.len() || english.len() != translated.len()).then(|| {
        format!(
            "{} formulas in {} paragraphs, the English page {of} in {}",
            translated.len(),
            in_translation.len(),
            in_english.len()
        )
    })
}

/// Holds the English pages to their Markdown in `src` (`book/src`): a page whose source has math
/// must show formulas, or a book built without KaTeX would compare no formulas with none and pass.
/// A page `NAME.html` is `NAME.md`, `index.html` the first chapter of `SUMMARY.md`, `print.html`
/// every chapter; a page with no source is not held. Returns how many pages have math.
fn math_as_in_source(
    src: &Path,
    pages: &[String],
    english: &[Shown],
    failures: &mut Vec<String>,
) -> Result<usize> {
    let read = |name: &str| {
        let path = src.join(name);
        std::fs::read_to_string(&path).with_context(|| format!("cannot read {}", path.display()))
    };
    let summary = read("SUMMARY.md")?;
    let chapters: Vec<&str> = (summary.split("](").skip(1))
        .filter_map(|rest| Some(rest.split_once(')')?.0))
        .filter(|link| link.ends_with(".md"))
        .collect();
    let mut with_math = Vec::new();
    for chapter in &chapters {
        if has_math(&read(chapter)?) {
            with_math.push(*chapter);
        }
    }
    let mut count = 0;
    for (page, shown) in pages.iter().zip(english) {
        let stem = page.trim_end_matches(".html");
        let source = with_math.iter().find(|chapter| match page.as_str() {
            "print.html" => true,
            "index.html" => chapters.first() == Some(*chapter),
            _ => chapter.trim_end_matches(".md") == stem,
        });
        let Some(source) = source else { continue };
        count += 1;
        if shown.formulas.is_empty() {
            failures.push(format!(
                "{page}: book/src/{source} has math, but the English page shows no formula"
            ));
        }
    }
    Ok(count)
}

/// Whether Markdown has math as mdbook-katex reads it: `$$`, or a `$...$` span whose TeX neither
/// begins nor ends with a space, outside fenced code blocks and inline code (a shell listing's `$`
/// is no math); `\$` is a dollar sign.
fn has_math(markdown: &str) -> bool {
    let mut fence: Option<&str> = None;
    for line in markdown.lines() {
        let trimmed = line.trim_start();
        if let Some(marker) = fence {
            if trimmed.starts_with(marker) {
                fence = None;
            }
            continue;
        }
        if let Some(marker) = ["```", "~~~"].into_iter().find(|m| trimmed.starts_with(m)) {
            fence = Some(marker);
            continue;
        }
        // Outside inline code: every other piece between backticks.
        let line = line.replace("\\$", "");
        let prose: Vec<&str> = line.split('`').step_by(2).collect();
        let prose = prose.join(" ");
        if prose.contains("$$") {
            return true;
        }
        let pieces: Vec<&str> = prose.split('$').collect();
        // A piece with a `$` on each side: pieces 1, 3, ... but the last.
        let spans = pieces.iter().take(pieces.len().saturating_sub(1)).skip(1);
        if spans.step_by(2).any(|tex| {
            !tex.is_empty()
                && !tex.starts_with(char::is_whitespace)
                && !tex.ends_with(char::is_whitespace)
        }) {
            return true;
        }
    }
    false
}

/// Queries of the Chinese book, each with the page that must be among its first N results (`None`:
/// any page will do). Chosen from the Chinese text: each page is the lesson that the words name, and
/// says them most often (掩码 is the stencil's masks, which lesson 2 teaches). The first result must
/// also hold every word of the query, and a single character must find something.
const CHINESE_SEARCHES: [(&str, Option<&str>, usize); 5] = [
    ("模板缓冲区", Some("stencil-basics.html"), 3),
    ("反射矩阵", Some("reflect-skull.html"), 1),
    ("环绕顺序", Some("winding-fix.html"), 1),
    ("stencil 掩码", Some("stencil-basics.html"), 3),
    ("镜", None, 0),
];

/// English queries whose results, with web/search.js, must be elasticlunr's own, in every book.
const ENGLISH_SEARCHES: [&str; 12] = [
    "stencil",
    "reflection matrix",
    "winding",
    "depth buffer",
    "mirror",
    "clockwise",
    "FLIP",
    "blend",
    "StencilFaceState",
    "cargo",
    "--show stencil",
    "front_face Ccw",
];

/// The search of `site`'s page `page` asked for `term` through `?search=` (as mdBook's own links to
/// results ask it), once its results header names `term` in the page's language: the header, and
/// the results in order, each its page, its address in the index and its section's text (title,
/// body and breadcrumbs, from the index's documents).
const SEARCHED: &str = r"new Promise((resolve) => {
    const t0 = performance.now();
    (function poll() {
        const h = document.getElementById('mdbook-searchresults-header');
        const header = h ? h.textContent : '';
        const done = header.includes(TERM) && (!TRANSLATED || /[\u4e00-\u9fff]/.test(header));
        if (done && window.search && window.search.index) {
            const urls = window.search.doc_urls, docs = window.search.index.documentStore.docs;
            const results = [...document.querySelectorAll('#mdbook-searchresults li > a')].map((a) => {
                const [path, anchor] = a.getAttribute('href').slice(path_to_root.length).split('#');
                const page = path.split('?')[0];
                const url = anchor ? page + '#' + anchor : page;
                const doc = docs[urls.indexOf(url)];
                return [page, url, doc ? [doc.title, doc.body, doc.breadcrumbs].join(' ') : ''];
            });
            resolve(JSON.stringify({ header, results }));
        } else if (performance.now() - t0 > 20000) resolve(JSON.stringify({ header, results: [] }));
        else setTimeout(poll, 50);
    })();
})";

/// What [`SEARCHED`] says: the results header, and each result's page, address and text.
struct Searched {
    header: String,
    results: Vec<(String, String, String)>,
}

/// Searches `page` (an address under `site`) for `term`, and leaves it open on the results.
fn searched(
    chrome: &WebBrowser,
    site: &str,
    page: &str,
    term: &str,
) -> Result<(BookPage, Searched)> {
    let query: String = term.bytes().map(|b| format!("%{b:02X}")).collect();
    let opened = chrome.page(&format!("{site}/{page}?search={query}"))?;
    let translated = !page.starts_with(PICKER_PAGE);
    let script = SEARCHED
        .replace("TERM", &serde_json::to_string(term)?)
        .replace("TRANSLATED", &translated.to_string());
    let json = opened.evaluate(&script)?;
    let value: serde_json::Value =
        serde_json::from_str(&json).with_context(|| format!("the search said {json:.200}"))?;
    let results = (value["results"].as_array())
        .context("the search's results are not a list")?
        .iter()
        .map(|result| {
            let text = |i: usize| result[i].as_str().unwrap_or_default().to_string();
            (text(0), text(1), text(2))
        })
        .collect();
    let header = value["header"].as_str().unwrap_or_default().to_string();
    Ok((opened, Searched { header, results }))
}

/// The search of a translated lesson page, as a reader uses it (through `?search=`): an English
/// word finds pages, with the results header in the page's language, and a word that is nowhere
/// gets the page's "none". In Chinese, the index holds the text's pairs of characters
/// (po/cjk-search.py), and each of [`CHINESE_SEARCHES`] finds its page; it still does when the
/// index was loaded and searched before web/search.js came. A screenshot of the results for
/// 模板缓冲区 goes into `dir`.
fn search(
    chrome: &WebBrowser,
    site: &str,
    language: &str,
    dir: &Path,
    failures: &mut Vec<String>,
) -> Result<()> {
    let at = format!("{language}/{PICKER_PAGE}");
    for (term, expected) in [("stencil", "找到"), ("xyzzy", "没有找到")] {
        let (_, found) = searched(chrome, site, &at, term)?;
        if !found.header.contains(expected) {
            failures.push(format!(
                "{at}?search={term}: the results header says {:?}",
                found.header
            ));
        } else {
            println!("search for {term:?}: {}", found.header);
        }
    }
    if !language.starts_with("zh") {
        return Ok(());
    }
    // The index itself: 模板 (a pair) under the body's 模.
    let (page, _) = searched(chrome, site, &at, "stencil")?;
    let pairs = page.evaluate(
        "(() => { const m = window.search.index.index.body.root['模'];
                  return String(m && m['板'] ? m['板'].df : 0); })()",
    )?;
    if pairs == "0" {
        failures.push(format!(
            "{language}: the search index holds no pairs of Chinese characters (模板 in no section): \
             book/po/cjk-search.py did not run on it"
        ));
    }
    chinese_searches(chrome, site, &at, dir, failures)?;
    searched_before_the_script(chrome, site, &at, failures)
}

/// Each of [`CHINESE_SEARCHES`] on the page `at`: its first result holds every word of the query,
/// and its page is among the first results; a screenshot of the first query's results into `dir`.
fn chinese_searches(
    chrome: &WebBrowser,
    site: &str,
    at: &str,
    dir: &Path,
    failures: &mut Vec<String>,
) -> Result<()> {
    for (term, page, within) in CHINESE_SEARCHES {
        let (opened, found) = searched(chrome, site, at, term)?;
        let mut fail = |what: String| failures.push(format!("{at}?search={term}: {what}"));
        let first: Vec<&str> = (found.results.iter().take(3))
            .map(|(_, url, _)| url.as_str())
            .collect();
        let Some((_, url, text)) = found.results.first() else {
            fail(format!("no results ({:?})", found.header));
            continue;
        };
        let text = text.to_lowercase();
        if let Some(missing) = term.split_whitespace().find(|word| !text.contains(word)) {
            fail(format!("the first result, {url}, has no {missing:?}"));
        }
        if let Some(page) = page
            && !(found.results.iter().take(within)).any(|(shown, _, _)| shown == page)
        {
            fail(format!("{page} is not among the first {within}: {first:?}"));
        }
        println!(
            "search for {term:?}: {} results shown, the first three {}",
            found.results.len(),
            first.join(", ")
        );
        if term == CHINESE_SEARCHES[0].0 {
            let shot = dir.join("search-zh.png");
            std::fs::write(&shot, opened.screenshot()?)?;
            println!("wrote {}", shot.display());
        }
    }
    Ok(())
}

/// An index loaded, and searched, before web/search.js ran (a race the page can lose when the
/// address asks for a search): the script, run again after elasticlunr's own tokenizer and
/// pipeline are put back and a Chinese query searched with them, searches it again.
fn searched_before_the_script(
    chrome: &WebBrowser,
    site: &str,
    at: &str,
    failures: &mut Vec<String>,
) -> Result<()> {
    let (page, _) = searched(chrome, site, at, "stencil")?;
    let late = page.evaluate(
        r"new Promise((resolve) => {
            const lunr = window.elasticlunr;
            lunr.tokenizer = lunr.tokenizer.original;
            lunr.Pipeline.prototype.run = lunr.Pipeline.prototype.run.original;
            const bar = document.getElementById('mdbook-searchbar');
            bar.value = '反射矩阵';
            bar.dispatchEvent(new KeyboardEvent('keyup'));
            const before = document.querySelectorAll('#mdbook-searchresults li').length;
            const script = document.createElement('script');
            script.src = [...document.scripts].find((s) => /\/search(-[0-9a-f]+)?\.js$/.test(s.src)).src;
            script.onload = () => {
                const first = document.querySelector('#mdbook-searchresults li > a');
                resolve(before + ' ' + (first ? first.getAttribute('href').split('?')[0] : 'none'));
            };
            document.head.append(script);
        })",
    )?;
    if late != format!("0 {}", CHINESE_SEARCHES[1].1.unwrap_or_default()) {
        failures.push(format!(
            "{at}: 反射矩阵 searched before web/search.js ran, then after: {late:?} (results before, \
             the first page after), not 0 and {}",
            CHINESE_SEARCHES[1].1.unwrap_or_default()
        ));
    } else {
        println!("search for \"反射矩阵\" before web/search.js ran: searched again when it came");
    }
    Ok(())
}

/// English search unchanged by web/search.js: in the book under `book` (`""`, or a translation's
/// `zh-CN/`), each of [`ENGLISH_SEARCHES`] gives the same results, in the same order and with the
/// same scores, through the wrapped tokenizer and pipeline as through elasticlunr's own (kept by
/// web/search.js as `.original`), on the book's own index.
fn english_search_unchanged(
    chrome: &WebBrowser,
    site: &str,
    book: &str,
    failures: &mut Vec<String>,
) -> Result<()> {
    let (page, _) = searched(chrome, site, &format!("{book}{PICKER_PAGE}"), "stencil")?;
    let script = r"(() => {
        const lunr = window.elasticlunr;
        const tokenizer = lunr.tokenizer, run = lunr.Pipeline.prototype.run;
        if (!tokenizer.original || !run.original)
            return JSON.stringify({ error: 'web/search.js did not wrap elasticlunr' });
        const index = lunr.Index.load(window.search.index);
        const search = (query) => index.search(query, window.search.search_options)
            .map((r) => [window.search.doc_urls[r.ref], r.score]);
        const out = {};
        for (const query of QUERIES) {
            const wrapped = search(query);
            lunr.tokenizer = tokenizer.original;
            lunr.Pipeline.prototype.run = run.original;
            try { out[query] = [wrapped, search(query)]; }
            finally { lunr.tokenizer = tokenizer; lunr.Pipeline.prototype.run = run; }
        }
        return JSON.stringify(out);
    })()"
        .replace("QUERIES", &serde_json::to_string(&ENGLISH_SEARCHES)?);
    let json = page.evaluate(&script)?;
    let value: serde_json::Value =
        serde_json::from_str(&json).with_context(|| format!("the page said {json:.200}"))?;
    let name = if book.is_empty() {
        "en"
    } else {
        book.trim_end_matches('/')
    };
    if let Some(error) = value.get("error") {
        failures.push(format!("{name} {PICKER_PAGE}: {error}"));
        return Ok(());
    }
    let mut results = 0;
    for query in ENGLISH_SEARCHES {
        let urls = |i: usize| -> Vec<&str> {
            (value[query][i].as_array().into_iter().flatten())
                .filter_map(|result| result[0].as_str())
                .collect()
        };
        let (wrapped, original) = (urls(0), urls(1));
        // Every query finds something in the English book: equal lists of nothing prove nothing.
        if value[query][0] != value[query][1] || (book.is_empty() && wrapped.is_empty()) {
            failures.push(format!(
                "{name}: search for {query:?}: {} results through web/search.js, {} through \
                 elasticlunr's own tokenizer (first {:?} against {:?})",
                wrapped.len(),
                original.len(),
                &wrapped[..wrapped.len().min(3)],
                &original[..original.len().min(3)]
            ));
        }
        results += wrapped.len();
    }
    println!(
        "{name}: {} English queries, {results} results, the same through web/search.js as through \
         elasticlunr's own tokenizer and pipeline (pages, order and scores)",
        ENGLISH_SEARCHES.len()
    );
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
    dir: &Path,
    failures: &mut Vec<String>,
) -> Result<()> {
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

#[cfg(test)]
mod tests {
    use super::{Formula, formulas_differ, has_math};

    #[test]
    fn math_is_found_outside_code_only() {
        assert!(has_math("The depth $d(z)$ of a point."));
        assert!(has_math("$$\nd = \\frac{f}{f - n}\n$$"));
        assert!(has_math("| `Less` | $d < d_s$ | `GL_LESS` |"));
        assert!(!has_math("Run `echo $HOME` and `$PATH`."));
        assert!(!has_math("```sh\n$ cargo run\nprice: $5 and $6\n```"));
        assert!(!has_math("It costs \\$5, or \\$6."));
        assert!(!has_math("From $5 to $ 6: no span."));
    }

    #[test]
    fn a_changed_formula_is_named_by_its_number() {
        let formula = |name: &str, html: &str, paragraph: u64| Formula {
            name: name.into(),
            html: html.into(),
            paragraph,
        };
        let english = [
            formula("x2", "x<sup>2</sup>", 0),
            formula("ds", "d<sub>s</sub>", 1),
            formula("n", "n", 1),
        ];
        // A translated sentence with its formulas the other way round, in a paragraph of its own.
        let reordered =
            [english[0].clone(), english[2].clone(), english[1].clone()].map(|f| Formula {
                paragraph: f.paragraph + 5,
                ..f
            });
        assert_eq!(formulas_differ(&english, &reordered), None);
        let changed = [
            english[0].clone(),
            formula("dt", "d<sub>t</sub>", 1),
            english[2].clone(),
        ];
        assert_eq!(
            formulas_differ(&english, &changed).as_deref(),
            Some("formula 2 of 3 is \"dt\", the English page's \"ds\"")
        );
        let lowered = [
            english[0].clone(),
            formula("ds", "d<sup>s</sup>", 1),
            english[2].clone(),
        ];
        assert_eq!(
            formulas_differ(&english, &lowered).as_deref(),
            Some("formula 2 of 3, \"ds\", is drawn otherwise than the English page's")
        );
        let moved = [english[0].clone(), english[1].clone(), formula("n", "n", 2)];
        assert_eq!(
            formulas_differ(&english, &moved).as_deref(),
            Some("formula 3 of 3, \"n\", is missing from its paragraph")
        );
        assert_eq!(
            formulas_differ(&english, &english[..1]).as_deref(),
            Some("1 formulas in 1 paragraphs, the English page 3 in 2")
        );
    }
}
