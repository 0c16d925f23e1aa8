//! Every lesson by its package name, in the book's order: the one place that maps a lesson's name
//! to its type, for the tools that take a name (`cargo screenshots`, the benchmark, the tests) and
//! for the web edition's module, which runs whichever lesson its page names.

use anyhow::{Result, bail};
use workbook::Lesson;

/// Every lesson by package name, in the book's order.
pub const LESSONS: &[&str] = &[
    "depth-test",
    "stencil-basics",
    "mark-mirror",
    "reflect-skull",
    "winding-fix",
    "transparent-mirror",
    "drawing-order",
    "floor-mirror",
    "render-to-texture",
    "planar-shadow",
    "two-mirrors",
];

/// Something to do with a lesson's type, given its package name: see [`for_lesson`].
pub trait ForLesson {
    type Output;
    fn run<L: Lesson>(self) -> Self::Output;
}

/// Runs `task` with the lesson called `lesson`.
pub fn for_lesson<T: ForLesson>(lesson: &str, task: T) -> Result<T::Output> {
    Ok(match lesson {
        "depth-test" => task.run::<depth_test::DepthTest>(),
        "stencil-basics" => task.run::<stencil_basics::StencilBasics>(),
        "mark-mirror" => task.run::<mark_mirror::MarkMirror>(),
        "reflect-skull" => task.run::<reflect_skull::ReflectSkull>(),
        "winding-fix" => task.run::<winding_fix::WindingFix>(),
        "transparent-mirror" => task.run::<transparent_mirror::TransparentMirror>(),
        "drawing-order" => task.run::<drawing_order::DrawingOrder>(),
        "floor-mirror" => task.run::<floor_mirror::FloorMirror>(),
        "render-to-texture" => task.run::<render_to_texture::RenderToTexture>(),
        "planar-shadow" => task.run::<planar_shadow::PlanarShadow>(),
        "two-mirrors" => task.run::<two_mirrors::TwoMirrors>(),
        other => bail!("there is no lesson called `{other}`"),
    })
}
