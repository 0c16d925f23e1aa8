//! The lesson trait: what every chapter implements, in the spirit of wgpu's `Example`.
//!
//! A lesson is built from the GPU, the room and its knobs, and renders one frame into a colour view
//! the caller gives plus the depth-stencil buffer the framework owns. It never knows whether a window
//! exists: the window runner and the headless runner call the same `render`.
//!
//! A frame is a list of named **steps** ([`Frame::step`]), each one render pass. The names are data:
//! `--list-steps`, `--step N`, `--film`, the window's `[` and `]`, the book's step strips and the tests
//! all read them from the lesson's `render`, and nowhere else. Where nobody looks between the steps
//! (a screenshot, the window without its panel), the frame records them into one render pass
//! instead, as an engine would ([`Passes::One`]): the same picture, for a fraction of the CPU's
//! time per pass.
//!
//! Beside the trait: the knobs ([`knobs`]), where a frame stops and what it shows ([`steps`]), and the
//! steps every mirror lesson begins with ([`mirror`]).

pub mod knobs;
pub mod mirror;
pub mod steps;
pub mod story;

use anyhow::Result;

use crate::gpu::pass::{Pass, Probe, Probing};
use crate::gpu::timing::StepTimer;
use crate::gpu::{DepthStencil, Gpu, Offscreen};
use crate::lesson::knobs::{Knob, Knobs};
use crate::lesson::steps::Show;
use crate::room::camera::{BOOK_POSE, Camera, View};
use crate::room::scene::{self, Scene};

// ANCHOR: lesson
pub trait Lesson: Sized + 'static {
    /// The package name, e.g. `depth-test`.
    const NAME: &'static str;
    /// The chapter's title, e.g. `Lesson 1: the depth test`.
    const TITLE: &'static str;
    /// Every knob of the lesson, the right picture's values as defaults.
    const KNOBS: &'static [Knob];
    /// The buffer the window and `--screenshot` show unless `--show` says otherwise.
    const SHOWS: Show = Show::Color;
    /// Where the camera starts unless `--camera` says otherwise.
    const CAMERA: Camera = BOOK_POSE;

    /// Builds the lesson's pipelines for these knob values. Called again when a knob changes.
    fn new(gpu: &Gpu, scene: &Scene, knobs: &Knobs) -> Result<Self>;

    /// Why this GPU cannot draw a knob's value, where it cannot (a feature it lacks); `None` where
    /// it can. The web page offers such a value disabled, with the reason.
    fn unavailable(_scene: &Scene, _knob: &str, _value: &str) -> Option<&'static str> {
        None
    }

    /// Records one frame as named steps: `frame.clear()`, then `frame.step("...", |pass| ...)`.
    fn render(&self, frame: &mut Frame<'_>);
}
// ANCHOR_END: lesson

/// The name of the step [`Frame::clear`] records.
pub const CLEAR: &str = "clear";

/// One frame being recorded: the targets, the room, and the steps met so far.
pub struct Frame<'a> {
    pub gpu: &'a Gpu,
    pub scene: &'a Scene,
    /// Where the camera is this frame (for sorting transparent objects back to front).
    pub camera: Camera,
    /// What the camera sees through: eye, view and projection (for views of a lesson's own).
    pub view: View,
    /// The frame's one pass while it is open (declared before the encoder: it ends first).
    open: Option<wgpu::RenderPass<'static>>,
    pub(crate) encoder: wgpu::CommandEncoder,
    color: &'a wgpu::TextureView,
    depth_stencil: &'a DepthStencil,
    /// The name of every step the lesson's `render` met, in order, drawn or not.
    pub(crate) steps: Vec<&'static str>,
    /// Steps after the first `stop` are named but not recorded.
    stop: usize,
    /// Called after each recorded step, to look at the buffers mid-frame (`--film`, a step drawn
    /// into a lesson's own target).
    after_step: Option<AfterStep<'a>>,
    /// Where each step's pass writes its timestamps, when the frame is timed.
    pub(crate) timer: Option<&'a StepTimer>,
    /// How the steps on the frame's own targets are recorded (see [`Passes`]).
    passes: Passes,
    /// Watches one pixel through the frame's own targets (a pixel's story), if asked to.
    probe: Option<&'a mut Probe>,
}

/// What the frame calls after each step it records: with the encoder, the step's index (from 0) and
/// the lesson's own target the step drew into, if it did not draw into the frame's.
pub type AfterStep<'a> = &'a mut dyn FnMut(&mut wgpu::CommandEncoder, usize, Option<&Offscreen>);

impl<'a> Frame<'a> {
    /// A frame that records the first `stop` steps (all of them with `usize::MAX`), and calls
    /// `after_step` after each.
    pub(crate) fn new(
        gpu: &'a Gpu,
        scene: &'a Scene,
        (camera, view): (Camera, View),
        (color, depth_stencil): (&'a wgpu::TextureView, &'a DepthStencil),
        stop: usize,
        after_step: Option<AfterStep<'a>>,
    ) -> Self {
        let encoder = gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("frame"),
            });
        Self {
            gpu,
            scene,
            camera,
            view,
            encoder,
            color,
            depth_stencil,
            steps: Vec::new(),
            stop,
            after_step,
            timer: None,
            passes: Passes::PerStep,
            open: None,
            probe: None,
        }
    }

    /// Records the frame's steps as `passes` says (a pass each unless told otherwise).
    pub(crate) fn with_passes(mut self, passes: Passes) -> Self {
        self.passes = passes;
        self
    }

    /// Watches one pixel of the frame's own targets with `probe`: a pass a step, each kept to that
    /// pixel, every draw counted and drawn as the probe says.
    pub fn with_probe(mut self, probe: &'a mut Probe) -> Self {
        self.probe = Some(probe);
        self
    }

    /// The frame recorded: its encoder (the open pass ended) and the names of its steps.
    pub(crate) fn finish(mut self) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        self.open = None;
        (self.encoder, self.steps)
    }

    /// The size of the frame's targets, in pixels.
    pub fn size(&self) -> (u32, u32) {
        self.depth_stencil.size()
    }

    // ANCHOR: steps
    /// The step "clear": colour to the sky, every depth to 1.0 (the far plane), every stencil
    /// value to 0.
    pub fn clear(&mut self) {
        self.record(CLEAR, Start::Cleared, None, |_| {});
    }

    /// One named step: a render pass on the colour and depth-stencil targets, keeping what earlier
    /// steps drew, with the frame's camera and lights bound; `draw` records into it.
    pub fn step(&mut self, name: &'static str, draw: impl FnOnce(&mut Pass<'_, '_>)) {
        self.record(name, Start::Kept, None, draw);
    }

    /// One named step drawn into a target of the lesson's own (a reflection texture), cleared
    /// first, with the frame's camera and lights bound. The window and the film show that target
    /// when the frame stops after this step.
    pub fn step_into(
        &mut self,
        name: &'static str,
        target: &Offscreen,
        draw: impl FnOnce(&mut Pass<'_, '_>),
    ) {
        self.record(name, Start::Cleared, Some(target), draw);
    }
    // ANCHOR_END: steps

    fn record(
        &mut self,
        name: &'static str,
        start: Start,
        target: Option<&Offscreen>,
        draw: impl FnOnce(&mut Pass<'_, '_>),
    ) {
        self.steps.push(name);
        if self.steps.len() > self.stop {
            return;
        }
        // A timed frame needs a pass a step: the timestamps are written where a pass begins and ends.
        let alone = self.timer.is_none() && self.probe.is_none() && target.is_none();
        if self.passes == Passes::One && alone {
            return self.record_in_one_pass(name, start, draw);
        }
        // A pass of its own: the frame's one pass, if open, ends first.
        self.open = None;
        let index = self.steps.len() - 1;
        let (color, depth_stencil) = match target {
            Some(target) => (&target.color_view, &target.depth_stencil),
            None => (self.color, self.depth_stencil),
        };
        let timestamps = self.timer.and_then(|timer| timer.writes(index));
        // A probe of a pixel watches the frame's own targets, not a lesson's; the complexity
        // counts in both.
        let probe = self
            .probe
            .as_deref_mut()
            .filter(|probe| target.is_none() || probe.probing == Probing::Count);
        // The step a test map shows draws its fates into the map, over which it is then painted.
        let map = probe
            .as_ref()
            .and_then(|probe| probe.map_for(index).cloned());
        if map.is_some() && start == Start::Cleared {
            let targets = (Attachment::Color(color), depth_stencil);
            drop(pass(&mut self.encoder, name, start, targets, (None, None)));
        }
        let queries = probe.as_ref().map(|probe| &probe.queries);
        let attachments = match &map {
            Some(map) => (Attachment::Map(map), depth_stencil),
            None => (Attachment::Color(color), depth_stencil),
        };
        let mut raw = pass(
            &mut self.encoder,
            name,
            start,
            attachments,
            (timestamps, queries),
        );
        let probe = probe.map(|probe| {
            probe.step = index;
            (probe, &self.scene.pipelines, &self.gpu.device)
        });
        let mut pass = Pass::new(&mut raw, probe);
        self.scene.bind_frame(&mut pass);
        draw(&mut pass);
        drop(raw);
        if let Some(map) = &map {
            if let Some(probe) = self.probe.as_deref_mut() {
                probe.map_drawn = true;
            }
            let device = &self.gpu.device;
            self.scene
                .test_map
                .paint(device, &mut self.encoder, map, color);
        }
        if let Some(after_step) = &mut self.after_step {
            after_step(&mut self.encoder, index, target);
        }
    }

    /// A step in the frame's one pass, opened by the first step (or again after a step into a
    /// target of the lesson's own).
    fn record_in_one_pass(
        &mut self,
        name: &'static str,
        start: Start,
        draw: impl FnOnce(&mut Pass<'_, '_>),
    ) {
        if start == Start::Cleared {
            self.open = None;
        }
        let targets = (self.color, self.depth_stencil);
        let pass = self.open.get_or_insert_with(|| {
            // The pass holds the encoder until it ends: `finish` and every pass of its own end it.
            let (color, depth_stencil) = targets;
            let targets = (Attachment::Color(color), depth_stencil);
            pass(&mut self.encoder, "one pass", start, targets, (None, None)).forget_lifetime()
        });
        let (width, height) = self.depth_stencil.size();
        pass.push_debug_group(name);
        pass.set_stencil_reference(0);
        pass.set_blend_constant(wgpu::Color::TRANSPARENT);
        pass.set_viewport(0.0, 0.0, width as f32, height as f32, 0.0, 1.0);
        pass.set_scissor_rect(0, 0, width, height);
        let mut step = Pass::new(pass, None);
        self.scene.bind_frame(&mut step);
        draw(&mut step);
        pass.pop_debug_group();
    }
}

/// How a frame records its steps on its own targets.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Passes {
    /// A render pass each: to look between the steps (timestamps per step, the film, the panel).
    PerStep,
    /// All of them in one render pass, each step a debug group in it, where nothing looks between
    /// the steps (a screenshot, the window without its panel), as an engine would record them. A
    /// step into a lesson's own target still has a pass of its own, and a timed frame a pass a
    /// step. Each step starts from the state a new pass starts from (stencil reference 0, blend
    /// constant 0, the whole target as viewport and scissor), so the picture is the same; a test
    /// checks that it is, for every knob value of every lesson.
    #[default]
    One,
}

/// Where a step's pass begins: from cleared buffers, or on top of what the frame has drawn so far.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Start {
    Cleared,
    Kept,
}

/// What a step's pass draws its colours into.
enum Attachment<'t> {
    /// The frame's colour target, or the lesson's own target.
    Color(&'t wgpu::TextureView),
    /// A test map, cleared to white (no fate) whatever the step's start.
    Map(&'t wgpu::TextureView),
}

/// Begins a render pass on these colour and depth-stencil targets.
fn pass<'e>(
    encoder: &'e mut wgpu::CommandEncoder,
    label: &str,
    start: Start,
    (color, depth_stencil): (Attachment<'_>, &DepthStencil),
    (timestamp_writes, occlusion_query_set): (
        Option<wgpu::RenderPassTimestampWrites<'_>>,
        Option<&wgpu::QuerySet>,
    ),
) -> wgpu::RenderPass<'e> {
    let [r, g, b] = scene::CLEAR_SRGB.map(|c| crate::gpu::srgb_to_linear(c) as f64);
    let (color_load, depth, stencil) = match start {
        Start::Cleared => (
            wgpu::LoadOp::Clear(wgpu::Color { r, g, b, a: 1.0 }),
            wgpu::LoadOp::Clear(1.0),
            wgpu::LoadOp::Clear(0),
        ),
        Start::Kept => (wgpu::LoadOp::Load, wgpu::LoadOp::Load, wgpu::LoadOp::Load),
    };
    let (color, color_load) = match color {
        Attachment::Color(color) => (color, color_load),
        Attachment::Map(map) => (map, wgpu::LoadOp::Clear(wgpu::Color::WHITE)),
    };
    encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
        label: Some(label),
        color_attachments: &[Some(wgpu::RenderPassColorAttachment {
            view: color,
            depth_slice: None,
            resolve_target: None,
            ops: wgpu::Operations {
                load: color_load,
                store: wgpu::StoreOp::Store,
            },
        })],
        depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
            view: &depth_stencil.view,
            depth_ops: Some(wgpu::Operations {
                load: depth,
                store: wgpu::StoreOp::Store,
            }),
            stencil_ops: Some(wgpu::Operations {
                load: stencil,
                store: wgpu::StoreOp::Store,
            }),
        }),
        timestamp_writes,
        occlusion_query_set,
        multiview_mask: None,
    })
}
