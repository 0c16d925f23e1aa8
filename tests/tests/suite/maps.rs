//! The maps of every lesson's frame (`--show complexity`, `--show tests`) against a pixel's story
//! (`--pixel`), told by other frames: each pixel's count is the number of fragments its story's
//! draws brought it, and a draw's test map paints each pixel with the best fate the story's tests
//! give that draw's fragments there — at the book's story pixels and at pixels drawn at random.
//! And the count against lesson 13's own count, which its tests check against ray casting.

use glam::Vec3;
use workbook::app::headless::{Headless, Request};
use workbook::gpu::maps::{BEST_FIRST, fate_colour};
use workbook::gpu::pipelines::Fate;
use workbook::lesson::story::{DrawStory, Story, Verdict};
use workbook::room::scene::SKULL_CENTRE;
use workbook::{Lesson, Show, Stop};
use workbook_tests::geometry::View;
use workbook_tests::shots::{ForLesson, for_lesson};
use workbook_tests::stories::{SIZE, STORIES};

use crate::depth_complexity;

/// The pixels a lesson's maps are checked at: its book stories', three on the skull (whose faces
/// hide each other: fragments that pass and fragments that fail the depth test at one pixel), and
/// `count` more at random (the same ones every run: a fixed seed).
fn pixels<L: Lesson>(count: usize) -> Vec<(u32, u32)> {
    let mut pixels: Vec<(u32, u32)> = STORIES
        .iter()
        .filter(|story| story.lesson == L::NAME && story.settings.is_empty())
        .map(|story| story.pixel)
        .collect();
    let view = View::new(L::CAMERA, SIZE.0, SIZE.1);
    for offset in [
        Vec3::ZERO,
        Vec3::new(0.1, 0.3, 0.0),
        Vec3::new(-0.2, -0.2, 0.0),
    ] {
        pixels.push(view.pixel_of(SKULL_CENTRE + offset));
    }
    let mut state = 0x2545_f491_u32;
    for _ in 0..count {
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state
        };
        pixels.push((next() % SIZE.0, next() % SIZE.1));
    }
    pixels
}

/// The best fate the story's tests give a draw's fragments: passed, else failed depth, else failed
/// stencil; `None` where the draw has no fragment at the pixel (it misses it, or culls it).
fn best_fate(draw: &DrawStory) -> Option<Fate> {
    let verdicts: Vec<Verdict> = draw.outcomes()?.iter().map(|o| o.verdict).collect();
    BEST_FIRST.into_iter().find(|fate| {
        let verdict = match fate {
            Fate::Passes => Verdict::Passes,
            Fate::DepthFails => Verdict::DepthFails,
            Fate::StencilFails => Verdict::StencilFails,
            Fate::Culled => return false,
        };
        verdicts.contains(&verdict)
    })
}

/// The fate a test map's pixel shows, read back from its colour; `Some(None)` for a pixel the
/// draw does not reach (the picture dimmed) and for a culled one (no fragment in a story either).
fn shown_fate([r, g, b, _]: [u8; 4]) -> Option<Fate> {
    let close = |colour: [u8; 3]| {
        colour
            .iter()
            .zip([r, g, b])
            .all(|(&c, m)| c.abs_diff(m) <= 1)
    };
    BEST_FIRST
        .into_iter()
        .find(|&fate| close(fate_colour(fate)))
        .filter(|&fate| fate != Fate::Culled)
}

/// What was checked, for the message of a test that checked too little.
#[derive(Default, Debug)]
struct Checked {
    counts: usize,
    fates: usize,
    /// Pixels at which a map said a fate other than "not reached".
    fates_met: usize,
}

/// Lesson `lesson`'s default frame at the stories' size: at every pixel of [`pixels`], its
/// complexity against the story's fragments, and the test map of every draw against the story.
struct AgainstStories(&'static str);

impl ForLesson for AgainstStories {
    type Output = Checked;
    fn run<L: Lesson>(self) -> Checked {
        let mut request = Request::new::<L>(&[] as &[&str]).unwrap();
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        let mut headless = Headless::<L>::new(&request).unwrap();
        let pixels = pixels::<L>(12);
        let stories: Vec<Story> = pixels
            .iter()
            .map(|&pixel| headless.story(pixel, String::new()).unwrap())
            .collect();
        let mut checked = Checked::default();

        headless.set_view(Stop::Last, Show::Complexity, None);
        let counts = headless.capture().unwrap().stencil.unwrap();
        for story in &stories {
            let (x, y) = story.pixel;
            let fragments: usize = story
                .steps
                .iter()
                .filter(|step| !step.into_own_target)
                .flat_map(|step| &step.draws)
                .map(|draw| draw.fragments.len())
                .sum();
            let count = counts[(y * SIZE.0 + x) as usize];
            assert_eq!(
                count as usize,
                fragments,
                "{}: pixel {x},{y} counts {count} fragments; its story has {fragments}:\n{}",
                self.0,
                story.text()
            );
            checked.counts += 1;
        }

        let steps = &stories[0].steps;
        for (index, step) in steps.iter().enumerate() {
            if step.into_own_target {
                continue;
            }
            // Each draw, then every draw of the step at once (the best fate over all of them).
            let draws = (0..step.draws.len()).map(Some).chain([None]);
            for draw in draws {
                headless.set_view(Stop::After(index + 1), Show::Tests, draw);
                let map = headless.capture().unwrap().color;
                for story in &stories {
                    let (x, y) = story.pixel;
                    let draws = &story.steps[index].draws;
                    let expected = match draw {
                        Some(draw) => best_fate(&draws[draw]),
                        None => BEST_FIRST
                            .into_iter()
                            .find(|&fate| draws.iter().any(|d| best_fate(d) == Some(fate))),
                    };
                    let shown = shown_fate(map.get_pixel(x, y).0);
                    assert_eq!(
                        shown,
                        expected,
                        "{}: step {} ({}), draw {draw:?} (from 0; None: all): the test map shows \
                         {shown:?} at pixel {x},{y}; the story's tests say {expected:?}:\n{}",
                        self.0,
                        index + 1,
                        step.name,
                        story.text()
                    );
                    checked.fates += 1;
                    checked.fates_met += usize::from(shown.is_some());
                }
            }
        }
        checked
    }
}

fn against_stories(lesson: &'static str) {
    let checked = for_lesson(lesson, AgainstStories(lesson)).unwrap();
    assert!(
        checked.counts >= 12 && checked.fates_met >= 10,
        "{lesson}: too little checked: {checked:?}"
    );
}

#[test]
fn the_maps_of_mark_mirror_agree_with_the_stories() {
    // The mirror's mark: passed where the mirror is in front, failed depth under the crate.
    against_stories("mark-mirror");
}

#[test]
fn the_maps_of_planar_shadow_agree_with_the_stories() {
    // The shadow's second fragment finds the first one's stencil: the test a draw meets with its
    // own writes.
    against_stories("planar-shadow");
}

#[test]
fn the_maps_of_two_mirrors_agree_with_the_stories() {
    // Stencil levels: each level's draws pass only where the stencil holds the level.
    against_stories("two-mirrors");
}

#[test]
fn the_maps_of_winding_fix_agree_with_the_stories() {
    // The reflection drawn with the winding unfixed: its culled faces, and its back faces drawn.
    against_stories("winding-fix");
}

/// Lesson 13 counts every fragment of its room in the stencil (checked against ray casting by its
/// own tests); the complexity view of the frame stopped after that count replays the same draws
/// with a counting stencil of its own: the same numbers at every pixel.
#[test]
fn the_complexity_of_lesson_13_s_count_is_its_count() {
    let view = depth_complexity::VIEW;
    let expected = depth_complexity::counts(&["count=every-fragment"]);
    let replayed =
        workbook_tests::shots::render("depth-complexity", &["count=every-fragment"], |request| {
            (request.width, request.height) = (view.width, view.height);
            request.read_stencil = true;
            request.stop = Stop::After(2);
            request.show = Show::Complexity;
        })
        .unwrap()
        .stencil
        .unwrap();
    let differing = expected
        .iter()
        .zip(&replayed)
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(differing, 0, "pixels whose replayed count differs");
    assert!(
        expected.iter().any(|&c| c >= 4),
        "the room has pixels of four fragments or more"
    );
}

#[test]
fn the_maps_of_drawing_order_agree_with_the_stories() {
    // Transparent objects drawn in an order of their own: a draw whose fragments pass at a pixel
    // where an earlier draw's nearer ones make others fail.
    against_stories("drawing-order");
}
