//! Comparing a lesson with the book: render one of the book's screenshots with the lesson as it is
//! now built (a learner's edited copy, say) and judge it by FLIP. `--check` does it for every picture
//! of the lesson; the window's panel for the one its settings match.

use std::path::Path;

use anyhow::{Context, Result, bail};
use image::RgbaImage;

use crate::app::headless::{Headless, Request};
use crate::app::output::say;
use crate::book::flip::{self, Comparison, STRICT};
use crate::book::shots::{self, BookShot, Setting};
use crate::lesson::Lesson;
use crate::room::scene::SceneOptions;

/// One picture compared.
pub struct Verdict {
    pub name: String,
    pub comparison: Comparison,
    /// The render, for writing beside the difference.
    pub actual: RgbaImage,
}

impl Verdict {
    /// Whether a reader would call it the book's picture (the tests' limit, [`STRICT`]).
    pub fn matches(&self) -> bool {
        self.comparison.passes(STRICT)
    }
}

/// Renders `shot` (with `setting`, its own settings or changed) at the book's size and compares it
/// with the book's picture.
pub fn compare<L: Lesson>(
    shot: &BookShot,
    setting: &Setting,
    scene: &SceneOptions,
    backend: Option<&str>,
) -> Result<Verdict> {
    let reference = flip::load(&shot.path())?;
    let (width, height) = reference.dimensions();
    let request = Request {
        width,
        height,
        knobs: setting.knobs.clone(),
        camera: setting.camera,
        scene: scene.clone(),
        read_stencil: false,
        read_depth: false,
        stop: setting.stop,
        show: setting.show,
        draw: setting.draw,
        backend: backend.map(str::to_string),
        verbose: false,
        passes: Default::default(),
    };
    let actual = Headless::<L>::new(&request)?.capture()?.color;
    Ok(Verdict {
        name: shot.name.clone(),
        comparison: flip::compare(&reference, &actual)?,
        actual,
    })
}

/// What `--check` and the panel say of a picture that is the driver's own choice.
pub fn not_compared(reason: &str) -> String {
    format!("driver-dependent ({reason}): not compared")
}

/// The book's screenshot that shows exactly `setting`, if there is one.
pub fn matching<L: Lesson>(shots: &[BookShot], setting: &Setting) -> Option<BookShot> {
    shots
        .iter()
        .find(|shot| shot.setting::<L>(&[]).is_ok_and(|s| s == *setting))
        .cloned()
}

/// `--check`: every screenshot of lesson `L` in the book, rendered with this build of the lesson
/// (and `overrides`, `--set` values applied after each picture's own), compared, one line each.
/// Where one differs, its render and the difference image go into `out`. Fails when any differs.
pub fn check<L: Lesson>(
    overrides: &[String],
    scene: &SceneOptions,
    backend: Option<&str>,
    out: &Path,
) -> Result<()> {
    let shots = shots::of_lesson::<L>()?;
    if shots.is_empty() {
        bail!("the book has no screenshot of `{}`", L::NAME);
    }
    let mut differ = Vec::new();
    for shot in &shots {
        if let Some(reason) = &shot.driver_dependent {
            say(format!("{}: {}\n", shot.name, not_compared(reason)))?;
            continue;
        }
        let setting = shot.setting::<L>(overrides)?;
        let verdict = compare::<L>(shot, &setting, scene, backend)?;
        let summary = verdict.comparison.summary();
        if verdict.matches() {
            say(format!("{}: matches the book ({summary})\n", shot.name))?;
            continue;
        }
        std::fs::create_dir_all(out)
            .with_context(|| format!("cannot write into `{}`", out.display()))?;
        let actual = out.join(format!("{}-actual.png", shot.name));
        let difference = out.join(format!("{}-difference.png", shot.name));
        crate::app::headless::save_png(&verdict.actual, &actual)?;
        let difference_image = image::DynamicImage::ImageRgb8(verdict.comparison.difference);
        crate::app::headless::save_png(&difference_image.to_rgba8(), &difference)?;
        say(format!(
            "{}: DIFFERS from the book ({summary}); yours is {}, where it differs {}; the book's: {}\n",
            shot.name,
            actual.display(),
            difference.display(),
            shot.path().display()
        ))?;
        differ.push(shot.name.as_str());
    }
    if !differ.is_empty() {
        bail!(
            "{} of {} pictures differ from the book: {}",
            differ.len(),
            shots.len(),
            differ.join(", ")
        );
    }
    Ok(())
}
