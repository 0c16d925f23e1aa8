//! What mirror lessons share: lesson 3's frame (the room as usual, then the mirror's visible pixels
//! marked with 1 in the stencil buffer), which lessons 4-7 begin with; the step that clears the depth
//! behind a marked mirror; and lesson 8's frame for a mirror in any plane, for the lessons after it.

use crate::gpu::pass::Pass;
use crate::gpu::pipelines::Stages;
use crate::gpu::states::{self, Clip};
use crate::lesson::Frame;
use crate::math::reflect::Plane;
use crate::room::mirror_world::MirrorWorld;
use crate::room::scene::Drawable;
use crate::{Gpu, Recipe, Scene};

pub struct MarkedRoom {
    draw_room: wgpu::RenderPipeline,
    mark_mirror: wgpu::RenderPipeline,
}

impl MarkedRoom {
    pub fn new(gpu: &Gpu, scene: &Scene) -> Self {
        Self {
            draw_room: scene.pipeline(&gpu.device, &states::OPAQUE),
            mark_mirror: scene.pipeline(&gpu.device, &states::MARK_MIRROR),
        }
    }

    // ANCHOR: steps
    /// The frame's first three steps: clear colour, depth (to 1.0) and stencil (to 0); draw the
    /// room but the mirror with OPAQUE; mark the mirror's visible pixels with 1 using MARK_MIRROR.
    pub fn steps(&self, frame: &mut Frame<'_>) {
        let scene = frame.scene;
        frame.clear();
        frame.step("draw the room", |pass| {
            pass.set_pipeline(&self.draw_room);
            scene.draw_room(pass);
        });
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark_mirror);
            pass.set_stencil_reference(1);
            scene.mirror.draw(pass);
        });
    }
    // ANCHOR_END: steps
}

/// RESET_DEPTH's pipeline: a far-plane triangle over the screen, drawn where the stencil holds the
/// reference, so that the marked pixels' depth is the far plane again (and, made
/// [`ResetDepth::to_the_sky`], their colour the sky's).
pub struct ResetDepth {
    pipeline: wgpu::RenderPipeline,
}

impl ResetDepth {
    pub fn new(gpu: &Gpu, scene: &Scene) -> Self {
        Self::with(gpu, scene, &states::RESET_DEPTH, "fs_no_colour")
    }

    /// RESET_TO_THE_SKY: the depth reset and the colour cleared to the sky, so that what lies
    /// beyond an opening is seen against its own sky, not against what was drawn there before
    /// (lesson 16's doorway, whose own surface the room drew).
    pub fn to_the_sky(gpu: &Gpu, scene: &Scene) -> Self {
        Self::with(gpu, scene, &states::RESET_TO_THE_SKY, "fs_sky")
    }

    fn with(gpu: &Gpu, scene: &Scene, recipe: &Recipe, fragment: &'static str) -> Self {
        let device = &gpu.device;
        let [r, g, b] = crate::room::scene::CLEAR_SRGB.map(crate::gpu::srgb_to_linear);
        let source = format!(
            "{}\nconst SKY = vec4<f32>({r:?}, {g:?}, {b:?}, 1.0);\n",
            include_str!("../shaders/reset_depth.wgsl")
        );
        let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("reset_depth.wgsl"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("reset depth pipeline layout"),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        let stages = Stages {
            layout,
            module: shader,
            vertex: "vs_far_plane",
            fragment,
            buffers: &[],
            color_format: scene.color_format,
        };
        let pipeline = scene.pipelines.bake(device, recipe, &stages);
        Self { pipeline }
    }

    /// Resets the depth wherever the stencil holds `reference`.
    pub fn draw(&self, pass: &mut Pass<'_, '_>, reference: u32) {
        pass.set_pipeline(&self.pipeline);
        pass.set_stencil_reference(reference);
        pass.object("a triangle over the screen");
        pass.draw(0..3, 0..1);
    }
}

/// Lesson 8's frame for a mirror in any plane, kept here for the lessons after it: mark the mirror's
/// surface, reset the depth there if something stands behind it, draw its mirror world where the
/// mark is (clipped at the plane), and blend the surface over it.
pub struct StencilMirror {
    mark: wgpu::RenderPipeline,
    reset_depth: Option<ResetDepth>,
    reflect: wgpu::RenderPipeline,
    surface: wgpu::RenderPipeline,
    world: MirrorWorld,
}

impl StencilMirror {
    /// The mirror in `plane` showing `objects`, clipped as `clip` says; with `something_behind`, the
    /// mark's depth is reset before the reflection.
    pub fn new(
        gpu: &Gpu,
        scene: &Scene,
        (plane, objects): (Plane, &[&Drawable]),
        clip: Clip,
        something_behind: bool,
    ) -> Self {
        let pipeline = |recipe: &Recipe| scene.pipeline(&gpu.device, recipe);
        Self {
            mark: pipeline(&states::MARK_MIRROR),
            reset_depth: something_behind.then(|| ResetDepth::new(gpu, scene)),
            reflect: pipeline(&Recipe {
                clip,
                ..states::FRONT_CLOCKWISE
            }),
            surface: pipeline(&states::BLEND_OVER_MARK),
            world: MirrorWorld::new(gpu, scene, plane, objects),
        }
    }

    /// The mirror's steps, for its `surface` and the `objects` it was made with.
    pub fn steps(&self, frame: &mut Frame<'_>, surface: &Drawable, objects: &[&Drawable]) {
        self.world.update(frame, false);
        frame.step("mark the mirror", |pass| {
            pass.set_pipeline(&self.mark);
            pass.set_stencil_reference(1);
            surface.draw(pass);
        });
        if let Some(reset_depth) = &self.reset_depth {
            frame.step("reset the depth in the mark", |pass| {
                reset_depth.draw(pass, 1)
            });
        }
        frame.step("draw the reflection", |pass| {
            pass.set_pipeline(&self.reflect);
            pass.set_stencil_reference(1);
            self.world.bind(pass);
            for object in objects {
                self.world.draw(pass, object);
            }
        });
        frame.step("draw the mirror's surface", |pass| {
            pass.set_pipeline(&self.surface);
            pass.set_stencil_reference(1);
            surface.draw(pass);
        });
    }
}

impl MirrorWorld {
    /// Writes this frame's camera (oblique or not), the reflected lights and the clip plane.
    pub fn update(&self, frame: &Frame<'_>, oblique: bool) {
        self.write(&frame.gpu.queue, &frame.view, oblique);
    }
}
