//! Every lesson's frame is a list of named steps: filmed step by step it ends in the full picture,
//! begins with the cleared buffers, and no step is empty. The book's strips are those films, and
//! each wrong picture's enlarged crop holds the place where it differs from the right one.

use image::Rgba;
use workbook::Show;
use workbook::gpu::views::stencil_colour;
use workbook::lesson::Passes;
use workbook::room::scene::CLEAR_SRGB;
use workbook_tests::pairs;
use workbook_tests::shots::{self, LESSONS, PAIRS, STRICT, Shot};
use workbook_tests::strips;

const SIZE: (u32, u32) = (160, 90);

#[test]
fn every_frame_goes_from_cleared_buffers_to_the_full_picture_with_no_empty_step() {
    for lesson in LESSONS {
        let film = shots::film(lesson, &[], |r| (r.width, r.height) = SIZE).unwrap();
        let full = shots::render(lesson, &[], |r| {
            (r.width, r.height) = SIZE;
            r.show = Show::Color;
        })
        .unwrap();
        assert!(film.len() >= 2, "{lesson} has {} steps", film.len());

        // The first step clears: the sky everywhere, every depth at the far plane (white), every
        // stencil value 0.
        let first = &film[0];
        assert_eq!(first.step, "clear", "{lesson}");
        let sky = Rgba([CLEAR_SRGB[0], CLEAR_SRGB[1], CLEAR_SRGB[2], 255]);
        let [r, g, b] = stencil_colour(0);
        let zero = Rgba([r, g, b, 255]);
        assert!(
            first.color.pixels().all(|p| *p == sky),
            "{lesson}: not cleared"
        );
        assert!(
            first.depth.pixels().all(|p| *p == Rgba([255; 4])),
            "{lesson}: depth"
        );
        assert!(
            first.stencil.pixels().all(|p| *p == zero),
            "{lesson}: stencil"
        );

        // The last step's colours are the frame's, exactly.
        let last = film.last().unwrap();
        assert!(
            last.color == full.color,
            "{lesson}: the last step is not the full frame"
        );

        // Every step changes at least one of the three buffers.
        for pair in film.windows(2) {
            let changed = Show::BUFFERS
                .iter()
                .any(|&show| pair[0].image(show) != pair[1].image(show));
            assert!(changed, "{lesson}: step `{}` changes nothing", pair[1].step);
        }
    }
}

/// Where nothing looks between the steps (a screenshot, the window without its panel) a frame
/// records them into one render pass, each step starting from the state a new pass starts from. The
/// colours, the depth and the stencil must be exactly those of the frame recorded a pass per step
/// (as the film, the timers and the panel record it), for every value of every knob.
#[test]
fn one_pass_gives_the_buffers_a_pass_per_step_gives() {
    let size = (96, 54);
    let mut compared = 0;
    for lesson in LESSONS {
        let each = shots::every_knob_value(lesson).unwrap();
        for show in Show::BUFFERS {
            let captures = |passes: Passes| {
                shots::render_each(lesson, &each, |request| {
                    (request.width, request.height) = size;
                    request.show = show;
                    request.passes = passes;
                })
                .unwrap_or_else(|e| panic!("{lesson}: {e:#}"))
            };
            let (one, per_step) = (captures(Passes::One), captures(Passes::PerStep));
            for ((one, per_step), settings) in one.iter().zip(&per_step).zip(&each) {
                assert!(
                    one.color == per_step.color,
                    "{lesson} {settings:?}: the {} buffer differs in one pass",
                    show.name()
                );
                compared += 1;
            }
        }
    }
    eprintln!("{compared} pictures the same in one pass and a pass per step");
}

/// The strips on the lesson pages are the lessons' films now: every image matches by FLIP, no image
/// is missing or left over, and the captions are the steps' names as the lesson's code gives them.
#[test]
fn the_book_strips_are_the_lessons_films() {
    let mut failures = Vec::new();
    for lesson in LESSONS {
        let film = strips::film(lesson).unwrap();
        let html = std::fs::read_to_string(strips::html_path(lesson)).unwrap_or_default();
        // The captions are the names `--list-steps` prints, from the same function.
        let names: Vec<&str> = film.iter().map(|still| still.step).collect();
        let listed = workbook::lesson::steps::describe(&names);
        assert_eq!(
            workbook::app::testing::strip_captions(&strips::html(lesson, &film)),
            listed
        );
        if html != strips::html(lesson, &film) {
            failures.push(format!(
                "{}: not the strip of the lesson's steps; remake it with `cargo screenshots {lesson}`",
                strips::html_path(lesson).display()
            ));
        }
        let mut expected = vec!["strip.html".to_string()];
        for (index, still) in film.iter().enumerate() {
            for show in Show::BUFFERS {
                let file = workbook::lesson::steps::film_file(index + 1, still.step, show);
                let name = format!("steps/{lesson}/{}", file.trim_end_matches(".png"));
                if let Err(error) = shots::check_image(&name, still.image(show), STRICT) {
                    failures.push(format!("{error:#}"));
                }
                expected.push(file);
            }
        }
        let mut found: Vec<String> = std::fs::read_dir(strips::dir(lesson))
            .map(|entries| {
                let names = entries.flatten();
                names
                    .map(|e| e.file_name().to_string_lossy().into_owned())
                    .collect()
            })
            .unwrap_or_default();
        found.sort();
        expected.sort();
        if found != expected {
            failures.push(format!(
                "{lesson}: the strip's files are {found:?}, not {expected:?}"
            ));
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

/// Each wrong picture's crop is placed from the book's own two pictures (the same on every
/// machine), holds at least 80% of the pixels that differ visibly there — and, rendered on this
/// machine, here too. The difference image, made from the book's pictures alone, is remade the
/// same; the zoom, rendered here, matches the book's (but where the wrong picture is the driver's
/// own choice, as z-fighting is: its zoom shows this driver's z-fighting).
#[test]
fn every_wrong_picture_has_its_crop_where_it_differs() {
    let mut failures = Vec::new();
    for pair in PAIRS {
        let made = pair.make().unwrap();
        let here = pair.here().unwrap();
        let here = pairs::coverage(&here.errors, shots::SIZE.0, made.rect);
        for (what, coverage) in [("in the book", made.coverage), ("rendered here", here)] {
            if coverage < 0.8 {
                failures.push(format!(
                    "{}: the crop {:?} holds only {:.0}% of the visibly different pixels {what}",
                    pair.wrong,
                    made.rect,
                    coverage * 100.0
                ));
            }
        }
        let mut compared = vec![(pair.difference_name(), &made.difference)];
        if Shot::named(pair.wrong).unwrap().driver_dependent.is_none() {
            compared.push((pair.zoom_name(), &made.zoom));
        }
        for (name, image) in compared {
            if let Err(error) = shots::check_image(&name, image, STRICT) {
                failures.push(format!("{error:#}"));
            }
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}
