//! The book's step strips: every lesson's frame, step by step, as the colour, depth and stencil
//! buffers after each step (`--film`), with the step's name as the caption. `cargo screenshots`
//! writes the images and the strip's HTML, which the lesson's page includes; the tests film the
//! lessons again and compare.

use std::path::PathBuf;

use anyhow::{Context, Result};
use workbook::app::headless::Still;
use workbook::{Show, lesson::steps};

use crate::shots;

/// The size of a strip's images: three to a row fill the page's width.
pub const SIZE: (u32, u32) = (384, 216);

/// The folder of a lesson's strip, `book/src/images/steps/<lesson>/`.
pub fn dir(lesson: &str) -> PathBuf {
    crate::images().join("steps").join(lesson)
}

/// The strip's HTML, which the lesson's page includes.
pub fn html_path(lesson: &str) -> PathBuf {
    dir(lesson).join("strip.html")
}

/// The lesson's default frame, filmed at the strip's size.
pub fn film(lesson: &str) -> Result<Vec<Still>> {
    shots::film(lesson, &[], |request| {
        (request.width, request.height) = SIZE
    })
}

/// The strip of a film as HTML: a table with a row per step, the step's number and name as the
/// row's caption, and the three buffers' images. Written by code, never by hand.
pub fn html(lesson: &str, stills: &[Still]) -> String {
    let mut html = format!(
        "<!-- Written by `cargo screenshots` from `cargo run -p {lesson} -- --film DIR`: edit the \
         lesson, not this file. -->\n<table class=\"steps\">\n<thead><tr><th>Step</th>"
    );
    for show in Show::BUFFERS {
        html += &format!("<th>{}</th>", buffer_title(show));
    }
    html += "</tr></thead>\n<tbody>\n";
    for (index, still) in stills.iter().enumerate() {
        let number = index + 1;
        html += &format!("<tr><th class=\"step\">{number}. {}</th>", still.step);
        for show in Show::BUFFERS {
            let file = steps::film_file(number, still.step, show);
            html += &format!(
                "<td><img src=\"images/steps/{lesson}/{file}\" alt=\"{} after step {number}, {}\" \
                 width=\"{}\" height=\"{}\"></td>",
                buffer_title(show).to_lowercase(),
                still.step,
                SIZE.0,
                SIZE.1
            );
        }
        html += "</tr>\n";
    }
    html + "</tbody>\n</table>\n"
}

fn buffer_title(show: Show) -> &'static str {
    match show {
        Show::Color => "Colour",
        Show::Depth | Show::RawDepth => "Depth",
        Show::Stencil => "Stencil",
        Show::Complexity => "Complexity",
        Show::Tests => "Tests",
    }
}

/// Films the lesson and writes its strip: the images and the HTML, in a folder emptied first (so
/// that a step renamed leaves no stale image behind), the PNGs written small as the book keeps them.
/// Returns the files written.
pub fn write(lesson: &str) -> Result<Vec<PathBuf>> {
    let stills = film(lesson)?;
    let dir = dir(lesson);
    if dir.exists() {
        std::fs::remove_dir_all(&dir).with_context(|| format!("cannot empty {}", dir.display()))?;
    }
    workbook::app::headless::save_film(&stills, &Show::BUFFERS, &dir)?;
    std::fs::write(html_path(lesson), html(lesson, &stills))
        .with_context(|| format!("cannot write {}", html_path(lesson).display()))?;
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)?
        .map(|entry| entry.map(|e| e.path()))
        .collect::<Result<_, _>>()?;
    files.sort();
    for png in files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "png"))
    {
        workbook::app::headless::compact_png(png)?;
    }
    Ok(files)
}
