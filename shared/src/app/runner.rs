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

    /// Records the frame `request` asks for: the one question every runner asks once a frame (the
    /// window, the headless runner, the web page, the workbench, each round of a pixel's story).
    /// The caller adds its copies to the encoder and submits it. Fails on a step past the end.
    pub fn record(&self, request: FrameRequest<'_>) -> Result<Recorded> {
        self.update();
        let FrameRequest {
            color,
            stop,
            output,
            pictures,
            timer,
            probe,
            mut after_step,
        } = request;
        // Looking between the steps, or at one pixel through them, needs a pass each; otherwise as
        // the runner records.
        let passes = match (&after_step, &probe) {
            (None, None) => self.passes,
            _ => Passes::PerStep,
        };
        let (mut shown, mut failure) = (false, None);
        // A frame that stops after a step drawn into a lesson's own target shows that target.
        let mut present =
            |encoder: &mut wgpu::CommandEncoder, index, target: Option<&Offscreen>| {
                if let Some(after_step) = after_step.as_mut() {
                    after_step(encoder, index, target);
                }
                if let (Some(target), Stop::After(number)) = (target, stop)
                    && index + 1 == number
                {
                    shown = true;
                    let mut paint = |show, output| {
                        if let Err(error) = self.show_offscreen(encoder, show, target, output) {
                            failure.get_or_insert(error);
                        }
                    };
                    if let Some((show, output)) = output {
                        paint(show, output);
                    }
                    for (show, picture) in self.pictures(pictures) {
                        paint(show, picture);
                    }
                }
            };
        let targets = (color, &self.depth_stencil);
        let cameras = (self.camera, self.view());
        let (stop_count, present) = (stop.count(), Some(&mut present as AfterStep<'_>));
        let frame = Frame::new(
            &self.gpu,
            &self.scene,
            cameras,
            targets,
            stop_count,
            present,
        );
        let mut frame = frame.with_passes(passes);
        frame.timer = timer;
        if let Some(probe) = probe {
            frame = frame.with_probe(probe);
        }
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
        if !shown {
            if let Some((show, output)) = output {
                self.show(&mut encoder, show, output)?;
            }
            for (show, picture) in self.pictures(pictures) {
                self.show(&mut encoder, show, picture)?;
            }
        }
        Ok(Recorded { encoder, steps })
    }

    /// The depth and stencil pictures asked for, each with what it shows (none of depth where the
    /// backend cannot read depth in a shader).
    fn pictures<'p>(&self, pictures: Option<Pictures<'p>>) -> Vec<(Show, &'p wgpu::TextureView)> {
        let Some(Pictures {
            depth,
            stencil,
            raw_depth,
        }) = pictures
        else {
            return Vec::new();
        };
        let depth_show = if raw_depth {
            Show::RawDepth
        } else {
            Show::Depth
        };
        let depth = self.can_show(Show::Depth).then_some((depth_show, depth));
        depth
            .into_iter()
            .chain([(Show::Stencil, stencil)])
            .collect()
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
        let request = FrameRequest::to(target).stop(stop).show(show, target);
        self.gpu
            .queue
            .submit([self.record(request)?.encoder.finish()]);
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
        let request = FrameRequest::to(picture).stop(stop).show(show, picture);
        let mut encoder = self.record(request)?.encoder;
        let (device, pixelated) = (&self.gpu.device, wgpu::FilterMode::Nearest);
        let blit = &self.scene.blit;
        blit.draw_in(device, &mut encoder, picture, target, None, pixelated);
        self.gpu.queue.submit([encoder.finish()]);
        Ok(())
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

/// What a runner is asked for one frame: where the colours go, where the frame stops, which
/// buffers are painted to be seen, and whether it is timed, probed or looked into after each step.
pub struct FrameRequest<'r> {
    color: &'r wgpu::TextureView,
    stop: Stop,
    output: Option<(Show, &'r wgpu::TextureView)>,
    pictures: Option<Pictures<'r>>,
    timer: Option<&'r StepTimer>,
    probe: Option<&'r mut Probe>,
    after_step: Option<AfterStep<'r>>,
}

/// The depth and stencil buffers painted to be seen (the window's panel shows them small).
#[derive(Clone, Copy)]
struct Pictures<'p> {
    depth: &'p wgpu::TextureView,
    stencil: &'p wgpu::TextureView,
    /// The stored depth values rather than the linearised depth.
    raw_depth: bool,
}

impl<'r> FrameRequest<'r> {
    /// The whole frame, its colours into `color`, nothing else.
    pub fn to(color: &'r wgpu::TextureView) -> Self {
        Self {
            color,
            stop: Stop::Last,
            output: None,
            pictures: None,
            timer: None,
            probe: None,
            after_step: None,
        }
    }

    /// Stopped after the step `stop` names.
    pub fn stop(self, stop: Stop) -> Self {
        Self { stop, ..self }
    }

    /// With `output` painted with the buffer `show` asks for, as it is where the frame stops (for
    /// [`Show::Color`], `output` is `color` itself; where the frame stops after a step drawn into
    /// a lesson's own target, that target's buffer).
    pub fn show(self, show: Show, output: &'r wgpu::TextureView) -> Self {
        let output = Some((show, output));
        Self { output, ..self }
    }

    /// With the depth and stencil buffers, as they are where the frame stops, painted into
    /// `depth` (linearised, or the stored values with `raw_depth`; not at all where the backend
    /// cannot read depth in a shader) and `stencil`.
    pub fn pictures(self, [depth, stencil]: [&'r wgpu::TextureView; 2], raw_depth: bool) -> Self {
        let pictures = Some(Pictures {
            depth,
            stencil,
            raw_depth,
        });
        Self { pictures, ..self }
    }

    /// With every step's pass writing its timestamps into `timer`, resolved for
    /// [`StepTimer::read`] (a pass a step).
    pub fn timed(self, timer: Option<&'r StepTimer>) -> Self {
        Self { timer, ..self }
    }

    /// With `probe` watching its pixel (a pass a step, each kept to that pixel; every draw drawn as
    /// the probe says): a round of a pixel's story.
    pub fn probed(self, probe: &'r mut Probe) -> Self {
        let probe = Some(probe);
        Self { probe, ..self }
    }

    /// Calling `after_step` after every step (a pass a step): the film of every step's buffers.
    pub fn each_step(self, after_step: AfterStep<'r>) -> Self {
        let after_step = Some(after_step);
        Self { after_step, ..self }
    }
}

/// What a runner gives back for a frame: its commands, for the caller to add its copies to and
/// submit, and the frame's step names.
pub struct Recorded {
    pub encoder: wgpu::CommandEncoder,
    pub steps: Vec<&'static str>,
}

fn depth_bind_group(gpu: &Gpu, scene: &Scene, target: &DepthStencil) -> Option<wgpu::BindGroup> {
    let pipelines = scene.depth_view.as_ref()?;
    Some(pipelines.bind_group(&gpu.device, target))
}
