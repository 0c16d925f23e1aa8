//! One pixel's story (`--pixel`) against other readings of the same frame: each step's values
//! against the film, each draw's written-out tests against what the GPU stored next (the model
//! against the GPU, in a masked test, a wrap, a clamp and rejected fragments), and the stories the
//! book tells, found from the room's geometry.

use glam::Vec3;
use workbook::app::headless::Still;
use workbook::gpu::views::stencil_colour;
use workbook::lesson::story::{DrawStory, Outcome, Story, Verdict};
use workbook::room::camera::{BOOK_POSE, FAR, NEAR};
use workbook::room::scene::{CRATE_CENTRE, CRATE_SIZE, MIRROR_MAX, MIRROR_MIN, SKULL_CENTRE};
use workbook_tests::geometry::{View, hit_box, hit_z0_rect};
use workbook_tests::shots::{self, LESSONS, STRICT};
use workbook_tests::stories::{STORIES, skeleton};

/// The book's camera, at a size that keeps the stories quick.
const VIEW: View = View::new(BOOK_POSE, 320, 180);

fn stories(lesson: &str, settings: &[&str], pixels: &[(u32, u32)]) -> (Vec<Story>, Vec<Still>) {
    shots::stories(lesson, settings, pixels, |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.camera = VIEW.camera;
    })
    .unwrap()
}

fn story(lesson: &str, settings: &[&str], pixel: (u32, u32)) -> Story {
    stories(lesson, settings, &[pixel]).0.remove(0)
}

/// Every draw of the story: its written-out tests predict what the GPU stored after it, and the
/// pixel after a step's last draw is the pixel after the step.
fn assert_consistent(story: &Story) {
    for step in &story.steps {
        for draw in &step.draws {
            assert!(
                draw.agrees(),
                "{}: the model and the GPU disagree (or the draw has no recipe):\n{}",
                step.name,
                story.text()
            );
        }
        if let Some(last) = step.draws.last() {
            assert_eq!(last.after, step.after, "{}:\n{}", step.name, story.text());
        }
    }
}

/// The grey `--show depth` paints a depth with (linearised, then sRGB-encoded by the target).
fn depth_grey(depth: f32) -> u8 {
    let z = NEAR * FAR / (FAR - depth * (FAR - NEAR));
    let linear = (z - NEAR) / (FAR - NEAR);
    let encoded = if linear <= 0.003_130_8 {
        linear * 12.92
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round() as u8
}

/// For a few pixels of every lesson's default frame, the story's values after each step are what
/// the film (`--film`: whole buffers, painted and read back another way) shows there.
#[test]
fn every_lesson_s_story_is_what_the_film_shows_at_its_pixel() {
    let pixels = [(160, 60), (200, 111), (100, 140), (130, 100)];
    for lesson in LESSONS {
        let (stories, stills) = stories(lesson, &[], &pixels);
        for story in &stories {
            assert_consistent(story);
            let (x, y) = story.pixel;
            assert_eq!(story.steps.len(), stills.len());
            for (step, still) in story.steps.iter().zip(&stills) {
                if step.into_own_target {
                    continue;
                }
                let at = |image: &image::RgbaImage| image.get_pixel(x, y).0;
                let context =
                    || format!("{lesson} ({x}, {y}) after {}:\n{}", step.name, story.text());
                assert_eq!(
                    at(&still.color)[..3],
                    step.after.color[..3],
                    "{}",
                    context()
                );
                let painted = at(&still.stencil);
                let expected = stencil_colour(step.after.stencil);
                let near = |a: u8, b: u8| a.abs_diff(b) <= 1;
                assert!(
                    (0..3).all(|c| near(painted[c], expected[c])),
                    "{}",
                    context()
                );
                let grey = at(&still.depth)[0];
                assert!(
                    grey.abs_diff(depth_grey(step.after.depth)) <= 2,
                    "{}",
                    context()
                );
            }
        }
    }
}

/// The model against the GPU where the tests do more than pass: a read mask that changes the
/// verdict, an operation that wraps (0 − 1 → 255) and one that clamps (0 − 1 → 0), fragments
/// rejected by the stencil test and by the depth test.
#[test]
fn the_written_out_tests_predict_the_gpu_in_masked_wrapping_clamping_and_rejecting_cases() {
    let mut seen: Vec<DrawStory> = Vec::new();
    let mut tell = |lesson: &str, settings: &[&str], pixels: &[(u32, u32)]| {
        for story in stories(lesson, settings, pixels).0 {
            assert_consistent(&story);
            seen.extend(story.steps.into_iter().flat_map(|step| step.draws));
        }
    };
    // Lesson 2: the bullseye holds 2, the ring 1; with read mask 0x01 and reference 3 the ring
    // passes (1 = 1) and the bullseye fails (1 ≠ 0).
    let masked = ["read-mask=0x01", "reference=3"];
    tell("stencil-basics", &masked, &[(130, 100), (195, 120)]);
    // In the ring behind the crate: the crate decrements 1 → 0, the mirror behind it fails the
    // depth test and wraps 0 → 255; outside the porthole the floor clamps 0 → 0.
    let wrap = [
        "compare=always",
        "pass-op=decrement-clamp",
        "depth-fail-op=decrement-wrap",
    ];
    tell("stencil-basics", &wrap, &[(195, 120), (250, 150)]);

    // Every fragment the model met, with the draw's recipe.
    let outcomes: Vec<(Outcome, wgpu::StencilState, u32)> = seen
        .iter()
        .flat_map(|draw| {
            let recipe = draw.recipe.clone().unwrap();
            let outcomes = draw.outcomes().unwrap();
            outcomes
                .into_iter()
                .map(move |o| (o, recipe.stencil.clone(), draw.reference))
        })
        .collect();
    let masked: Vec<Verdict> = outcomes
        .iter()
        .filter(|(_, stencil, _)| {
            stencil.read_mask != 0xff && stencil.front.compare != wgpu::CompareFunction::Always
        })
        .map(|(outcome, ..)| outcome.verdict)
        .collect();
    assert!(masked.contains(&Verdict::Passes) && masked.contains(&Verdict::StencilFails));
    let applied = |op, before: u8, after: u8| {
        outcomes.iter().any(|(outcome, ..)| {
            outcome.operation == Some((op, after)) && outcome.before.stencil == before
        })
    };
    use wgpu::StencilOperation::{DecrementClamp, DecrementWrap};
    assert!(applied(DecrementWrap, 0, 255), "no wrap");
    assert!(applied(DecrementClamp, 0, 0), "no clamp");
    let rejected = |verdict| outcomes.iter().any(|(o, ..)| o.verdict == verdict);
    assert!(
        rejected(Verdict::DepthFails),
        "no fragment failed the depth test"
    );
    assert!(
        rejected(Verdict::StencilFails),
        "no fragment failed the stencil test"
    );
}

/// Reflect-skull: where the mirrored skull shows, the mirror's pixel goes 0 → 1 at "mark the
/// mirror", and the reflection's draw passes there and paints it.
#[test]
fn a_mirror_pixel_is_marked_then_painted_by_the_reflection() {
    let mirrored_skull = SKULL_CENTRE * Vec3::new(1.0, 1.0, -1.0);
    let story = story("reflect-skull", &[], VIEW.pixel_of(mirrored_skull));
    assert_consistent(&story);
    let step = |name: &str| {
        let index = story.steps.iter().position(|s| s.name == name).unwrap();
        (&story.steps[index - 1], &story.steps[index])
    };
    let (before, mark) = step("mark the mirror");
    assert_eq!(
        (before.after.stencil, mark.after.stencil),
        (0, 1),
        "{}",
        story.text()
    );
    let (before, reflection) = step("draw the reflected skull");
    let draw = &reflection.draws[0];
    assert!(draw.passed && draw.any_passes(), "{}", story.text());
    assert_ne!(
        reflection.after.color,
        before.after.color,
        "{}",
        story.text()
    );
}

/// Two-mirrors' first level is the reflection: behind the crate, the mirror's mark fails the depth
/// test, the stencil stays 0, and the reflected floor's fragment is rejected by the stencil test.
#[test]
fn behind_the_crate_the_mark_stays_zero_and_the_stencil_rejects_the_reflection() {
    let behind_crate = |(x, y): (u32, u32)| {
        let (origin, direction) = VIEW.ray(x, y);
        let half = Vec3::splat(CRATE_SIZE / 2.0);
        let crate_hit = hit_box(origin, direction, CRATE_CENTRE - half, CRATE_CENTRE + half);
        let mirror_hit = hit_z0_rect(origin, direction, MIRROR_MIN, MIRROR_MAX);
        matches!((crate_hit, mirror_hit), (Some(c), Some(m)) if c < m)
    };
    let pixels: Vec<(u32, u32)> = VIEW
        .pixels()
        .filter(|&(x, y)| {
            behind_crate((x, y)) && VIEW.inside_region(x, y, |x, y| behind_crate((x, y)))
        })
        .collect();
    assert!(
        pixels.len() > 100,
        "only {} pixels behind the crate",
        pixels.len()
    );
    // A few spread over the region.
    let chosen: Vec<_> = pixels.iter().step_by(pixels.len() / 4).copied().collect();
    let (stories, _) = stories("two-mirrors", &[], &chosen);
    let mut rejected = 0;
    for story in &stories {
        assert_consistent(story);
        let mark = story
            .steps
            .iter()
            .find(|s| s.name == "mark level 1")
            .unwrap();
        assert_eq!(mark.after.stencil, 0, "{}", story.text());
        let outcomes = mark.draws[0].outcomes().unwrap();
        let verdicts: Vec<_> = outcomes.iter().map(|o| o.verdict).collect();
        assert_eq!(verdicts, [Verdict::DepthFails], "{}", story.text());
        let level = story
            .steps
            .iter()
            .find(|s| s.name == "draw level 1")
            .unwrap();
        rejected += level
            .draws
            .iter()
            .filter(|d| d.any(Verdict::StencilFails) && !d.passed)
            .count();
    }
    assert!(
        rejected > 0,
        "no reflected fragment was rejected by the stencil test"
    );
}

/// Two-mirrors at depth 3: in the corridor's third level, a pixel is marked 1, 2 and 3 by the
/// three marks, each an increment that passes both tests.
#[test]
fn a_corridor_pixel_three_levels_deep_reaches_three() {
    let capture = shots::render("two-mirrors", &[], |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height);
        request.read_stencil = true;
    })
    .unwrap();
    let three = |(x, y): (u32, u32)| capture.stencil_at(x, y) == Some(3);
    let pixel = VIEW
        .pixels()
        .find(|&(x, y)| three((x, y)) && VIEW.inside_region(x, y, |x, y| three((x, y))))
        .expect("no pixel three levels deep");
    // The lesson's own camera, as the capture had it.
    let (mut stories, _) = shots::stories("two-mirrors", &[], &[pixel], |request| {
        (request.width, request.height) = (VIEW.width, VIEW.height)
    })
    .unwrap();
    let story = stories.remove(0);
    assert_consistent(&story);
    for level in 1..=3u8 {
        let mark = story
            .steps
            .iter()
            .find(|s| s.name == format!("mark level {level}"))
            .unwrap();
        let draw = &mark.draws[0];
        assert_eq!(
            draw.before.stencil + 1,
            mark.after.stencil,
            "{}",
            story.text()
        );
        assert_eq!(mark.after.stencil, level, "{}", story.text());
        assert!(draw.passed, "{}", story.text());
    }
}

/// The book's pixel stories are what the lessons tell today: the same steps, draws, fragments and
/// verdicts (the measured colours and depths may differ by a driver's rounding), each consistent
/// with the GPU, and the picture with the pixel marked matches by FLIP.
#[test]
fn the_book_s_pixel_stories_are_what_the_lessons_tell() {
    for story in STORIES {
        let (told, picture) = story.tell().unwrap();
        assert_consistent(&told);
        let path = story.text_path();
        let committed = std::fs::read_to_string(&path).unwrap_or_else(|_| {
            panic!(
                "{} is missing: make it with `cargo screenshots {}`",
                path.display(),
                story.name
            )
        });
        assert_eq!(
            skeleton(&committed),
            skeleton(&told.text()),
            "{} tells another story now: look at it (`{}`) and run `cargo screenshots {}`",
            path.display(),
            story.command(),
            story.name
        );
        shots::check_image(&story.image_name(), &picture, STRICT).unwrap();
    }
}

/// A story checks each draw against the CPU model through the draw's recipe: every draw of every
/// lesson, with each value of each knob, has one (a pipeline baked elsewhere would be told but
/// not checked, so none may be drawn).
#[test]
fn every_draw_of_every_lesson_has_a_recipe() {
    struct Draws;
    impl shots::ForLesson for Draws {
        type Output = usize;
        fn run<L: workbook::Lesson>(self) -> usize {
            let mut settings = vec![String::new()];
            for knob in L::KNOBS {
                let other = knob.values.iter().filter(|v| **v != knob.default);
                settings.extend(other.map(|value| format!("{}={value}", knob.name)));
            }
            let mut checked = 0;
            for setting in settings {
                let setting: Vec<&str> = Some(setting.as_str())
                    .filter(|s| !s.is_empty())
                    .into_iter()
                    .collect();
                let mut request = workbook::app::headless::Request::new::<L>(&setting).unwrap();
                (request.width, request.height) = (64, 36);
                let Ok(headless) = workbook::app::headless::Headless::<L>::new(&request) else {
                    // A value this GPU cannot draw (lesson 8's clip distances): said so, not drawn.
                    continue;
                };
                let draws = headless.draws();
                assert!(!draws.is_empty(), "{} {setting:?}: no draws", L::NAME);
                for draw in &draws {
                    assert!(
                        draw.recipe.is_some(),
                        "{} {setting:?}: a draw of step {} ({:?}) has no recipe",
                        L::NAME,
                        draw.step,
                        draw.object
                    );
                }
                checked += draws.len();
            }
            checked
        }
    }
    let mut total = 0;
    for lesson in LESSONS {
        total += shots::for_lesson(lesson, Draws).unwrap();
    }
    println!("{total} draws, every one with a recipe");
}
