//! What the window and the headless runner share: a lesson with its room, knobs, camera and
//! depth-stencil buffer, rendering into whatever colour view it is handed.

use std::sync::Arc;

use anyhow::Result;

use crate::gpu::pass::Probe;
use crate::gpu::timing::StepTimer;
use crate::gpu::views::DepthViewPipelines;
use crate::gpu::{DepthStencil, Gpu, Offscreen};
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::lesson::{AfterStep, Frame, Lesson, Passes};
use crate::room::camera::{Camera, View};
use crate::room::scene::Scene;

pub struct Runner<L: Lesson> {
    pub gpu: Arc<Gpu>,
    pub scene: Scene,
    pub lesson: L,
    pub knobs: Knobs,
    pub camera: Camera,
    pub depth_stencil: DepthStencil,
    depth_bind_group: Option<wgpu::BindGroup>,
    /// How frames that nothing looks into between their steps are recorded (tests compare both).
    pub passes: Passes,
}

impl<L: Lesson> Runner<L> {
    #[cfg(not(target_arch = "wasm32"))]
    pub fn new(
        gpu: Arc<Gpu>,
        color_format: wgpu::TextureFormat,
        scene: crate::room::scene::SceneReading,
        knobs: Knobs,
        camera: Camera,
        (width, height): (u32, u32),
    ) -> Result<Self> {
        let scene = Scene::new(&gpu, color_format, scene)?;
        // Timed here, not in `with_scene`: the browser has no `Instant` (it panics there).
        let start = std::time::Instant::now();
        let runner = Self::with_scene(gpu, scene, knobs, camera, (width, height));
        log::info!(target: crate::gpu::STARTUP, "lesson built in {:.0?}", start.elapsed());
        runner
    }

    /// The lesson in a room already built (the web page builds it from fetched assets).
    pub fn with_scene(
        gpu: Arc<Gpu>,
        scene: Scene,
        knobs: Knobs,
        camera: Camera,
        (width, height): (u32, u32),
    ) -> Result<Self> {
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
            passes: Passes::default(),
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
        self.scene.pipelines.forget();
        self.lesson = L::new(&self.gpu, &self.scene, &knobs)?;
        self.knobs = knobs;
        Ok(())
    }

    /// The names of the frame's steps with the current knobs, in order (nothing is recorded).
    pub fn steps(&self) -> Vec<&'static str> {
        // A frame that stops before its first step records nothing: any view will do as its colour.
        self.frame(&self.depth_stencil.stencil_values, 0, None, Passes::PerStep)
            .steps
    }

    /// Records the lesson's frame into `color` up to the step `stop` names, and paints `output`
    /// with the buffer `show` asks for (for [`Show::Color`], `output` is `color` itself, or where a
    /// step drawn into a lesson's own target is shown). Returns the encoder, for the caller to add
    /// copies to and submit, with the frame's step names. Fails on a step past the end.
    pub fn record(
        &self,
        color: &wgpu::TextureView,
        stop: Stop,
        show: Show,
        output: &wgpu::TextureView,
    ) -> Result<(wgpu::CommandEncoder, Vec<&'static str>)> {
        self.update();
        let (mut shown, mut failure) = (false, None);
        // A frame that stops after a step drawn into a lesson's own target shows that target.
        let mut present =
            |encoder: &mut wgpu::CommandEncoder, index, target: Option<&Offscreen>| {
                if let (Some(target), Stop::After(number)) = (target, stop)
                    && index + 1 == number
                {
                    shown = true;
                    if let Err(error) = self.show_offscreen(encoder, show, target, output) {
                        failure.get_or_insert(error);
                    }
                }
            };
        let frame = self.frame(color, stop.count(), Some(&mut present), self.passes);
        let (mut encoder, steps) = frame.finish();
        if let Some(error) = failure {
            return Err(error);
        }
        stop.resolve(&steps)?;
        if !shown {
            self.show(&mut encoder, show, output)?;
        }
        Ok((encoder, steps))
    }

    /// Draws the lesson alone into `target` of `size` pixels (a window's surface with the panel
    /// hidden), as the headless runner draws it, and submits.
    pub fn draw_alone(
        &mut self,
        target: &wgpu::TextureView,
        (width, height): (u32, u32),
        stop: Stop,
        show: Show,
    ) -> Result<()> {
        self.resize(width, height);
        let (encoder, _) = self.record(target, stop, show, target)?;
        self.gpu.queue.submit([encoder.finish()]);
        Ok(())
    }

    /// Draws the frame into `picture` (of the size the lesson draws at) and shows it over the whole
    /// of `target`, each of its pixels made a block of the target's: a window drawing at half
    /// resolution, a WebGL2 canvas (see [`crate::app::web`]).
    pub fn draw_through(
        &mut self,
        (picture, size): (&wgpu::TextureView, (u32, u32)),
        target: &wgpu::TextureView,
        stop: Stop,
        show: Show,
    ) -> Result<()> {
        self.resize(size.0, size.1);
        let (mut encoder, _) = self.record(picture, stop, show, picture)?;
        let (device, pixelated) = (&self.gpu.device, wgpu::FilterMode::Nearest);
        let blit = &self.scene.blit;
        blit.draw_in(device, &mut encoder, picture, target, None, pixelated);
        self.gpu.queue.submit([encoder.finish()]);
        Ok(())
    }

    /// Records the frame into `color` up to `stop` and, given `pictures`, paints the depth and stencil
    /// buffers, as they are then, into them (the depth linearised, or the stored values with
    /// `raw_depth`; not at all where the backend cannot read depth in a shader). Where the frame stops
    /// after a step drawn into a lesson's own target, all three show that target's buffers. With a
    /// timer, every step's pass writes its timestamps, resolved for [`StepTimer::read`]. The window's
    /// panel shows the three side by side.
    pub fn record_buffers(
        &self,
        color: &wgpu::TextureView,
        pictures: Option<[&wgpu::TextureView; 2]>,
        stop: Stop,
        raw_depth: bool,
        timer: Option<&StepTimer>,
    ) -> Result<(wgpu::CommandEncoder, Vec<&'static str>)> {
        self.update();
        let depth_show = if raw_depth {
            Show::RawDepth
        } else {
            Show::Depth
        };
        let can_depth = self.can_show(Show::Depth);
        let (mut shown, mut failure) = (false, None);
        let mut present =
            |encoder: &mut wgpu::CommandEncoder, index, target: Option<&Offscreen>| {
                if let (Some(target), Stop::After(number)) = (target, stop)
                    && index + 1 == number
                {
                    shown = true;
                    let mut paint = |show, output| {
                        if let Err(error) = self.show_offscreen(encoder, show, target, output) {
                            failure.get_or_insert(error);
                        }
                    };
                    paint(Show::Color, color);
                    if let Some([depth, stencil]) = pictures {
                        if can_depth {
                            paint(depth_show, depth);
                        }
                        paint(Show::Stencil, stencil);
                    }
                }
            };
        let targets = (color, &self.depth_stencil);
        let cameras = (self.camera, self.view());
        let mut frame = Frame::new(
            &self.gpu,
            &self.scene,
            cameras,
            targets,
            stop.count(),
            Some(&mut present),
        )
        .with_passes(self.passes);
        frame.timer = timer;
        self.lesson.render(&mut frame);
        let (mut encoder, steps) = frame.finish();
        if let Some(error) = failure {
            return Err(error);
        }
        stop.resolve(&steps)?;
        if let Some(timer) = timer {
            // The steps after the stop were named but not recorded.
            timer.resolve(&mut encoder, steps.len().min(stop.count()));
        }
        if let (false, Some([depth, stencil])) = (shown, pictures) {
            if can_depth {
                self.show(&mut encoder, depth_show, depth)?;
            }
            self.show(&mut encoder, Show::Stencil, stencil)?;
        }
        Ok((encoder, steps))
    }

    /// Records the whole frame into `color` with each step's pass writing its timestamps into
    /// `timer`, which is then resolved: read the times with [`StepTimer::read`] after submitting.
    pub fn record_timed(
        &self,
        color: &wgpu::TextureView,
        timer: &StepTimer,
    ) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        self.update();
        let mut frame = Frame::new(
            &self.gpu,
            &self.scene,
            (self.camera, self.view()),
            (color, &self.depth_stencil),
            usize::MAX,
            None,
        );
        frame.timer = Some(timer);
        self.lesson.render(&mut frame);
        let (mut encoder, steps) = frame.finish();
        timer.resolve(&mut encoder, steps.len());
        (encoder, steps)
    }

    /// Records the whole frame into `color`, calling `after_step` after every step: one frame that
    /// shows each step's buffers (`--film`).
    pub fn record_each_step(
        &self,
        color: &wgpu::TextureView,
        after_step: AfterStep<'_>,
    ) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        self.update();
        let frame = self.frame(color, usize::MAX, Some(after_step), Passes::PerStep);
        frame.finish()
    }

    /// Records the whole frame into `color` with `probe` watching its pixel (a pass a step, each
    /// kept to that pixel; every draw drawn as the probe says), calling `after_step` after every
    /// step: one frame of a pixel's story.
    pub fn record_probed(
        &self,
        color: &wgpu::TextureView,
        probe: &mut Probe,
        after_step: AfterStep<'_>,
    ) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        self.update();
        let targets = (color, &self.depth_stencil);
        let cameras = (self.camera, self.view());
        let mut frame = Frame::new(
            &self.gpu,
            &self.scene,
            cameras,
            targets,
            usize::MAX,
            Some(after_step),
        )
        .with_probe(probe);
        self.lesson.render(&mut frame);
        frame.finish()
    }

    /// Copies one pixel of the depth buffer into the same pixel of `target` (R32Float).
    pub fn copy_depth_pixel(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        pixel: (u32, u32),
    ) -> Result<()> {
        let (Some(pipelines), Some(bind_group)) = (&self.scene.depth_view, &self.depth_bind_group)
        else {
            anyhow::bail!(DepthViewPipelines::UNSUPPORTED);
        };
        pipelines.copy_pixel(encoder, target, bind_group, pixel);
        Ok(())
    }

    /// Rebuilds one pixel of the stencil buffer into the same pixel of `target`
    /// ([`crate::gpu::views::STENCIL_VALUES_FORMAT`]: value / 255).
    pub fn copy_stencil_pixel(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        pixel: (u32, u32),
    ) {
        let views = &self.scene.stencil_view;
        views.rebuild_pixel(encoder, target, &self.depth_stencil, pixel);
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
        after_step: Option<AfterStep<'f>>,
        passes: Passes,
    ) -> Frame<'f> {
        let targets = (color, &self.depth_stencil);
        let scene = &self.scene;
        let cameras = (self.camera, self.view());
        let mut frame =
            Frame::new(&self.gpu, scene, cameras, targets, stop, after_step).with_passes(passes);
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

    /// Paints `output` (any size) with one of the buffers of a lesson's own target: its colours, or
    /// its depth or stencil buffer as [`Runner::show`] paints the frame's.
    pub fn show_offscreen(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        show: Show,
        target: &Offscreen,
        output: &wgpu::TextureView,
    ) -> Result<()> {
        let device = &self.gpu.device;
        if show == Show::Color {
            self.scene
                .blit
                .draw(device, encoder, &target.color_view, output);
            return Ok(());
        }
        let picture = crate::gpu::target_texture(
            device,
            "offscreen buffer picture",
            self.scene.color_format,
            target.size(),
            wgpu::TextureUsages::TEXTURE_BINDING,
        );
        let picture = picture.create_view(&Default::default());
        match show {
            Show::Color => {}
            Show::Depth | Show::RawDepth => {
                let pipelines = self.scene.depth_view.as_ref();
                let pipelines =
                    pipelines.ok_or_else(|| anyhow::anyhow!(DepthViewPipelines::UNSUPPORTED))?;
                let bind_group = pipelines.bind_group(device, &target.depth_stencil);
                pipelines.show(encoder, &picture, &bind_group, show == Show::RawDepth);
            }
            Show::Stencil => {
                let views = &self.scene.stencil_view;
                views.show(device, encoder, &picture, &target.depth_stencil);
            }
        }
        self.scene.blit.draw(device, encoder, &picture, output);
        Ok(())
    }

    /// Copies the depth buffer into an R32Float texture the caller can read back.
    #[cfg(not(target_arch = "wasm32"))]
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
