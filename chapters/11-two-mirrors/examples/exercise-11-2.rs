//! Lesson 11, exercise 2: make each mirror reflect 80% of the light, as real mirrors absorb some,
//! so that an image seen after k reflections is 0.8^k as bright and the corridor darkens as it goes.

use two_mirrors::{MAX_DEPTH, TwoMirrors, level_reflection, second_mirror_world};
use workbook::glam::Mat4;
use workbook::gpu::states;
use workbook::room::camera::Camera;
use workbook::room::scene::{Material, Placed, SHADOW_MATERIAL};
use workbook::wgpu::{self, CompareFunction, StencilFaceState, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

/// How much of the light a mirror reflects.
pub const REFLECTS: f32 = 0.8;

const DARKEN_LEVEL: [&str; MAX_DEPTH] = [
    "darken level 1 and beyond",
    "darken level 2 and beyond",
    "darken level 3 and beyond",
    "darken level 4 and beyond",
    "darken level 5 and beyond",
    "darken level 6 and beyond",
];

pub struct Solution {
    lesson: TwoMirrors,
    darken: wgpu::RenderPipeline,
    /// The mirror through which level k is seen, for k = 1 to the depth, as dark glass.
    portals: Vec<Placed>,
}

impl Lesson for Solution {
    const NAME: &'static str = "two-mirrors-exercise-2";
    const TITLE: &'static str = "Lesson 11, exercise 2: mirrors that absorb light";
    const KNOBS: &'static [Knob] = two_mirrors::KNOBS;
    const CAMERA: Camera = TwoMirrors::CAMERA;

    // ANCHOR: solution
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let depth: usize = knobs.get("depth").parse()?;
        // Black at 20%: what it is blended over keeps 80% of its light.
        let glass = Material {
            alpha: 1.0 - REFLECTS,
            ..SHADOW_MATERIAL
        };
        let portals = (1..=depth)
            .map(|level| {
                let own = match (level - 1) % 2 {
                    0 => Mat4::IDENTITY,
                    _ => second_mirror_world(),
                };
                let world = level_reflection(level - 1) * own;
                scene.placed_as(&gpu.device, &scene.mirror, world, Some(glass))
            })
            .collect();
        Ok(Self {
            lesson: TwoMirrors::new(gpu, scene, knobs)?,
            darken: scene.pipeline(&gpu.device, &darken_recipe()),
            portals,
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
        // A pixel of level k is darkened by the portals of levels 1 to k: 0.8^k.
        let scene = frame.scene;
        for (level, portal) in (1..).zip(&self.portals) {
            frame.step(DARKEN_LEVEL[level - 1], |pass| {
                pass.set_pipeline(&self.darken);
                pass.set_stencil_reference(level as u32);
                scene.mirror.draw_placed(pass, portal);
            });
        }
    }
    // ANCHOR_END: solution
}

/// Where the stencil holds the reference or more (reference <= stored value), whatever the depth,
/// both sides, blended; the stencil and the depth stay as they are.
fn darken_recipe() -> Recipe {
    let at_least = StencilFaceState {
        compare: CompareFunction::LessEqual,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: StencilOperation::Keep,
    };
    Recipe {
        name: "DARKEN_LEVELS",
        depth_write: false,
        depth_compare: CompareFunction::Always,
        stencil: wgpu::StencilState {
            front: at_least,
            back: at_least,
            read_mask: 0xff,
            write_mask: 0,
        },
        cull_mode: None,
        ..states::TRANSPARENT
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
