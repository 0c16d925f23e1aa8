//! The lesson trait: what every chapter implements, in the spirit of wgpu's `Example`.
//!
//! A lesson is built from the GPU, the room and its knobs, and renders one frame into a colour view
//! the caller gives plus the depth-stencil buffer the framework owns. It never knows whether a window
//! exists: the window runner and the headless runner call the same `render`.

use anyhow::Result;

use crate::camera::Camera;
use crate::gpu::{DepthStencil, Gpu};
use crate::knobs::{Knob, Knobs};
use crate::scene::{self, Scene};
use crate::views::DepthViewPipelines;

// ANCHOR: lesson
pub trait Lesson: Sized {
    /// The package name, e.g. `depth-test`.
    const NAME: &'static str;
    /// The chapter's title, e.g. `Lesson 1: the depth test`.
    const TITLE: &'static str;
    /// Every knob of the lesson, the right picture's values as defaults.
    const KNOBS: &'static [Knob];

    /// Builds the lesson's pipelines for these knob values. Called again when a knob changes.
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> Result<Self>;

    /// Records one frame.
    fn render(&self, frame: &mut Frame<'_>);
}
// ANCHOR_END: lesson

/// Where to begin a pass: from cleared buffers, or on top of what the frame has drawn so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// Colour to the sky, depth to 1.0 (the far plane), stencil to 0.
    Cleared,
    /// Keep what is there.
    Kept,
}

/// One frame being recorded: the targets, the room and the encoder.
pub struct Frame<'a> {
    pub gpu: &'a Gpu,
    pub scene: &'a Scene,
    /// Where the camera is this frame (for sorting transparent objects back to front).
    pub camera: Camera,
    pub encoder: wgpu::CommandEncoder,
    pub color: &'a wgpu::TextureView,
    pub depth_stencil: &'a DepthStencil,
    pub(crate) depth_view: Option<(&'a DepthViewPipelines, &'a wgpu::BindGroup)>,
    /// Set when the lesson asked for something this backend cannot do.
    pub(crate) unsupported: Option<&'static str>,
}

impl Frame<'_> {
    /// Begins a render pass on the colour and depth-stencil targets, with the frame's camera and
    /// lights bound.
    pub fn pass(&mut self, label: &str, start: Start) -> wgpu::RenderPass<'_> {
        let [r, g, b] = scene::CLEAR_SRGB.map(|c| crate::texture::srgb_to_linear(c) as f64);
        let (color, depth, stencil) = match start {
            Start::Cleared => (
                wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a: 1.0 }),
                wgpu::LoadOp::Clear(1.0),
                wgpu::LoadOp::Clear(0),
            ),
            Start::Kept => (wgpu::LoadOp::Load, wgpu::LoadOp::Load, wgpu::LoadOp::Load),
        };
        let mut pass = self.encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some(label),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: self.color,
                depth_slice: None,
                resolve_target: None,
                ops: wgpu::Operations {
                    load: color,
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.depth_stencil.view,
                depth_ops: Some(wgpu::Operations {
                    load: depth,
                    store: wgpu::StoreOp::Store,
                }),
                stencil_ops: Some(wgpu::Operations {
                    load: stencil,
                    store: wgpu::StoreOp::Store,
                }),
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        self.scene.bind_frame(&mut pass);
        pass
    }

    /// Replaces the colours with the stencil buffer in false colour (see `views::stencil_colour`).
    pub fn show_stencil(&mut self) {
        let (device, stencil_view) = (&self.gpu.device, &self.scene.stencil_view);
        stencil_view.show(device, &mut self.encoder, self.color, self.depth_stencil);
    }

    /// Replaces the colours with the depth buffer: raw values on the left, linearised on the right.
    pub fn show_depth(&mut self) {
        match self.depth_view {
            Some((pipelines, bind_group)) => {
                pipelines.show(&mut self.encoder, self.color, bind_group)
            }
            None => self.unsupported = Some(DepthViewPipelines::UNSUPPORTED),
        }
    }
}
