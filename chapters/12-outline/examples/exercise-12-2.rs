//! Lesson 12, exercise 2: the crate selected too, with a bit of its own (0b100), and outlined in
//! blue: scaled about its centre, since grown along its normals its corners tear open.

use outline::{Outline, SHADER};
use workbook::glam::{Mat4, Vec3};
use workbook::gpu::states;
use workbook::room::scene::Placed;
use workbook::wgpu::{self, CompareFunction, StencilFaceState, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Recipe, Scene};

pub struct Solution {
    lesson: Outline,
    select_crate: wgpu::RenderPipeline,
    outline_crate: wgpu::RenderPipeline,
    /// The crate scaled about its centre (crate-grow=scale), or `None`: grown along its normals.
    scaled: Option<Placed>,
}

// ANCHOR: solution
/// The crate's bit, beside the mirror's (0b01) and the skull's (0b10).
pub const CRATE_BIT: u32 = 0b100;

/// How much bigger the crate's copy is, about its centre.
pub const CRATE_SCALE: f32 = 1.05;

pub const KNOBS: &[Knob] = &[Knob {
    name: "crate-grow",
    values: &["scale", "normals"],
    default: "scale",
    meaning: "the crate's copy scaled about its centre, or grown along its normals as the skull's is",
}];

/// The blue of the crate's outline, an entry beside the lesson's own.
const CRATE_COLOUR: &str = "
@fragment
fn fs_crate_outline(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(0.0, 0.3, 1.0, 1.0);
}";

/// The crate drawn again where it was drawn (LessEqual), setting its bit and nothing else.
const SELECT_CRATE: Recipe = Recipe {
    name: "SELECT_CRATE",
    depth_write: false,
    depth_compare: CompareFunction::LessEqual,
    stencil: wgpu::StencilState {
        front: FACE_REPLACE,
        back: FACE_REPLACE,
        read_mask: 0,
        write_mask: CRATE_BIT,
    },
    color_writes: wgpu::ColorWrites::empty(),
    ..states::OPAQUE
};

const FACE_REPLACE: StencilFaceState = StencilFaceState {
    compare: CompareFunction::Always,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Replace,
    pass_op: StencilOperation::Replace,
};

/// The crate's outline: where its bit is clear, reading that bit only.
const OUTLINE_CRATE: Recipe = Recipe {
    name: "OUTLINE_CRATE",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    stencil: wgpu::StencilState {
        front: StencilFaceState {
            compare: CompareFunction::NotEqual,
            ..StencilFaceState::IGNORE
        },
        back: StencilFaceState {
            compare: CompareFunction::NotEqual,
            ..StencilFaceState::IGNORE
        },
        read_mask: CRATE_BIT,
        write_mask: 0,
    },
    ..states::OPAQUE
};

/// The crate's world matrix scaled about its centre: every point moves straight away from it.
fn scaled_about_centre(world: Mat4, centre: Vec3) -> Mat4 {
    Mat4::from_translation(centre)
        * Mat4::from_scale(Vec3::splat(CRATE_SCALE))
        * Mat4::from_translation(-centre)
        * world
}

impl Solution {
    fn select_and_outline_the_crate(&self, frame: &mut Frame<'_>) {
        let crate_box = &frame.scene.crate_box;
        frame.step("select the crate", |pass| {
            pass.set_pipeline(&self.select_crate);
            pass.set_stencil_reference(CRATE_BIT);
            crate_box.draw(pass);
        });
        frame.step("outline the crate", |pass| {
            pass.set_pipeline(&self.outline_crate);
            pass.set_stencil_reference(CRATE_BIT);
            match &self.scaled {
                Some(scaled) => crate_box.draw_placed(pass, scaled),
                None => crate_box.draw(pass),
            }
        });
    }
}
// ANCHOR_END: solution

impl Lesson for Solution {
    const NAME: &'static str = "outline-exercise-2";
    const TITLE: &'static str = "Lesson 12, exercise 2: the crate selected too";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let lesson_knobs = Knobs::defaults(outline::KNOBS);
        let shader = scene.shader_with(device, "outline.wgsl", &format!("{SHADER}{CRATE_COLOUR}"));
        let scale = knobs.get("crate-grow") == "scale";
        let vertex = if scale { "vs_main" } else { "vs_grown" };
        let crate_box = &scene.crate_box;
        let world = scaled_about_centre(crate_box.world(), crate_box.centre());
        Ok(Self {
            lesson: Outline::new(gpu, scene, &lesson_knobs)?,
            select_crate: scene.pipeline(device, &SELECT_CRATE),
            outline_crate: scene.pipeline_in(
                device,
                &OUTLINE_CRATE,
                (&shader, vertex, "fs_crate_outline"),
            ),
            scaled: scale.then(|| scene.placed(device, crate_box, world)),
        })
    }

    fn render(&self, frame: &mut Frame<'_>) {
        self.lesson.render(frame);
        self.select_and_outline_the_crate(frame);
    }
}

fn main() -> std::process::ExitCode {
    workbook::main::<Solution>()
}
