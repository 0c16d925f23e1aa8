//! `cargo screenshots [NAME...]`: renders the book's images into `book/src/images/` — the
//! screenshots, the enlarged crop and difference image of each wrong/right pair, and each lesson's
//! step strip, its pixel stories (`--pixel`, with the pixel marked on the picture), and the list of the screenshots with the arguments that make each (`shots.txt`). These files are also the tests' references, so run this only on purpose: when a
//! picture is meant to change, look at the new one, and say why in the commit.
//!
//! A NAME is a screenshot's name, or a lesson's (all of that lesson's images); none means all.

use std::process::ExitCode;

use anyhow::Result;
use workbook::app::headless::PngSize;
use workbook_tests::shots::{LESSONS, PAIRS, SHOTS};
use workbook_tests::stories::STORIES;
use workbook_tests::strips;

fn main() -> ExitCode {
    workbook::app::cli::quiet_mesa();
    let names: Vec<String> = std::env::args().skip(1).collect();
    let known = |name: &str| {
        SHOTS.iter().any(|s| s.name == name)
            || STORIES.iter().any(|s| s.name == name)
            || LESSONS.contains(&name)
    };
    if let Some(unknown) = names.iter().find(|n| !known(n)) {
        let shots: Vec<_> = SHOTS.iter().map(|s| s.name).collect();
        eprintln!(
            "screenshots: error: no screenshot or lesson called `{unknown}`; the lessons are {}, \
             the screenshots {}",
            LESSONS.join(", "),
            shots.join(", ")
        );
        return ExitCode::FAILURE;
    }
    let wanted = |name: &str, lesson: &str| {
        names.is_empty() || names.iter().any(|n| n == name || n == lesson)
    };
    match write(&wanted) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            eprintln!("screenshots: error: {error:#}");
            ExitCode::FAILURE
        }
    }
}

fn write(wanted: &dyn Fn(&str, &str) -> bool) -> Result<()> {
    let images = workbook_tests::images();
    std::fs::create_dir_all(&images)?;
    let save = |image: &image::RgbaImage, name: &str| {
        let path = images.join(format!("{name}.png"));
        workbook::app::headless::save_png_as(image, &path, PngSize::Small)?;
        anyhow::Ok(path)
    };
    for shot in SHOTS.iter().filter(|s| wanted(s.name, s.lesson)) {
        let path = save(&shot.render()?, shot.name)?;
        println!("wrote {}   ({})", path.display(), shot.command()?);
    }
    // The list of them all, which the window's panel and `--check` read: cheap, so always.
    let list = images.join(workbook::book::shots::LIST);
    std::fs::write(&list, workbook_tests::shots::list_text()?)?;
    println!("wrote {}", list.display());
    for pair in PAIRS {
        let lesson = workbook_tests::shots::Shot::named(pair.wrong)?.lesson;
        if !(wanted(pair.wrong, lesson) || wanted(pair.right, lesson)) {
            continue;
        }
        let made = pair.make()?;
        save(&made.zoom, &pair.zoom_name())?;
        let path = save(&made.difference, &pair.difference_name())?;
        println!(
            "wrote {} and its zoom   (crop {:?}, {:.0}% of the visibly different pixels)",
            path.display(),
            made.rect,
            made.coverage * 100.0
        );
    }
    for story in STORIES.iter().filter(|s| wanted(s.name, s.lesson)) {
        for path in story.write()? {
            println!("wrote {}   ({})", path.display(), story.command());
        }
    }
    for lesson in LESSONS.iter().filter(|l| wanted("", l)) {
        let files = strips::write(lesson)?;
        println!(
            "wrote {} ({} files)",
            strips::dir(lesson).display(),
            files.len()
        );
    }
    Ok(())
}
