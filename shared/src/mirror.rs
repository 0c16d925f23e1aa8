//! What every lesson after lesson 3 does before its own steps: the room as usual, then the mirror's
//! visible pixels marked with 1 in the stencil buffer — lesson 3's frame, kept here once.

use crate::lesson::{Frame, Start};
use crate::{Gpu, Scene, states};

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

    // ANCHOR: begin
    /// Begins the frame's pass: clears colour, depth (to 1.0) and stencil (to 0), draws the room but
    /// the mirror with OPAQUE, and marks the mirror's visible pixels with 1 using MARK_MIRROR. The
    /// stencil reference stays 1 for the lesson's own steps.
    pub fn begin<'f>(&self, frame: &'f mut Frame<'_>, label: &str) -> wgpu::RenderPass<'f> {
        let scene = frame.scene;
        let mut pass = frame.pass(label, Start::Cleared);
        pass.set_pipeline(&self.draw_room);
        scene.draw_room(&mut pass);
        pass.set_pipeline(&self.mark_mirror);
        pass.set_stencil_reference(1);
        scene.mirror.draw(&mut pass);
        pass
    }
    // ANCHOR_END: begin
}
