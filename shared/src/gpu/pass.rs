//! The render pass a lesson's step draws with: wgpu's own, and, when a pixel's story is being read,
//! a [`Probe`] that watches every draw at that one pixel.
//!
//! A lesson sets pipelines, stencil references and blend constants and draws, as with
//! `wgpu::RenderPass`; the framework's drawing functions (a mesh, a shape, the room) take this pass
//! too, so that every draw goes through [`Pass::draw`] or [`Pass::draw_indexed`]. Without a probe it
//! adds nothing but a branch.

use std::ops::Range;

use crate::gpu::pipelines::{Fate, Pipelines, Twin};
use crate::gpu::states::Recipe;
use crate::math::screen::ScreenRect;

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
            if let Some((x, y)) = probe.pixel {
                pass.raw.set_scissor_rect(x, y, 1, 1);
            }
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
        let watched = self.probe.as_mut().and_then(|(probe, ..)| {
            let pixel = probe.pixel?;
            Some((probe, pixel))
        });
        match watched {
            Some((probe, pixel)) => {
                let rect = ScreenRect {
                    x,
                    y,
                    width,
                    height,
                };
                probe.state.outside_scissor = !rect.contains(pixel);
            }
            None => self.raw.set_scissor_rect(x, y, width, height),
        }
    }

    /// The scissor rectangle `rect` (see [`Pass::set_scissor_rect`]).
    pub fn set_scissor(&mut self, rect: ScreenRect) {
        self.set_scissor_rect(rect.x, rect.y, rect.width, rect.height);
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
            outside_scissor: state.outside_scissor,
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
            Probing::Twin(k, _) | Probing::Facing(k, _) if index < k && !outside => draw(raw),
            Probing::Twin(k, fragment) | Probing::Facing(k, fragment) if index == k && !outside => {
                let select = twin(probing.selecting());
                if let (Some(zero), Some(select)) = (twin(Twin::Zero), select) {
                    raw.set_pipeline(&zero);
                    raw.set_stencil_reference(0);
                    draw(raw);
                    raw.set_pipeline(&select);
                    raw.set_stencil_reference(fragment);
                    draw(raw);
                }
            }
            Probing::Twin(..) | Probing::Facing(..) => {}
            Probing::Count | Probing::Fates { .. } => {
                let in_step = probe.draws.iter().filter(|d| d.step == probe.step).count() - 1;
                match whole_picture(probing, (probe.step, in_step)) {
                    None => draw(raw),
                    Some(twins) => {
                        for twin in twins.into_iter().filter_map(twin) {
                            raw.set_pipeline(&twin);
                            draw(raw);
                        }
                    }
                }
            }
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

/// How a probe of the whole picture draws the draw of index `in_step` in step `step`: as the
/// lesson does (`None`), or as these twins — its counting twin ([`Probing::Count`]); in the step
/// [`Probing::Fates`] maps, its fates' twins, or its quiet twin before the draw shown, or nothing
/// after it.
fn whole_picture(probing: Probing, (step, in_step): (usize, usize)) -> Option<Vec<Twin>> {
    use std::cmp::Ordering::*;
    let Probing::Fates {
        step: mapped,
        draw: shown,
    } = probing
    else {
        return Some(vec![Twin::Count]);
    };
    match (step.cmp(&mapped), shown) {
        (Less, _) => None,
        (Equal, Some(shown)) if in_step < shown => Some(vec![Twin::Quiet]),
        (Equal, Some(shown)) if in_step > shown => Some(Vec::new()),
        (Equal, _) => Some(Fate::ALL.map(Twin::Fate).to_vec()),
        (Greater, _) => Some(Vec::new()),
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
    /// [`Probing::Twin`] with [`Twin::Facing`] for [`Twin::Select`]: the pixel is left white if
    /// that fragment lies on a front face, black if on a back face.
    Facing(usize, u32),
    /// The whole picture: every draw as its counting twin ([`Twin::Count`]), the stencil left
    /// holding how many fragments reached each pixel (`--show complexity`).
    Count,
    /// The whole picture: the steps before `step` (its index) as the lesson draws them; in it,
    /// `draw` (its index in the step; every draw of the step for `None`) as its fate twins
    /// ([`Twin::Fate`]) into the test map, the step's draws before it as their quiet twins, none
    /// after it (`--show tests`).
    Fates { step: usize, draw: Option<usize> },
}

impl Probing {
    /// The twin that selects one fragment: [`Twin::Facing`] for [`Probing::Facing`].
    fn selecting(self) -> Twin {
        match self {
            Probing::Facing(..) => Twin::Facing,
            _ => Twin::Select,
        }
    }

    /// Whether it watches the whole picture rather than one pixel.
    pub fn whole(self) -> bool {
        matches!(self, Probing::Count | Probing::Fates { .. })
    }
}

/// Watches one pixel through a frame, or the whole picture: every draw of the frame's steps is
/// counted and described, and drawn as [`Probing`] says; watching a pixel, with the pass kept to
/// it (a 1×1 scissor).
pub struct Probe {
    /// The pixel watched; `None` for the whole picture ([`Probing::Count`], [`Probing::Fates`]).
    pub pixel: Option<(u32, u32)>,
    /// The test map the step of [`Probing::Fates`] draws into, in place of the colour target.
    pub map: Option<wgpu::TextureView>,
    /// Whether that step was drawn into it (not where the step drew into a lesson's own target).
    pub map_drawn: bool,
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
            pixel: Some(pixel),
            map: None,
            map_drawn: false,
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

    /// A probe of the whole picture, as `probing` says ([`Probing::Count`] or [`Probing::Fates`],
    /// whose test map is `map`).
    pub fn whole(device: &wgpu::Device, probing: Probing, map: Option<wgpu::TextureView>) -> Self {
        debug_assert!(probing.whole());
        let mut probe = Self::new(device, (0, 0), 0);
        probe.pixel = None;
        probe.probing = probing;
        probe.map = map;
        probe
    }

    /// The test map, where the step with this index is the one [`Probing::Fates`] maps.
    pub(crate) fn map_for(&self, step: usize) -> Option<&wgpu::TextureView> {
        match self.probing {
            Probing::Fates { step: mapped, .. } if mapped == step => self.map.as_ref(),
            _ => None,
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

/// A draw's name in a list of its step's: `2. DRAW_REFLECTION: skull` for the draw of index 1.
pub fn draw_name(index: usize, draw: &Draw) -> String {
    let recipe = draw.recipe.as_ref().map_or("a pipeline", |r| r.name);
    match draw.object {
        Some(object) => format!("{}. {recipe}: {object}", index + 1),
        None => format!("{}. {recipe}", index + 1),
    }
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
    /// Whether the step's scissor rectangle left the watched pixel out (the draw was not drawn).
    pub outside_scissor: bool,
}
