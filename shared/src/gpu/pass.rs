//! The render pass a lesson's step draws with: wgpu's own, and, when a pixel's story is being read,
//! a [`Probe`] that watches every draw at that one pixel.
//!
//! A lesson sets pipelines, stencil references and blend constants and draws, as with
//! `wgpu::RenderPass`; the framework's drawing functions (a mesh, a shape, the room) take this pass
//! too, so that every draw goes through [`Pass::draw`] or [`Pass::draw_indexed`]. Without a probe it
//! adds nothing but a branch.

use std::ops::Range;

use crate::gpu::pipelines::{Pipelines, Twin};
use crate::gpu::states::Recipe;

/// A step's render pass.
pub struct Pass<'p, 'e> {
    raw: &'p mut wgpu::RenderPass<'e>,
    probe: Option<(&'p mut Probe, &'p Pipelines, &'p wgpu::Device)>,
}

impl<'p, 'e> Pass<'p, 'e> {
    /// A pass as wgpu gives it, watched by `probe` if there is one.
    pub(crate) fn new(
        raw: &'p mut wgpu::RenderPass<'e>,
        probe: Option<(&'p mut Probe, &'p Pipelines, &'p wgpu::Device)>,
    ) -> Self {
        let mut pass = Self { raw, probe };
        if let Some((probe, ..)) = &mut pass.probe {
            // A new pass starts with the whole target as scissor, reference 0, constant 0.
            probe.state = State::default();
            let (x, y) = probe.pixel;
            pass.raw.set_scissor_rect(x, y, 1, 1);
        }
        pass
    }

    pub fn set_pipeline(&mut self, pipeline: &wgpu::RenderPipeline) {
        if let Some((probe, ..)) = &mut self.probe {
            probe.state.pipeline = Some(pipeline.clone());
        }
        self.raw.set_pipeline(pipeline);
    }

    pub fn set_stencil_reference(&mut self, reference: u32) {
        if let Some((probe, ..)) = &mut self.probe {
            probe.state.reference = reference;
        }
        self.raw.set_stencil_reference(reference);
    }

    pub fn set_blend_constant(&mut self, color: wgpu::Color) {
        if let Some((probe, ..)) = &mut self.probe {
            probe.state.blend_constant = color;
        }
        self.raw.set_blend_constant(color);
    }

    pub fn set_bind_group(&mut self, index: u32, bind_group: &wgpu::BindGroup, offsets: &[u32]) {
        self.raw.set_bind_group(index, bind_group, offsets);
    }

    pub fn set_vertex_buffer(&mut self, slot: u32, slice: wgpu::BufferSlice<'_>) {
        self.raw.set_vertex_buffer(slot, slice);
    }

    pub fn set_index_buffer(&mut self, slice: wgpu::BufferSlice<'_>, format: wgpu::IndexFormat) {
        self.raw.set_index_buffer(slice, format);
    }

    pub fn set_viewport(&mut self, x: f32, y: f32, w: f32, h: f32, min_depth: f32, max_depth: f32) {
        self.raw.set_viewport(x, y, w, h, min_depth, max_depth);
    }

    /// The scissor rectangle; while a pixel is watched, the pass keeps to that pixel, and draws
    /// whose scissor leaves it out are not drawn (they cannot reach it).
    pub fn set_scissor_rect(&mut self, x: u32, y: u32, width: u32, height: u32) {
        match &mut self.probe {
            Some((probe, ..)) => {
                let (px, py) = probe.pixel;
                probe.state.outside_scissor =
                    !(px >= x && px - x < width && py >= y && py - y < height);
            }
            None => self.raw.set_scissor_rect(x, y, width, height),
        }
    }

    /// Names the object the next draw draws (a pixel's story says which object reached it).
    pub fn object(&mut self, name: &'static str) {
        if let Some((probe, ..)) = &mut self.probe {
            probe.state.object = Some(name);
        }
    }

    pub fn draw(&mut self, vertices: Range<u32>, instances: Range<u32>) {
        self.probed(|raw| raw.draw(vertices.clone(), instances.clone()));
    }

    pub fn draw_indexed(&mut self, indices: Range<u32>, base_vertex: i32, instances: Range<u32>) {
        self.probed(|raw| raw.draw_indexed(indices.clone(), base_vertex, instances.clone()));
    }

    /// Draws as the probe says: every draw, the draws up to one, or one draw as its twin.
    fn probed(&mut self, draw: impl Fn(&mut wgpu::RenderPass<'e>)) {
        let Some((probe, pipelines, device)) = &mut self.probe else {
            return draw(self.raw);
        };
        let index = probe.draws.len();
        let state = &probe.state;
        let recipe = state.pipeline.as_ref().and_then(|p| pipelines.recipe(p));
        probe.draws.push(Draw {
            step: probe.step,
            recipe,
            object: state.object,
            reference: state.reference,
            blend_constant: state.blend_constant,
        });
        probe.state.object = None;
        let outside = probe.state.outside_scissor;
        let raw = &mut *self.raw;
        let queried = |raw: &mut wgpu::RenderPass<'e>, query: u32, drawn: bool| {
            raw.begin_occlusion_query(query);
            if drawn {
                draw(raw);
            }
            raw.end_occlusion_query();
        };
        let (probing, twin_queries) = (probe.probing, probe.twin_queries);
        let pipeline = probe.state.pipeline.clone();
        let twin = |kind: Twin| pipelines.twin(device, pipeline.as_ref()?, kind);
        match probing {
            Probing::Watch => queried(raw, index as u32, !outside),
            Probing::Cover => {
                let query = twin_queries + index as u32;
                match twin(Twin::Silent) {
                    Some(silent) => {
                        raw.set_pipeline(&silent);
                        queried(raw, query, !outside);
                    }
                    None => queried(raw, query, false),
                }
            }
            Probing::Until(last) => {
                if index <= last && !outside {
                    draw(raw);
                }
            }
            Probing::Twin(k, _) if index < k && !outside => draw(raw),
            Probing::Twin(k, fragment) if index == k && !outside => {
                if let (Some(zero), Some(select)) = (twin(Twin::Zero), twin(Twin::Select)) {
                    raw.set_pipeline(&zero);
                    raw.set_stencil_reference(0);
                    draw(raw);
                    raw.set_pipeline(&select);
                    raw.set_stencil_reference(fragment);
                    draw(raw);
                }
            }
            Probing::Twin(..) => {}
        }
        // The lesson's own pipeline and reference again, for its next draw.
        if let Some(pipeline) = &probe.state.pipeline
            && probing != Probing::Watch
        {
            raw.set_pipeline(pipeline);
            raw.set_stencil_reference(probe.state.reference);
        }
    }
}

/// What a probed frame does with each draw.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Probing {
    /// Every draw as the lesson records it, each in an occlusion query: did it pass both tests?
    Watch,
    /// Every draw as its silent twin (see [`Twin::Silent`]) in an occlusion query: does it reach
    /// the pixel at all? Nothing is written.
    Cover,
    /// The draws up to and with this one; none after it.
    Until(usize),
    /// The draws before the first; the first as its twins [`Twin::Zero`] then [`Twin::Select`]
    /// for the second, its fragment at the pixel counted from 0, which leave in the pixel that
    /// fragment's colour and depth and, in the stencil, how many fragments the draw has there;
    /// none after it.
    Twin(usize, u32),
}

/// Watches one pixel through a frame: every draw of the frame's steps is counted and described,
/// and drawn as [`Probing`] says, with the pass kept to that pixel (a 1×1 scissor).
pub struct Probe {
    pub pixel: (u32, u32),
    pub probing: Probing,
    /// Every draw met so far in this frame, in order.
    pub draws: Vec<Draw>,
    /// The occlusion queries: one per draw for [`Probing::Watch`] (at the draw's index), and one
    /// per draw for [`Probing::Cover`], at `twin_queries` + the draw's index.
    pub queries: wgpu::QuerySet,
    pub twin_queries: u32,
    /// The step being recorded (its index in the frame).
    pub(crate) step: usize,
    state: State,
}

impl Probe {
    /// A probe of `pixel` with room for the queries of `draws` draws (counted by a first frame
    /// with any number: a frame probed with too few fails validation, and says so).
    pub fn new(device: &wgpu::Device, pixel: (u32, u32), draws: usize) -> Self {
        let count = (2 * draws).clamp(1, wgpu::QUERY_SET_MAX_QUERIES as usize) as u32;
        Self {
            pixel,
            probing: Probing::Watch,
            draws: Vec::new(),
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("pixel probe's occlusion queries"),
                ty: wgpu::QueryType::Occlusion,
                count,
            }),
            twin_queries: draws as u32,
            step: 0,
            state: State::default(),
        }
    }

    /// Ready for another frame, probed as `probing` says.
    pub fn start(&mut self, probing: Probing) {
        self.probing = probing;
        self.draws.clear();
        self.state = State::default();
    }
}

/// What the pass has set that a draw's story needs.
#[derive(Default)]
struct State {
    pipeline: Option<wgpu::RenderPipeline>,
    reference: u32,
    blend_constant: wgpu::Color,
    object: Option<&'static str>,
    outside_scissor: bool,
}

/// One draw as the probe met it.
#[derive(Debug, Clone)]
pub struct Draw {
    /// The step it belongs to (its index in the frame).
    pub step: usize,
    /// The recipe its pipeline was baked from (`None` for a pipeline baked elsewhere).
    pub recipe: Option<Recipe>,
    /// The object it draws, where the drawing function names it.
    pub object: Option<&'static str>,
    pub reference: u32,
    pub blend_constant: wgpu::Color,
}
