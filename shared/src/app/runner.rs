//! What the window and the headless runner share: a lesson with its room, knobs, camera and
//! depth-stencil buffer, rendering into whatever colour view it is handed.

use std::sync::Arc;

use anyhow::Result;

use crate::gpu::views::DepthViewPipelines;
use crate::gpu::{DepthStencil, Gpu};
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::lesson::{Frame, Lesson};
use crate::room::camera::{Camera, View};
use crate::room::scene::{Scene, SceneOptions};

pub struct Runner<L: Lesson> {
    pub gpu: Arc<Gpu>,
    pub scene: Scene,
    pub lesson: L,
    pub knobs: Knobs,
    pub camera: Camera,
    pub depth_stencil: DepthStencil,
    depth_bind_group: Option<wgpu::BindGroup>,
}

impl<L: Lesson> Runner<L> {
    pub fn new(
        gpu: Arc<Gpu>,
        color_format: wgpu::TextureFormat,
        scene: &SceneOptions,
        knobs: Knobs,
        camera: Camera,
        (width, height): (u32, u32),
    ) -> Result<Self> {
        let scene = Scene::new(&gpu, color_format, scene)?;
        let lesson = L::new(&gpu, &scene, &knobs)?;
        let depth_stencil = DepthStencil::new(&gpu.device, width, height);
        let depth_bind_group = depth_bind_group(&gpu, &scene, &depth_stencil);
        gpu.check_errors()?;
        Ok(Self {
            gpu,
            scene,
            lesson,
            knobs,
            camera,
            depth_stencil,
            depth_bind_group,
        })
    }

    /// Makes the depth-stencil buffer match a new target size.
    pub fn resize(&mut self, width: u32, height: u32) {
        if self.depth_stencil.size() != (width, height) {
            self.depth_stencil = DepthStencil::new(&self.gpu.device, width, height);
            self.depth_bind_group = depth_bind_group(&self.gpu, &self.scene, &self.depth_stencil);
        }
    }

    /// Rebuilds the lesson for new knob values.
    pub fn set_knobs(&mut self, knobs: Knobs) -> Result<()> {
        self.lesson = L::new(&self.gpu, &self.scene, &knobs)?;
        self.knobs = knobs;
        Ok(())
    }

    /// The names of the frame's steps with the current knobs, in order (nothing is recorded).
    pub fn steps(&self) -> Vec<&'static str> {
        // A frame that stops before its first step records nothing: any view will do as its colour.
        self.frame(&self.depth_stencil.stencil_values, 0, None)
            .steps
    }

    /// Records the lesson's frame into `color`, up to the step `stop` names, and returns the encoder
    /// (for the caller to add views, copies and submit) with the frame's step names. Fails on a step
    /// past the end.
    pub fn record(
        &self,
        color: &wgpu::TextureView,
        stop: Stop,
    ) -> Result<(wgpu::CommandEncoder, Vec<&'static str>)> {
        self.update();
        let frame = self.frame(color, stop.count(), None);
        stop.resolve(&frame.steps)?;
        Ok((frame.encoder, frame.steps))
    }

    /// Records the whole frame into `color`, calling `after_step` with the encoder after every
    /// step: one frame that shows each step's buffers (`--film`).
    pub fn record_each_step(
        &self,
        color: &wgpu::TextureView,
        after_step: &mut dyn FnMut(&mut wgpu::CommandEncoder),
    ) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        self.update();
        let frame = self.frame(color, usize::MAX, Some(after_step));
        (frame.encoder, frame.steps)
    }

    /// Writes this frame's camera and lights.
    fn update(&self) {
        self.scene.update(&self.gpu.queue, &self.view());
    }

    /// What the camera sees through, at the target's aspect ratio.
    pub fn view(&self) -> View {
        let (width, height) = self.depth_stencil.size();
        self.camera.view_at(width as f32 / height as f32)
    }

    fn frame<'f>(
        &'f self,
        color: &'f wgpu::TextureView,
        stop: usize,
        after_step: Option<&'f mut dyn FnMut(&mut wgpu::CommandEncoder)>,
    ) -> Frame<'f> {
        let targets = (color, &self.depth_stencil);
        let scene = &self.scene;
        let cameras = (self.camera, self.view());
        let mut frame = Frame::new(&self.gpu, scene, cameras, targets, stop, after_step);
        self.lesson.render(&mut frame);
        frame
    }

    /// Whether this backend can show that buffer (the GL backend cannot read depth in a shader).
    pub fn can_show(&self, show: Show) -> bool {
        match show {
            Show::Depth | Show::RawDepth => self.depth_bind_group.is_some(),
            Show::Color | Show::Stencil => true,
        }
    }

    /// Paints `target` (a texture of the scene's colour format and the frame's size) with what the
    /// depth or stencil buffer holds now; for [`Show::Color`] does nothing, the colours being the
    /// frame's own target.
    pub fn show(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        show: Show,
        target: &wgpu::TextureView,
    ) -> Result<()> {
        let depth = || {
            let pipelines = self.scene.depth_view.as_ref();
            pipelines
                .zip(self.depth_bind_group.as_ref())
                .ok_or_else(|| anyhow::anyhow!(DepthViewPipelines::UNSUPPORTED))
        };
        match show {
            Show::Color => {}
            Show::Depth | Show::RawDepth => {
                let (pipelines, bind_group) = depth()?;
                pipelines.show(encoder, target, bind_group, show == Show::RawDepth);
            }
            Show::Stencil => {
                let (device, views) = (&self.gpu.device, &self.scene.stencil_view);
                views.show(device, encoder, target, &self.depth_stencil);
            }
        }
        Ok(())
    }

    /// Copies the depth buffer into an R32Float texture the caller can read back.
    pub(crate) fn copy_depth(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
    ) -> Result<()> {
        let (Some(pipelines), Some(bind_group)) = (&self.scene.depth_view, &self.depth_bind_group)
        else {
            anyhow::bail!(DepthViewPipelines::UNSUPPORTED);
        };
        pipelines.copy(encoder, target, bind_group);
        Ok(())
    }
}

fn depth_bind_group(gpu: &Gpu, scene: &Scene, target: &DepthStencil) -> Option<wgpu::BindGroup> {
    let pipelines = scene.depth_view.as_ref()?;
    Some(pipelines.bind_group(&gpu.device, target))
}
