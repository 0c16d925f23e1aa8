//! What the window and the headless runner share: a lesson with its room, knobs, camera and
//! depth-stencil buffer, rendering into whatever colour view it is handed.

use std::sync::Arc;

use anyhow::Result;

use crate::camera::Camera;
use crate::gpu::{DepthStencil, Gpu};
use crate::knobs::Knobs;
use crate::lesson::{Frame, Lesson};
use crate::scene::{Scene, SceneOptions};
use crate::views::DepthViewPipelines;

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

    /// Records the lesson's frame into `color` and returns the encoder, for the caller to add copies to
    /// and submit. Fails when the lesson asked for something this backend cannot do.
    pub fn record(&self, color: &wgpu::TextureView) -> Result<wgpu::CommandEncoder> {
        let (width, height) = self.depth_stencil.size();
        self.scene
            .update(&self.gpu.queue, &self.camera, width as f32 / height as f32);
        let encoder = self
            .gpu
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some(L::NAME),
            });
        let mut frame = Frame {
            gpu: &self.gpu,
            scene: &self.scene,
            camera: self.camera,
            encoder,
            color,
            depth_stencil: &self.depth_stencil,
            depth_view: self
                .scene
                .depth_view
                .as_ref()
                .zip(self.depth_bind_group.as_ref()),
            unsupported: None,
        };
        self.lesson.render(&mut frame);
        match frame.unsupported {
            Some(problem) => Err(anyhow::anyhow!(problem)),
            None => Ok(frame.encoder),
        }
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
