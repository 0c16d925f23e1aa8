//! Lesson 13: depth complexity.
//!
//! How many fragments does each pixel receive? Frank Luna's exercise: draw the room with a stencil
//! that every fragment increments, then paint the screen level by level, one triangle over the
//! screen for each count k where the stencil equals k. The same count by additive blending beside
//! it, and what the count becomes past 255.

use workbook::gpu::pipelines::Stages;
use workbook::gpu::states;
use workbook::room::scene::Drawable;
use workbook::wgpu::{self, CompareFunction, StencilFaceState, StencilOperation};
use workbook::{Frame, Gpu, Knob, Knobs, Lesson, Pass, Recipe, Scene};

// ANCHOR: knobs
pub const KNOBS: &[Knob] = &[
    Knob {
        name: "count",
        values: &["every-fragment", "passed-depth"],
        default: "every-fragment",
        meaning: "count every fragment the rasteriser makes, or only those that pass the depth test (in the order they are drawn)",
    },
    Knob {
        name: "way",
        values: &["stencil", "blend"],
        default: "stencil",
        meaning: "count in the stencil buffer and paint the levels, or add an eighth of white per fragment",
    },
    Knob {
        name: "increment",
        values: &["clamp", "wrap"],
        default: "clamp",
        meaning: "what an increment does at 255: stay (IncrementClamp) or go round to 0 (IncrementWrap)",
    },
    Knob {
        name: "stack",
        values: &["1", "64"],
        default: "1",
        meaning: "how many times the room is drawn: 64 times pushes the counts past 255",
    },
];
// ANCHOR_END: knobs

/// The levels painted: 0 to 7 each in its colour, and 8 or more in white.
pub const LEVELS: u32 = 9;

/// The palette's shader and the additive way's fragment entry.
pub const SHADER: &str = include_str!("levels.wgsl");

// ANCHOR: recipes
/// COUNT: every fragment that reaches the stencil test increments the value there, and writes
/// nothing else. With count=every-fragment the depth test is `Always`; with count=passed-depth it
/// is the usual `Less` with depth writes, and a fragment that fails it keeps the value.
pub fn count(knobs: &Knobs) -> Recipe {
    let increment = match knobs.get("increment") {
        "wrap" => StencilOperation::IncrementWrap,
        _ => StencilOperation::IncrementClamp,
    };
    let every = knobs.get("count") == "every-fragment";
    let face = StencilFaceState {
        compare: CompareFunction::Always,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: increment,
    };
    Recipe {
        name: "COUNT",
        depth_write: !every,
        depth_compare: match every {
            true => CompareFunction::Always,
            false => CompareFunction::Less,
        },
        stencil: wgpu::StencilState {
            front: face,
            back: face,
            read_mask: 0xff,
            write_mask: 0xff,
        },
        color_writes: wgpu::ColorWrites::empty(),
        ..states::OPAQUE
    }
}

/// PAINT_LEVEL: a triangle over the screen where the stencil equals the reference k.
pub const PAINT_LEVEL: Recipe = Recipe {
    name: "PAINT_LEVEL",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    stencil: wgpu::StencilState {
        front: keep_if(CompareFunction::Equal),
        back: keep_if(CompareFunction::Equal),
        read_mask: 0xff,
        write_mask: 0,
    },
    cull_mode: None,
    ..states::OPAQUE
};

/// PAINT_MORE: the last level, where 8 ≤ the value (`LessEqual`: the reference, 8, on the left).
pub const PAINT_MORE: Recipe = Recipe {
    name: "PAINT_MORE",
    stencil: wgpu::StencilState {
        front: keep_if(CompareFunction::LessEqual),
        back: keep_if(CompareFunction::LessEqual),
        ..PAINT_LEVEL.stencil
    },
    ..PAINT_LEVEL
};

/// ADD: the additive way: every fragment's colour added to what is there (One + One), whatever its
/// depth.
pub const ADD: Recipe = Recipe {
    name: "ADD",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    blend: Some(wgpu::BlendState {
        color: wgpu::BlendComponent {
            src_factor: wgpu::BlendFactor::One,
            dst_factor: wgpu::BlendFactor::One,
            operation: wgpu::BlendOperation::Add,
        },
        alpha: wgpu::BlendComponent::OVER,
    }),
    ..states::OPAQUE
};

const fn keep_if(compare: CompareFunction) -> StencilFaceState {
    StencilFaceState {
        compare,
        fail_op: StencilOperation::Keep,
        depth_fail_op: StencilOperation::Keep,
        pass_op: StencilOperation::Keep,
    }
}
// ANCHOR_END: recipes

/// A pipeline that draws the room's objects with `recipe` and a fragment shader that does nothing:
/// COUNT writes no colour, so the lighting is left out, and every fragment counts (the wire
/// fence's holes too: see `fs_count`).
pub fn counting(device: &wgpu::Device, scene: &Scene, recipe: &Recipe) -> wgpu::RenderPipeline {
    let shader = scene.shader_with(device, "levels.wgsl", SHADER);
    scene.pipeline_in(device, recipe, (&shader, "vs_main", "fs_count"))
}

pub struct DepthComplexity {
    /// COUNT for the solid objects (culled) and for the see-through ones (both sides).
    count: [wgpu::RenderPipeline; 2],
    add: [wgpu::RenderPipeline; 2],
    paint_level: wgpu::RenderPipeline,
    paint_more: wgpu::RenderPipeline,
    blend: bool,
    stack: u32,
}

/// The room's solid objects, in the order they are drawn, with their back faces culled.
pub fn solid(scene: &Scene) -> [&Drawable; 5] {
    [
        &scene.floor,
        &scene.wall,
        &scene.mirror,
        &scene.crate_box,
        &scene.skull,
    ]
}

/// The room's see-through objects, drawn from both sides.
pub fn see_through(scene: &Scene) -> [&Drawable; 2] {
    [&scene.fence_box, &scene.water]
}

impl Lesson for DepthComplexity {
    const NAME: &'static str = "depth-complexity";
    const TITLE: &'static str = "Lesson 13: depth complexity";
    const KNOBS: &'static [Knob] = KNOBS;

    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> anyhow::Result<Self> {
        let device = &gpu.device;
        let shader = scene.shader_with(device, "levels.wgsl", SHADER);
        let both_sides = |recipe: &Recipe| Recipe {
            cull_mode: None,
            ..recipe.clone()
        };
        let count = count(knobs);
        let add =
            |recipe: &Recipe| scene.pipeline_in(device, recipe, (&shader, "vs_main", "fs_eighth"));
        let paint = |recipe: &Recipe| {
            let stages = Stages {
                layout: device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                    label: Some("paint level pipeline layout"),
                    bind_group_layouts: &[],
                    immediate_size: 0,
                }),
                module: shader.clone(),
                vertex: "vs_level",
                fragment: "fs_level",
                buffers: &[],
                color_format: scene.color_format,
            };
            scene.pipelines.bake(device, recipe, &stages)
        };
        Ok(Self {
            count: [
                counting(device, scene, &count),
                counting(device, scene, &both_sides(&count)),
            ],
            add: [add(&ADD), add(&both_sides(&ADD))],
            paint_level: paint(&PAINT_LEVEL),
            paint_more: paint(&PAINT_MORE),
            blend: knobs.get("way") == "blend",
            stack: knobs.get("stack").parse()?,
        })
    }

    // ANCHOR: render
    fn render(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        if self.blend {
            // The additive way: black, then every fragment adds an eighth of white.
            frame.step("paint the screen black", |pass| self.paint(pass, 0..1));
            frame.step("add every fragment", |pass| {
                self.draw_room(pass, scene, &self.add)
            });
            return;
        }
        // Every fragment increments the stencil where it lands.
        frame.step("count the fragments", |pass| {
            self.draw_room(pass, scene, &self.count)
        });
        // A triangle over the screen for each level, drawn where the stencil holds it.
        frame.step("paint the levels", |pass| self.paint(pass, 0..LEVELS));
    }
    // ANCHOR_END: render
}

impl DepthComplexity {
    /// The room, `stack` times: solid objects with the first pipeline, see-through with the second.
    fn draw_room(
        &self,
        pass: &mut Pass<'_, '_>,
        scene: &Scene,
        pipelines: &[wgpu::RenderPipeline; 2],
    ) {
        for _ in 0..self.stack {
            pass.set_pipeline(&pipelines[0]);
            for object in solid(scene) {
                object.draw(pass);
            }
            pass.set_pipeline(&pipelines[1]);
            for object in see_through(scene) {
                object.draw(pass);
            }
        }
    }

    // ANCHOR: paint
    /// Level k painted where the stencil holds k (the last, 8, where it holds 8 or more): the
    /// draw's instance index is the level, and picks its colour.
    pub fn paint(&self, pass: &mut Pass<'_, '_>, levels: std::ops::Range<u32>) {
        for level in levels {
            let last = level == LEVELS - 1;
            pass.set_pipeline(if last {
                &self.paint_more
            } else {
                &self.paint_level
            });
            pass.set_stencil_reference(level);
            pass.object("a triangle over the screen");
            pass.draw(0..3, level..level + 1);
        }
    }
    // ANCHOR_END: paint
}
