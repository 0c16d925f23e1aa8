//! The catalogue of the book's screenshots. Each is made by the project's own command
//! (`cargo screenshots`, which renders this list), shown in the book, and checked by the tests
//! against the committed file with the threshold given here.

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use image::RgbaImage;
use workbook::app::headless::{Capture, Headless, Request, Still};
use workbook::book::shots::{self as book_shots, BookShot};
use workbook::lesson::story::Story;
use workbook::room::camera::Camera;
use workbook::{Knobs, Lesson, Show};

use crate::flip::{self, Threshold};

/// The size of every screenshot in the book.
pub use workbook::book::shots::SIZE;

/// The limit every screenshot is judged by (see its comment).
pub use workbook::book::flip::STRICT;

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
    /// The buffer shown, where it is not the lesson's own (`--show`).
    pub show: Option<Show>,
    /// The step the frame stops after, by name (`--step`, which takes its number).
    pub step: Option<&'static str>,
    pub threshold: Threshold,
    /// Why the picture is the driver's own choice, if it is (z-fighting: which of two surfaces at
    /// one depth wins is decided by the rasteriser's rounding). Such a picture is never compared
    /// with its reference; a test of its lesson judges it by what it teaches.
    pub driver_dependent: Option<&'static str>,
}

/// What the entries of [`SHOTS`] leave out: default knobs, camera and buffer, the strict threshold.
const SHOT: Shot = Shot {
    name: "",
    lesson: "",
    settings: &[],
    camera: None,
    show: None,
    step: None,
    threshold: STRICT,
    driver_dependent: None,
};

pub const SHOTS: &[Shot] = &[
    Shot {
        name: "depth-test",
        lesson: "depth-test",
        ..SHOT
    },
    Shot {
        name: "depth-test-always",
        lesson: "depth-test",
        settings: &["depth=always"],
        ..SHOT
    },
    Shot {
        name: "depth-test-painter",
        lesson: "depth-test",
        settings: &["depth=always", "order=far-first"],
        ..SHOT
    },
    Shot {
        name: "depth-test-show-depth",
        lesson: "depth-test",
        show: Some(Show::Depth),
        ..SHOT
    },
    Shot {
        name: "depth-test-show-raw-depth",
        lesson: "depth-test",
        show: Some(Show::RawDepth),
        ..SHOT
    },
    Shot {
        name: "stencil-basics",
        lesson: "stencil-basics",
        ..SHOT
    },
    Shot {
        name: "stencil-basics-show-stencil",
        lesson: "stencil-basics",
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "stencil-basics-less",
        lesson: "stencil-basics",
        settings: &["compare=less"],
        ..SHOT
    },
    Shot {
        name: "stencil-basics-always",
        lesson: "stencil-basics",
        settings: &["compare=always"],
        ..SHOT
    },
    Shot {
        name: "stencil-basics-overdraw",
        lesson: "stencil-basics",
        settings: &["compare=always", "pass-op=increment-clamp"],
        show: Some(Show::Stencil),
        ..SHOT
    },
    // Lesson 3 shows the stencil buffer unless told otherwise.
    Shot {
        name: "mark-mirror",
        lesson: "mark-mirror",
        ..SHOT
    },
    Shot {
        name: "mark-mirror-tests",
        lesson: "mark-mirror",
        show: Some(Show::Tests),
        step: Some("mark the mirror"),
        ..SHOT
    },
    Shot {
        name: "mark-mirror-no-depth-test",
        lesson: "mark-mirror",
        settings: &["mark-depth-test=off"],
        ..SHOT
    },
    Shot {
        name: "mark-mirror-color",
        lesson: "mark-mirror",
        show: Some(Show::Color),
        ..SHOT
    },
    Shot {
        name: "reflect-skull",
        lesson: "reflect-skull",
        ..SHOT
    },
    Shot {
        name: "reflect-skull-behind",
        lesson: "reflect-skull",
        camera: Some(BEHIND_THE_WALL),
        ..SHOT
    },
    Shot {
        name: "reflect-skull-no-stencil-behind",
        lesson: "reflect-skull",
        settings: &["stencil=off"],
        camera: Some(BEHIND_THE_WALL),
        ..SHOT
    },
    Shot {
        name: "reflect-skull-unreflected-lights",
        lesson: "reflect-skull",
        settings: &["reflect-lights=off"],
        ..SHOT
    },
    Shot {
        name: "winding-fix",
        lesson: "winding-fix",
        ..SHOT
    },
    Shot {
        name: "winding-fix-off",
        lesson: "winding-fix",
        settings: &["winding-fix=off"],
        ..SHOT
    },
    Shot {
        name: "transparent-mirror",
        lesson: "transparent-mirror",
        ..SHOT
    },
    Shot {
        name: "transparent-mirror-opaque",
        lesson: "transparent-mirror",
        settings: &["blend=off"],
        ..SHOT
    },
    Shot {
        name: "transparent-mirror-alpha-0.25",
        lesson: "transparent-mirror",
        settings: &["mirror-alpha=0.25"],
        ..SHOT
    },
    Shot {
        name: "drawing-order",
        lesson: "drawing-order",
        ..SHOT
    },
    Shot {
        name: "drawing-order-complexity",
        lesson: "drawing-order",
        show: Some(Show::Complexity),
        // Judged by tests/suite/maps.rs (the count against the pixels' stories, on any driver):
        // the wire fence's alpha test throws away the fragments where its filtered texels fall
        // below the cut-off, and which those are is the driver's texture filtering (SwiftShader's
        // count differs from lavapipe's in 1.1% of the pixels, all on the fence).
        driver_dependent: Some("texture filtering"),
        ..SHOT
    },
    Shot {
        name: "drawing-order-luna",
        lesson: "drawing-order",
        settings: &["order=luna"],
        ..SHOT
    },
    Shot {
        name: "floor-mirror",
        lesson: "floor-mirror",
        ..SHOT
    },
    Shot {
        name: "floor-mirror-spe",
        lesson: "floor-mirror",
        settings: &["recipe=spe"],
        ..SHOT
    },
    Shot {
        name: "floor-mirror-always",
        lesson: "floor-mirror",
        settings: &["recipe=always"],
        ..SHOT
    },
    Shot {
        name: "floor-mirror-sunk",
        lesson: "floor-mirror",
        settings: &["sink=2"],
        ..SHOT
    },
    Shot {
        name: "floor-mirror-sunk-unclipped",
        lesson: "floor-mirror",
        settings: &["sink=2", "clip=off"],
        ..SHOT
    },
    Shot {
        name: "render-to-texture",
        lesson: "render-to-texture",
        ..SHOT
    },
    Shot {
        name: "render-to-texture-texture",
        lesson: "render-to-texture",
        step: Some("render the reflection into a texture"),
        ..SHOT
    },
    Shot {
        name: "render-to-texture-64",
        lesson: "render-to-texture",
        settings: &["resolution=64"],
        ..SHOT
    },
    Shot {
        name: "render-to-texture-wall",
        lesson: "render-to-texture",
        settings: &["plane=wall"],
        ..SHOT
    },
    Shot {
        name: "render-to-texture-wall-rastertek",
        lesson: "render-to-texture",
        settings: &["plane=wall", "camera=rastertek"],
        ..SHOT
    },
    Shot {
        name: "render-to-texture-sunk",
        lesson: "render-to-texture",
        settings: &["sink=2"],
        ..SHOT
    },
    Shot {
        name: "render-to-texture-unclipped",
        lesson: "render-to-texture",
        settings: &["sink=2", "clip=off"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow",
        lesson: "planar-shadow",
        ..SHOT
    },
    Shot {
        name: "planar-shadow-double-blend",
        lesson: "planar-shadow",
        settings: &["no-double-blend=off"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-wall",
        lesson: "planar-shadow",
        settings: &["surface=wall", "light=point"],
        camera: Some("-20,15,10"),
        ..SHOT
    },
    Shot {
        name: "planar-shadow-point",
        lesson: "planar-shadow",
        settings: &["light=point"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-spot",
        lesson: "planar-shadow",
        settings: &["light=spot"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-unreflected",
        lesson: "planar-shadow",
        settings: &["reflect-shadow=off"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-no-masks",
        lesson: "planar-shadow",
        settings: &["masks=off"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-z-fighting",
        lesson: "planar-shadow",
        settings: &["lift=none"],
        // Judged by tests/suite/planar_shadow.rs: the unlifted shadow loses to the floor in many
        // of its pixels, on any driver.
        driver_dependent: Some("z-fighting"),
        ..SHOT
    },
    Shot {
        name: "planar-shadow-depth-bias",
        lesson: "planar-shadow",
        settings: &["lift=depth-bias"],
        ..SHOT
    },
    Shot {
        name: "planar-shadow-stencil",
        lesson: "planar-shadow",
        show: Some(Show::Stencil),
        step: Some("draw the reflected shadow"),
        ..SHOT
    },
    Shot {
        name: "two-mirrors",
        lesson: "two-mirrors",
        ..SHOT
    },
    Shot {
        name: "two-mirrors-depth-1",
        lesson: "two-mirrors",
        settings: &["depth=1"],
        ..SHOT
    },
    Shot {
        name: "two-mirrors-depth-6",
        lesson: "two-mirrors",
        settings: &["depth=6"],
        ..SHOT
    },
    Shot {
        name: "two-mirrors-stencil",
        lesson: "two-mirrors",
        settings: &["depth=6"],
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "two-mirrors-complexity",
        lesson: "two-mirrors",
        settings: &["depth=6"],
        show: Some(Show::Complexity),
        ..SHOT
    },
    Shot {
        name: "two-mirrors-tests",
        lesson: "two-mirrors",
        show: Some(Show::Tests),
        step: Some("draw level 1"),
        ..SHOT
    },
    Shot {
        name: "two-mirrors-tests-2",
        lesson: "two-mirrors",
        show: Some(Show::Tests),
        step: Some("draw level 2"),
        ..SHOT
    },
    Shot {
        name: "two-mirrors-tests-3",
        lesson: "two-mirrors",
        show: Some(Show::Tests),
        step: Some("draw level 3"),
        ..SHOT
    },
    Shot {
        name: "two-mirrors-replace",
        lesson: "two-mirrors",
        settings: &["mark=replace"],
        ..SHOT
    },
    Shot {
        name: "two-mirrors-always-flipped",
        lesson: "two-mirrors",
        settings: &["winding=always-flipped"],
        ..SHOT
    },
    Shot {
        name: "floor-mirror-reflection-depth",
        lesson: "floor-mirror",
        settings: &["sink=2", "clip=discard"],
        show: Some(Show::Depth),
        step: Some("draw the reflection"),
        ..SHOT
    },
    Shot {
        name: "floor-mirror-oblique-depth",
        lesson: "floor-mirror",
        settings: &["sink=2", "clip=oblique"],
        show: Some(Show::Depth),
        step: Some("draw the reflection"),
        ..SHOT
    },
    // The answers of the lesson pages' "Predict the picture" questions.
    Shot {
        name: "outline",
        lesson: "outline",
        ..SHOT
    },
    Shot {
        name: "outline-stencil",
        lesson: "outline",
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "outline-no-stencil",
        lesson: "outline",
        settings: &["outline-stencil=off"],
        ..SHOT
    },
    Shot {
        name: "outline-scaled",
        lesson: "outline",
        settings: &["grow=scale"],
        ..SHOT
    },
    Shot {
        name: "outline-whole-byte",
        lesson: "outline",
        settings: &["masks=whole-byte"],
        ..SHOT
    },
    Shot {
        name: "outline-screen-space",
        lesson: "outline",
        settings: &["way=screen-space"],
        ..SHOT
    },
    Shot {
        name: "outline-screen-space-mask",
        lesson: "outline",
        settings: &["way=screen-space"],
        step: Some("draw the selection mask"),
        ..SHOT
    },
    Shot {
        name: "outline-behind-the-crate",
        lesson: "outline",
        camera: Some(BEHIND_THE_CRATE),
        ..SHOT
    },
    Shot {
        name: "outline-behind-the-crate-less",
        lesson: "outline",
        settings: &["outline-depth=less"],
        camera: Some(BEHIND_THE_CRATE),
        ..SHOT
    },
    Shot {
        name: "depth-complexity",
        lesson: "depth-complexity",
        ..SHOT
    },
    Shot {
        name: "depth-complexity-passed",
        lesson: "depth-complexity",
        settings: &["count=passed-depth"],
        ..SHOT
    },
    Shot {
        name: "depth-complexity-blend",
        lesson: "depth-complexity",
        settings: &["way=blend"],
        ..SHOT
    },
    Shot {
        name: "depth-complexity-counts",
        lesson: "depth-complexity",
        step: Some("count the fragments"),
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "depth-complexity-stack",
        lesson: "depth-complexity",
        settings: &["stack=64"],
        ..SHOT
    },
    Shot {
        name: "depth-complexity-wrap",
        lesson: "depth-complexity",
        settings: &["stack=64", "increment=wrap"],
        ..SHOT
    },
    Shot {
        name: "shadow-volume",
        lesson: "shadow-volume",
        ..SHOT
    },
    Shot {
        name: "shadow-volume-volumes",
        lesson: "shadow-volume",
        settings: &["see-volumes=on"],
        ..SHOT
    },
    Shot {
        name: "shadow-volume-counts",
        lesson: "shadow-volume",
        step: Some("count the volumes"),
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "shadow-volume-inside",
        lesson: "shadow-volume",
        camera: Some(IN_THE_SKULLS_SHADOW),
        ..SHOT
    },
    Shot {
        name: "shadow-volume-inside-z-pass",
        lesson: "shadow-volume",
        settings: &["method=z-pass"],
        camera: Some(IN_THE_SKULLS_SHADOW),
        ..SHOT
    },
    Shot {
        name: "shadow-volume-no-caps",
        lesson: "shadow-volume",
        settings: &["caps=off"],
        ..SHOT
    },
    Shot {
        name: "shadow-volume-clamp",
        lesson: "shadow-volume",
        settings: &["increment=clamp"],
        ..SHOT
    },
    Shot {
        name: "capping",
        lesson: "capping",
        ..SHOT
    },
    Shot {
        name: "capping-open",
        lesson: "capping",
        settings: &["cap=off"],
        ..SHOT
    },
    Shot {
        name: "capping-counts",
        lesson: "capping",
        settings: &["crate=through"],
        step: Some("count the inside"),
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "capping-crate",
        lesson: "capping",
        settings: &["crate=through"],
        ..SHOT
    },
    Shot {
        name: "capping-parity",
        lesson: "capping",
        settings: &["crate=through", "count=invert"],
        ..SHOT
    },
    Shot {
        name: "capping-holed",
        lesson: "capping",
        settings: &["mesh=holed"],
        ..SHOT
    },
    Shot {
        name: "portal",
        lesson: "portal",
        ..SHOT
    },
    Shot {
        name: "portal-uncut",
        lesson: "portal",
        settings: &["clip=off"],
        ..SHOT
    },
    Shot {
        name: "portal-not-cleared",
        lesson: "portal",
        settings: &["clear-behind=off"],
        ..SHOT
    },
    Shot {
        name: "portal-doorway-first",
        lesson: "portal",
        settings: &["order=doorway-first"],
        ..SHOT
    },
    Shot {
        name: "portal-depth-0",
        lesson: "portal",
        settings: &["depth=0"],
        ..SHOT
    },
    Shot {
        name: "portal-depth-1",
        lesson: "portal",
        settings: &["depth=1"],
        ..SHOT
    },
    Shot {
        name: "portal-depth-2",
        lesson: "portal",
        settings: &["depth=2"],
        ..SHOT
    },
    Shot {
        name: "portal-levels",
        lesson: "portal",
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "predict-depth-test-not-equal",
        lesson: "depth-test",
        settings: &["depth=not-equal"],
        ..SHOT
    },
    Shot {
        name: "predict-stencil-basics-greater",
        lesson: "stencil-basics",
        settings: &["compare=greater"],
        ..SHOT
    },
    Shot {
        name: "predict-stencil-basics-masked",
        lesson: "stencil-basics",
        settings: &["reference=3", "read-mask=0x01"],
        ..SHOT
    },
    Shot {
        name: "predict-mark-mirror-behind",
        lesson: "mark-mirror",
        camera: Some(BEHIND_THE_WALL),
        ..SHOT
    },
    Shot {
        name: "predict-reflect-skull-no-stencil",
        lesson: "reflect-skull",
        settings: &["stencil=off"],
        ..SHOT
    },
    Shot {
        name: "predict-winding-fix-no-culling",
        lesson: "winding-fix",
        settings: &["winding-fix=no-culling"],
        ..SHOT
    },
    Shot {
        name: "predict-transparent-mirror-opaque-alpha-0",
        lesson: "transparent-mirror",
        settings: &["mirror-alpha=0", "blend=off"],
        ..SHOT
    },
    Shot {
        name: "predict-drawing-order-luna-stencil",
        lesson: "drawing-order",
        settings: &["order=luna"],
        show: Some(Show::Stencil),
        ..SHOT
    },
    Shot {
        name: "predict-floor-mirror-clip-off",
        lesson: "floor-mirror",
        settings: &["clip=off"],
        ..SHOT
    },
    Shot {
        name: "predict-render-to-texture-rastertek",
        lesson: "render-to-texture",
        settings: &["camera=rastertek"],
        ..SHOT
    },
    Shot {
        name: "predict-planar-shadow-wall-double-blend",
        lesson: "planar-shadow",
        settings: &["surface=wall", "light=point", "no-double-blend=off"],
        // planar-shadow-wall's pose, -20,15,10, with a yaw a command line takes without `=`.
        camera: Some("340,15,10"),
        ..SHOT
    },
    Shot {
        name: "predict-two-mirrors-depth-0",
        lesson: "two-mirrors",
        settings: &["depth=0"],
        ..SHOT
    },
    Shot {
        name: "predict-outline-image-unoutlined",
        lesson: "outline",
        settings: &["reflected-outline=off"],
        ..SHOT
    },
    Shot {
        name: "predict-outline-whole-byte-unoutlined",
        lesson: "outline",
        settings: &["masks=whole-byte", "reflected-outline=off"],
        ..SHOT
    },
    Shot {
        name: "predict-depth-complexity-blend-stack",
        lesson: "depth-complexity",
        settings: &["way=blend", "stack=64"],
        ..SHOT
    },
    Shot {
        name: "predict-shadow-volume-z-pass",
        lesson: "shadow-volume",
        settings: &["method=z-pass"],
        ..SHOT
    },
    Shot {
        name: "predict-shadow-volume-inside-no-caps",
        lesson: "shadow-volume",
        settings: &["caps=off"],
        camera: Some(IN_THE_SKULLS_SHADOW),
        ..SHOT
    },
    Shot {
        name: "predict-capping-invert",
        lesson: "capping",
        settings: &["count=invert"],
        ..SHOT
    },
    Shot {
        name: "predict-capping-deeper",
        lesson: "capping",
        settings: &["cut=0.3"],
        ..SHOT
    },
    Shot {
        name: "predict-portal-oblique",
        lesson: "portal",
        settings: &["clip=oblique"],
        ..SHOT
    },
    Shot {
        name: "predict-portal-side",
        lesson: "portal",
        camera: Some("35,10,8"),
        ..SHOT
    },
];

/// A wrong picture of the book and the right one it is shown beside. `cargo screenshots` makes an
/// enlarged crop of where they differ and the difference image for each (see [`crate::pairs`]).
#[derive(Debug)]
pub struct Pair {
    /// The names of two shots of [`SHOTS`].
    pub wrong: &'static str,
    pub right: &'static str,
}

pub const PAIRS: &[Pair] = &[
    Pair {
        wrong: "depth-test-always",
        right: "depth-test",
    },
    Pair {
        wrong: "stencil-basics-always",
        right: "stencil-basics",
    },
    Pair {
        wrong: "mark-mirror-no-depth-test",
        right: "mark-mirror",
    },
    Pair {
        wrong: "reflect-skull-no-stencil-behind",
        right: "reflect-skull-behind",
    },
    Pair {
        wrong: "reflect-skull-unreflected-lights",
        right: "reflect-skull",
    },
    Pair {
        wrong: "winding-fix-off",
        right: "winding-fix",
    },
    Pair {
        wrong: "transparent-mirror-opaque",
        right: "transparent-mirror",
    },
    Pair {
        wrong: "drawing-order-luna",
        right: "drawing-order",
    },
    Pair {
        wrong: "floor-mirror-spe",
        right: "floor-mirror",
    },
    Pair {
        wrong: "floor-mirror-always",
        right: "floor-mirror",
    },
    Pair {
        wrong: "floor-mirror-sunk-unclipped",
        right: "floor-mirror-sunk",
    },
    Pair {
        wrong: "render-to-texture-64",
        right: "render-to-texture",
    },
    Pair {
        wrong: "render-to-texture-wall-rastertek",
        right: "render-to-texture-wall",
    },
    Pair {
        wrong: "render-to-texture-unclipped",
        right: "render-to-texture-sunk",
    },
    Pair {
        wrong: "planar-shadow-double-blend",
        right: "planar-shadow",
    },
    Pair {
        wrong: "planar-shadow-no-masks",
        right: "planar-shadow",
    },
    Pair {
        wrong: "planar-shadow-unreflected",
        right: "planar-shadow",
    },
    Pair {
        wrong: "planar-shadow-z-fighting",
        right: "planar-shadow",
    },
    Pair {
        wrong: "two-mirrors-replace",
        right: "two-mirrors",
    },
    Pair {
        wrong: "two-mirrors-always-flipped",
        right: "two-mirrors",
    },
    Pair {
        wrong: "outline-no-stencil",
        right: "outline",
    },
    Pair {
        wrong: "outline-scaled",
        right: "outline",
    },
    Pair {
        wrong: "outline-whole-byte",
        right: "outline",
    },
    Pair {
        wrong: "depth-complexity-wrap",
        right: "depth-complexity-stack",
    },
    Pair {
        wrong: "shadow-volume-inside-z-pass",
        right: "shadow-volume-inside",
    },
    Pair {
        wrong: "shadow-volume-no-caps",
        right: "shadow-volume",
    },
    Pair {
        wrong: "shadow-volume-clamp",
        right: "shadow-volume",
    },
    Pair {
        wrong: "capping-open",
        right: "capping",
    },
    Pair {
        wrong: "capping-parity",
        right: "capping-crate",
    },
    Pair {
        wrong: "capping-holed",
        right: "capping",
    },
    Pair {
        wrong: "portal-uncut",
        right: "portal",
    },
    Pair {
        wrong: "portal-not-cleared",
        right: "portal",
    },
    Pair {
        wrong: "portal-doorway-first",
        right: "portal",
    },
];

/// A camera behind the wall and to one side, where Luna's figure 10.1 looks from: the reflected
/// skull stands between it and the wall's back.
pub const BEHIND_THE_WALL: &str = "140,12,10";

/// A camera low and to the right, where the crate hides the skull's jaw (lesson 12's outline
/// depth test).
pub const BEHIND_THE_CRATE: &str = "72,-3,7";

/// Lesson 14's `IN_THE_SKULLS_SHADOW`: the eye low behind the skull, inside its shadow volume.
pub const IN_THE_SKULLS_SHADOW: &str = "9,-18,3.8";

impl Shot {
    pub fn path(&self) -> PathBuf {
        crate::images().join(format!("{}.png", self.name))
    }

    /// The command a reader types to make this picture.
    pub fn command(&self) -> Result<String> {
        let arguments = self.arguments()?.join(" ");
        Ok(format!(
            "cargo run -p {} -- {arguments} --screenshot {}.png",
            self.lesson, self.name
        ))
    }

    /// The arguments of the lesson's command line that make this picture (all but `--screenshot`).
    pub fn arguments(&self) -> Result<Vec<String>> {
        let mut arguments = vec!["--size".to_string(), format!("{}x{}", SIZE.0, SIZE.1)];
        for setting in self.settings {
            arguments.extend(["--set".to_string(), setting.to_string()]);
        }
        if let Some(camera) = self.camera {
            arguments.extend(["--camera".to_string(), camera.to_string()]);
        }
        if let Some(show) = self.show {
            arguments.extend(["--show".to_string(), show.name().to_string()]);
        }
        if let Some(stop) = self.stop()
            && let workbook::Stop::After(number) = stop?
        {
            arguments.extend(["--step".to_string(), number.to_string()]);
        }
        Ok(arguments)
    }

    /// The shot as the book's list of screenshots holds it (for the window and `--check`).
    pub fn book_shot(&self) -> Result<BookShot> {
        Ok(BookShot {
            name: self.name.to_string(),
            lesson: self.lesson.to_string(),
            arguments: self.arguments()?,
            driver_dependent: self.driver_dependent.map(str::to_string),
        })
    }

    /// Where the shot's frame stops, when it names a step.
    fn stop(&self) -> Option<Result<workbook::Stop>> {
        self.step
            .map(|step| after_step(self.lesson, self.settings, step))
    }

    /// Renders the shot at the book's size.
    pub fn render(&self) -> Result<RgbaImage> {
        self.render_at(SIZE)
    }

    /// Renders the shot at another size (the zoomed crops of [`Pair`] use a larger one).
    pub fn render_at(&self, size: (u32, u32)) -> Result<RgbaImage> {
        let camera = self.camera.map(Camera::parse).transpose()?;
        let stop = self.stop().transpose()?;
        let capture = render(self.lesson, self.settings, |request| {
            (request.width, request.height) = size;
            if let Some(camera) = camera {
                request.camera = camera;
            }
            if let Some(show) = self.show {
                request.show = show;
            }
            if let Some(stop) = stop {
                request.stop = stop;
            }
        })?;
        Ok(capture.color)
    }

    /// The shot called `name`.
    pub fn named(name: &str) -> Result<&'static Shot> {
        SHOTS
            .iter()
            .find(|shot| shot.name == name)
            .with_context(|| format!("there is no screenshot called `{name}`"))
    }

    /// Renders the shot and compares it with its reference; a driver-dependent shot's reference
    /// must exist, at the book's size, and is not compared.
    pub fn check(&self) -> Result<()> {
        if self.driver_dependent.is_some() {
            let reference = flip::load(&self.path())
                .with_context(|| format!("the reference of {} is missing", self.name))?;
            if reference.dimensions() != SIZE {
                bail!(
                    "{} is {:?}, not {SIZE:?}",
                    self.path().display(),
                    reference.dimensions()
                );
            }
            return Ok(());
        }
        check_image(self.name, &self.render()?, self.threshold)
    }
}

/// The driver that drew the book's pictures: Mesa 22.3's lavapipe (Debian 12's), on Vulkan.
/// `cargo screenshots` on it remakes them bit for bit, so where a picture is the driver's own
/// choice (z-fighting) the tests compare it only on this driver.
pub const BOOK_DRIVER: &str = "Mesa 22.3.6";

/// Whether `adapter` is the driver that drew the book ([`BOOK_DRIVER`]).
pub fn drew_the_book(adapter: &workbook::wgpu::AdapterInfo) -> bool {
    adapter.backend == workbook::wgpu::Backend::Vulkan
        && adapter.device_type == workbook::wgpu::DeviceType::Cpu
        && adapter.driver_info.starts_with(BOOK_DRIVER)
}

/// The book's list of screenshots (`book/src/images/shots.txt`) as the catalogue makes it.
pub fn list_text() -> Result<String> {
    let shots = SHOTS
        .iter()
        .map(Shot::book_shot)
        .collect::<Result<Vec<_>>>()?;
    Ok(book_shots::list_text(&shots))
}

pub use lessons::{ForLesson, LESSONS, for_lesson};

/// The knobs of a lesson, by package name.
pub fn knobs(lesson: &str) -> Result<&'static [workbook::Knob]> {
    struct Knobs;
    impl ForLesson for Knobs {
        type Output = &'static [workbook::Knob];
        fn run<L: Lesson>(self) -> Self::Output {
            L::KNOBS
        }
    }
    for_lesson(lesson, Knobs)
}

/// Every value of every knob of a lesson, one knob at a time, as `--set` settings. Of the 256
/// values of a byte knob (a stencil reference or mask) it takes the ones at the edges and a few
/// between: they all run the same code, and 768 renders would cost minutes on a software GPU.
pub fn every_knob_value(lesson: &str) -> Result<Vec<Vec<String>>> {
    let mut each = Vec::new();
    for knob in knobs(lesson)? {
        let values: Vec<&str> = if knob.values.len() > 16 {
            [0, 1, 2, 15, 16, 127, 128, 254, 255]
                .iter()
                .filter_map(|&i| knob.values.get(i).copied())
                .collect()
        } else {
            knob.values.to_vec()
        };
        for value in values {
            each.push(vec![format!("{}={value}", knob.name)]);
        }
    }
    Ok(each)
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
    struct Each<'a, A>(&'a [Vec<String>], A);
    impl<A: FnOnce(&mut Request)> ForLesson for Each<'_, A> {
        type Output = Result<Vec<Capture>>;
        fn run<L: Lesson>(self) -> Self::Output {
            let Each(each, adjust) = self;
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
    }
    for_lesson(lesson, Each(each, adjust))?
}

/// Where the frame of lesson `lesson` (with these knob settings) stops after the step called `step`.
pub fn after_step(lesson: &str, settings: &[&str], step: &str) -> Result<workbook::Stop> {
    struct Steps<'a>(&'a [&'a str]);
    impl ForLesson for Steps<'_> {
        type Output = Result<Vec<&'static str>>;
        fn run<L: Lesson>(self) -> Self::Output {
            let mut request = Request::new::<L>(self.0)?;
            (request.width, request.height) = (16, 16);
            Ok(Headless::<L>::new(&request)?.steps())
        }
    }
    let steps = for_lesson(lesson, Steps(settings))??;
    let number = steps.iter().position(|s| *s == step);
    let number = number.with_context(|| format!("{lesson} has no step `{step}`: {steps:?}"))?;
    Ok(workbook::Stop::After(number + 1))
}

/// Films lesson `lesson` headless with these knob settings: every step's three buffers.
pub fn film(
    lesson: &str,
    settings: &[&str],
    adjust: impl FnOnce(&mut Request),
) -> Result<Vec<Still>> {
    struct Film<'a, A>(&'a [&'a str], A);
    impl<A: FnOnce(&mut Request)> ForLesson for Film<'_, A> {
        type Output = Result<Vec<Still>>;
        fn run<L: Lesson>(self) -> Self::Output {
            let mut request = Request::new::<L>(self.0)?;
            (self.1)(&mut request);
            Headless::<L>::new(&request)?.film()
        }
    }
    for_lesson(lesson, Film(settings, adjust))?
}

/// The stories of `pixels` in lesson `lesson`'s frame with these knob settings, and the film of the
/// same frame (every step's buffers), from one lesson built once.
pub fn stories(
    lesson: &str,
    settings: &[&str],
    pixels: &[(u32, u32)],
    adjust: impl FnOnce(&mut Request),
) -> Result<(Vec<Story>, Vec<Still>)> {
    struct Stories<'a, A>(&'a [&'a str], &'a [(u32, u32)], A);
    impl<A: FnOnce(&mut Request)> ForLesson for Stories<'_, A> {
        type Output = Result<(Vec<Story>, Vec<Still>)>;
        fn run<L: Lesson>(self) -> Self::Output {
            let Stories(settings, pixels, adjust) = self;
            let mut request = Request::new::<L>(settings)?;
            adjust(&mut request);
            let headless = Headless::<L>::new(&request)?;
            let stories = pixels
                .iter()
                .map(|&pixel| headless.story(pixel, settings.join(" ")))
                .collect::<Result<_>>()?;
            Ok((stories, headless.film()?))
        }
    }
    for_lesson(lesson, Stories(settings, pixels, adjust))?
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
