//! What every lesson after lesson 3 does before its own steps: the room as usual, then the mirror's
//! visible pixels marked with 1 in the stencil buffer — lesson 3's frame, kept here once.

use crate::lesson::Frame;
use crate::{Gpu, Scene, gpu::states};

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
