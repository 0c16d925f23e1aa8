//! The catalogue of the book's screenshots. Each is made by the project's own command
//! (`cargo screenshots`, which renders this list), shown in the book, and checked by the tests
//! against the committed file with the threshold given here.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use image::RgbaImage;
use workbook::Knobs;
use workbook::Lesson;
use workbook::camera::Camera;
use workbook::headless::{Capture, Headless, Request};

use crate::flip::{self, Threshold};

/// The size of every screenshot in the book: small enough to keep the repository light, large enough
/// to see a fringe.
pub const SIZE: (u32, u32) = (800, 450);

/// The references were made with lavapipe, which renders each of these bit-identically run to run:
/// on the machine that made them the error is 0. An NVIDIA H200 (Vulkan, driver 580) filters the
/// textures a little differently (anisotropic filtering is the driver's own): measured against the
/// references, FLIP mean 0.017-0.018 with 0.000-0.056% of the pixels visibly different. The mean
/// limit sits above that. What a reader would notice shows in the share of visibly different pixels:
/// the smallest wrong picture of the book (drawing-order's dark fringe) differs from its right one
/// in 0.33% of the pixels, a 30×30 patch in 0.25%; the limit, 0.15%, lies between those and the
/// other driver's 0.056%.
pub const STRICT: Threshold = Threshold {
    mean: 0.03,
    visible_share: 0.0015,
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
    /// A camera pose other than the default, as given to `--camera`.
    pub camera: Option<&'static str>,
    pub threshold: Threshold,
}

pub const SHOTS: &[Shot] = &[
    Shot {
        name: "depth-test",
        lesson: "depth-test",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-always",
        lesson: "depth-test",
        settings: &["depth=always"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-painter",
        lesson: "depth-test",
        settings: &["depth=always", "order=far-first"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "depth-test-view-depth",
        lesson: "depth-test",
        settings: &["view=depth"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "stencil-basics",
        lesson: "stencil-basics",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "stencil-basics-view-stencil",
        lesson: "stencil-basics",
        settings: &["view=stencil"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "stencil-basics-less",
        lesson: "stencil-basics",
        settings: &["compare=less"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "stencil-basics-always",
        lesson: "stencil-basics",
        settings: &["compare=always"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "stencil-basics-overdraw",
        lesson: "stencil-basics",
        settings: &["compare=always", "pass-op=increment-clamp", "view=stencil"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "mark-mirror",
        lesson: "mark-mirror",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "mark-mirror-no-depth-test",
        lesson: "mark-mirror",
        settings: &["mark-depth-test=off"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "mark-mirror-color",
        lesson: "mark-mirror",
        settings: &["view=color"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "reflect-skull",
        lesson: "reflect-skull",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "reflect-skull-behind",
        lesson: "reflect-skull",
        settings: &[],
        camera: Some(BEHIND_THE_WALL),
        threshold: STRICT,
    },
    Shot {
        name: "reflect-skull-no-stencil-behind",
        lesson: "reflect-skull",
        settings: &["stencil=off"],
        camera: Some(BEHIND_THE_WALL),
        threshold: STRICT,
    },
    Shot {
        name: "reflect-skull-unreflected-lights",
        lesson: "reflect-skull",
        settings: &["reflect-lights=off"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "winding-fix",
        lesson: "winding-fix",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "winding-fix-off",
        lesson: "winding-fix",
        settings: &["winding-fix=off"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "transparent-mirror",
        lesson: "transparent-mirror",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "transparent-mirror-opaque",
        lesson: "transparent-mirror",
        settings: &["blend=off"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "transparent-mirror-alpha-0.25",
        lesson: "transparent-mirror",
        settings: &["mirror-alpha=0.25"],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "drawing-order",
        lesson: "drawing-order",
        settings: &[],
        camera: None,
        threshold: STRICT,
    },
    Shot {
        name: "drawing-order-luna",
        lesson: "drawing-order",
        settings: &["order=luna"],
        camera: None,
        threshold: STRICT,
    },
];

/// A camera behind the wall and to one side, where Luna's figure 10.1 looks from: the reflected
/// skull stands between it and the wall's back.
pub const BEHIND_THE_WALL: &str = "140,12,10";

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
        if let Some(camera) = self.camera {
            command += &format!(" --camera {camera}");
        }
        command + &format!(" --screenshot {}.png", self.name)
    }

    pub fn render(&self) -> Result<RgbaImage> {
        let camera = self.camera.map(Camera::parse).transpose()?;
        let capture = render(self.lesson, self.settings, |request| {
            (request.width, request.height) = SIZE;
            if let Some(camera) = camera {
                request.camera = camera;
            }
        })?;
        Ok(capture.color)
    }

    /// Renders the shot and compares it with its reference.
    pub fn check(&self) -> Result<()> {
        check_image(self.name, &self.render()?, self.threshold)
    }
}

/// Every lesson by package name, in the book's order.
pub const LESSONS: &[&str] = &[
    "depth-test",
    "stencil-basics",
    "mark-mirror",
    "reflect-skull",
    "winding-fix",
    "transparent-mirror",
    "drawing-order",
];

/// The knobs of a lesson, by package name.
pub fn knobs(lesson: &str) -> Result<&'static [workbook::Knob]> {
    Ok(match lesson {
        "depth-test" => depth_test::DepthTest::KNOBS,
        "stencil-basics" => stencil_basics::StencilBasics::KNOBS,
        "mark-mirror" => mark_mirror::MarkMirror::KNOBS,
        "reflect-skull" => reflect_skull::ReflectSkull::KNOBS,
        "winding-fix" => winding_fix::WindingFix::KNOBS,
        "transparent-mirror" => transparent_mirror::TransparentMirror::KNOBS,
        "drawing-order" => drawing_order::DrawingOrder::KNOBS,
        other => bail!("there is no lesson called `{other}`"),
    })
}

/// Renders lesson `lesson` headless with these knob settings, after `adjust` changed the request.
pub fn render(
    lesson: &str,
    settings: &[&str],
    adjust: impl FnOnce(&mut Request),
) -> Result<Capture> {
    let settings: Vec<String> = settings.iter().map(|s| s.to_string()).collect();
    let mut captures = render_each(lesson, &[settings], adjust)?;
    Ok(captures.remove(0))
}

/// Renders lesson `lesson` once per entry of `each` (knob settings), building the GPU and the room
/// once; fails on the first setting that fails.
pub fn render_each(
    lesson: &str,
    each: &[Vec<String>],
    adjust: impl FnOnce(&mut Request),
) -> Result<Vec<Capture>> {
    fn go<L: Lesson>(
        each: &[Vec<String>],
        adjust: impl FnOnce(&mut Request),
    ) -> Result<Vec<Capture>> {
        let first = each.first().map(Vec::as_slice).unwrap_or_default();
        let mut request = Request::new::<L>(first)?;
        adjust(&mut request);
        let mut headless = Headless::<L>::new(&request)?;
        let mut captures = Vec::with_capacity(each.len());
        for (index, settings) in each.iter().enumerate() {
            let knobs = Knobs::from_settings(L::KNOBS, settings)?;
            // The first settings were built with the request already.
            let rebuilt = if index == 0 {
                Ok(())
            } else {
                headless.set_knobs(knobs)
            };
            let capture = rebuilt
                .and_then(|()| headless.capture())
                .with_context(|| format!("{} --set {}", L::NAME, settings.join(" --set ")))?;
            captures.push(capture);
        }
        Ok(captures)
    }
    match lesson {
        "depth-test" => go::<depth_test::DepthTest>(each, adjust),
        "stencil-basics" => go::<stencil_basics::StencilBasics>(each, adjust),
        "mark-mirror" => go::<mark_mirror::MarkMirror>(each, adjust),
        "reflect-skull" => go::<reflect_skull::ReflectSkull>(each, adjust),
        "winding-fix" => go::<winding_fix::WindingFix>(each, adjust),
        "transparent-mirror" => go::<transparent_mirror::TransparentMirror>(each, adjust),
        "drawing-order" => go::<drawing_order::DrawingOrder>(each, adjust),
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
