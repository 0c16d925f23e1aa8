//! The catalogue of the book's screenshots. Each is made by the project's own command
//! (`cargo screenshots`, which renders this list), shown in the book, and checked by the tests
//! against the committed file with the threshold given here.

use std::path::PathBuf;

use anyhow::{Result, bail};
use image::RgbaImage;
use workbook::Lesson;
use workbook::headless::{self, Capture, Request};

use crate::flip::{self, Threshold};

/// The size of every screenshot in the book: small enough to keep the repository light, large enough
/// to see a fringe.
pub const SIZE: (u32, u32) = (800, 450);

/// lavapipe renders each of these bit-identically from run to run, so on the machine that made the
/// references the error is 0. Another driver (a real GPU) may round colours by 1/255 and place a few
/// edge pixels differently; that moves the mean by well under 0.01 and touches far fewer than 0.1% of
/// the pixels visibly. A change a reader would notice (a 30×30 patch, a missing object) exceeds one
/// of the two.
pub const STRICT: Threshold = Threshold {
    mean: 0.01,
    visible_share: 0.001,
};

/// One screenshot of the book.
#[derive(Debug)]
pub struct Shot {
    /// The file `book/src/images/<name>.png`.
    pub name: &'static str,
    /// The lesson's package name.
    pub lesson: &'static str,
    /// Knob settings, as given to `--set`.
    pub settings: &'static [&'static str],
    pub threshold: Threshold,
}

pub const SHOTS: &[Shot] = &[
    Shot {
        name: "depth-test",
        lesson: "depth-test",
        settings: &[],
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-always",
        lesson: "depth-test",
        settings: &["depth=always"],
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-painter",
        lesson: "depth-test",
        settings: &["depth=always", "order=far-first"],
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-view-depth",
        lesson: "depth-test",
        settings: &["view=depth"],
        threshold: STRICT,
    },
];

impl Shot {
    pub fn path(&self) -> PathBuf {
        crate::images().join(format!("{}.png", self.name))
    }

    /// The command a reader types to make this picture.
    pub fn command(&self) -> String {
        let mut command = format!(
            "cargo run -p {} -- --size {}x{}",
            self.lesson, SIZE.0, SIZE.1
        );
        for setting in self.settings {
            command += &format!(" --set {setting}");
        }
        command + &format!(" --screenshot {}.png", self.name)
    }

    pub fn render(&self) -> Result<RgbaImage> {
        let capture = render(self.lesson, self.settings, |request| {
            (request.width, request.height) = SIZE;
        })?;
        Ok(capture.color)
    }

    /// Renders the shot and compares it with its reference.
    pub fn check(&self) -> Result<()> {
        check_image(self.name, &self.render()?, self.threshold)
    }
}

/// Every lesson by package name, in the book's order.
pub const LESSONS: &[&str] = &["depth-test"];

/// The knobs of a lesson, by package name.
pub fn knobs(lesson: &str) -> Result<&'static [workbook::Knob]> {
    Ok(match lesson {
        "depth-test" => depth_test::DepthTest::KNOBS,
        other => bail!("there is no lesson called `{other}`"),
    })
}

/// Renders lesson `lesson` headless with these knob settings, after `adjust` changed the request.
pub fn render(
    lesson: &str,
    settings: &[&str],
    adjust: impl FnOnce(&mut Request),
) -> Result<Capture> {
    fn go<L: Lesson>(settings: &[&str], adjust: impl FnOnce(&mut Request)) -> Result<Capture> {
        let mut request = Request::new::<L>(settings)?;
        adjust(&mut request);
        headless::render::<L>(&request)
    }
    match lesson {
        "depth-test" => go::<depth_test::DepthTest>(settings, adjust),
        other => bail!("there is no lesson called `{other}`"),
    }
}

/// Compares `actual` with the reference `book/src/images/<name>.png`. On failure writes
/// `<name>-actual.png` and `<name>-difference.png` beside it and says where.
pub fn check_image(name: &str, actual: &RgbaImage, threshold: Threshold) -> Result<()> {
    let dir = crate::images();
    let reference_path = dir.join(format!("{name}.png"));
    let actual_path = dir.join(format!("{name}-actual.png"));
    let difference_path = dir.join(format!("{name}-difference.png"));
    if !reference_path.exists() {
        bail!(
            "the reference {} is missing; make it on purpose with `cargo screenshots {name}`, look at \
             it, and commit it",
            reference_path.display()
        );
    }
    let reference = flip::load(&reference_path)?;
    if reference.dimensions() != actual.dimensions() {
        actual.save(&actual_path)?;
        bail!(
            "{name}: the render is {:?} but the reference is {:?}; the render is in {}",
            actual.dimensions(),
            reference.dimensions(),
            actual_path.display()
        );
    }
    let comparison = flip::compare(&reference, actual)?;
    if comparison.passes(threshold) {
        let _ = std::fs::remove_file(&actual_path);
        let _ = std::fs::remove_file(&difference_path);
        return Ok(());
    }
    actual.save(&actual_path)?;
    comparison.difference.save(&difference_path)?;
    bail!(
        "{name} differs from its reference: {} (allowed: mean {}, {}% visibly different); \
         see {} and {}",
        comparison.summary(),
        threshold.mean,
        threshold.visible_share * 100.0,
        actual_path.display(),
        difference_path.display()
    )
}
