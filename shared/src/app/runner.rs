//! What the window and the headless runner share: a lesson with its room, knobs, camera and
//! depth-stencil buffer, rendering into whatever colour view it is handed.

use std::sync::Arc;

use anyhow::Result;

use crate::gpu::pass::{Probe, Probing};
use crate::gpu::timing::StepTimer;
use crate::gpu::views::{DepthViewPipelines, Palette};
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
    /// The test map of `--show tests`, kept for the next frame of the same size.
    test_map: std::sync::Mutex<Option<((u32, u32), wgpu::TextureView)>>,
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
            test_map: Default::default(),
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
            draw,
        } = request;
        let map = output.map(|(show, _)| show).filter(|show| show.is_map());
        let mut whole = match probe {
            None => self.replay(map, (color, stop, draw), pictures, timer)?,
            Some(_) => None,
        };
        let (pictures, timer) = match whole {
            Some(_) => (None, None),
            None => (pictures, timer),
        };
        let probe = probe.or(whole.as_mut());
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
                        // A test map of such a step is refused once the frame is recorded.
                        if show == Show::Tests {
                            return;
                        }
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
        let present = Some(&mut present as AfterStep<'_>);
        let (mut encoder, steps) = self.render(color, (stop, passes, timer), probe, present);
        if let Some(error) = failure {
            return Err(error);
        }
        stop.resolve(&steps)?;
        if let Some(whole) = &whole {
            mapped(whole, &steps)?;
        }
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

    /// Records the lesson's frame into `color`, up to `stop`, recorded as `passes` say, timed,
    /// probed and looked into after each step as asked.
    fn render<'f>(
        &'f self,
        color: &'f wgpu::TextureView,
        (stop, passes, timer): (Stop, Passes, Option<&'f StepTimer>),
        probe: Option<&'f mut Probe>,
        present: Option<AfterStep<'f>>,
    ) -> (wgpu::CommandEncoder, Vec<&'static str>) {
        let targets = (color, &self.depth_stencil);
        let cameras = (self.camera, self.view());
        let frame = Frame::new(
            &self.gpu,
            &self.scene,
            cameras,
            targets,
            stop.count(),
            present,
        );
        let mut frame = frame.with_passes(passes);
        frame.timer = timer;
        if let Some(probe) = probe {
            frame = frame.with_probe(probe);
        }
        self.lesson.render(&mut frame);
        frame.finish()
    }

    /// The depth and stencil pictures asked for, each with what it shows (none of depth where the
    /// backend cannot read depth in a shader).
    fn pictures<'p>(&self, pictures: Option<Pictures<'p>>) -> Vec<(Show, &'p wgpu::TextureView)> {
        let Some(Pictures {
            depth,
            stencil,
            raw_depth,
            ..
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
    /// hidden), as the headless runner draws it, stopped and shown as asked (with the draw a test
    /// map shows), and submits.
    pub fn draw_alone(
        &mut self,
        target: &wgpu::TextureView,
        (width, height): (u32, u32),
        (stop, show, draw): (Stop, Show, Option<usize>),
    ) -> Result<()> {
        self.resize(width, height);
        let request = FrameRequest::to(target).stop(stop).show(show, target);
        let request = request.draw(draw);
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
        (stop, show, draw): (Stop, Show, Option<usize>),
    ) -> Result<()> {
        self.resize(size.0, size.1);
        let request = FrameRequest::to(picture).stop(stop).show(show, picture);
        let request = request.draw(draw);
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
            Show::Color | Show::Stencil | Show::Complexity | Show::Tests => true,
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
            Show::Color | Show::Tests => {}
            Show::Depth | Show::RawDepth => {
                let (pipelines, bind_group) = depth()?;
                pipelines.show(encoder, target, bind_group, show == Show::RawDepth);
            }
            Show::Stencil | Show::Complexity => {
                let (device, views) = (&self.gpu.device, &self.scene.stencil_view);
                let palette = palette(show);
                views.show(device, encoder, (target, palette), &self.depth_stencil);
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
        if show == Show::Tests {
            anyhow::bail!(
                "this step draws into the lesson's own texture: a test map shows a step drawn into \
                 the frame's target"
            );
        }
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
            Show::Color | Show::Tests => {}
            Show::Depth | Show::RawDepth => {
                let pipelines = self.scene.depth_view.as_ref();
                let pipelines =
                    pipelines.ok_or_else(|| anyhow::anyhow!(DepthViewPipelines::UNSUPPORTED))?;
                let bind_group = pipelines.bind_group(device, &target.depth_stencil);
                pipelines.show(encoder, &picture, &bind_group, show == Show::RawDepth);
            }
            Show::Stencil | Show::Complexity => {
                let views = &self.scene.stencil_view;
                let palette = (&picture, palette(show));
                views.show(device, encoder, palette, &target.depth_stencil);
            }
        }
        self.scene.blit.draw(device, encoder, &picture, output);
        Ok(())
    }

    /// Where a map is shown, the probe that replays the frame's draws as their twins, in a frame of
    /// its own: the buffers' pictures, where asked for too, are recorded and submitted first, from
    /// the frame as the lesson draws it. Where the complexity's picture is asked for beside
    /// another view, its frame is recorded and submitted first.
    fn replay(
        &self,
        map: Option<Show>,
        (color, stop, draw): (&wgpu::TextureView, Stop, Option<usize>),
        pictures: Option<Pictures<'_>>,
        timer: Option<&StepTimer>,
    ) -> Result<Option<Probe>> {
        let submit = |request| -> Result<()> {
            let recorded = self.record(request)?;
            self.gpu.queue.submit([recorded.encoder.finish()]);
            Ok(())
        };
        let Some(show) = map else {
            if let Some(heat) = pictures.and_then(|p| p.complexity) {
                let to = FrameRequest::to(color).stop(stop);
                submit(to.show(Show::Complexity, heat))?;
            }
            return Ok(None);
        };
        if pictures.is_some() {
            let frame = FrameRequest::to(color).stop(stop).timed(timer);
            let pictures = pictures.map(|p| Pictures {
                complexity: p.complexity.filter(|_| show != Show::Complexity),
                ..p
            });
            submit(FrameRequest { pictures, ..frame })?;
        }
        Ok(Some(self.whole_probe(show, stop, draw)?))
    }

    /// The probe that replays the frame for a map: every draw counted, or the fates of the draws of
    /// the step the frame stops after, drawn into a test map of the frame's size.
    fn whole_probe(&self, show: Show, stop: Stop, draw: Option<usize>) -> Result<Probe> {
        let device = &self.gpu.device;
        if show == Show::Complexity {
            return Ok(Probe::whole(device, Probing::Count, None));
        }
        let step = stop.resolve(&self.steps())? - 1;
        let mut cached = self.test_map.lock().unwrap_or_else(|p| p.into_inner());
        let size = self.depth_stencil.size();
        let format = self.scene.color_format;
        let map = match cached.as_ref() {
            Some((made_for, map)) if *made_for == size => map.clone(),
            _ => {
                let map = crate::gpu::maps::map_texture(device, format, size);
                cached.insert((size, map)).1.clone()
            }
        };
        let probing = Probing::Fates { step, draw };
        Ok(Probe::whole(device, probing, Some(map)))
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
    /// The draw a test map shows (its index in the step), or every draw of the step.
    draw: Option<usize>,
}

/// The depth and stencil buffers painted to be seen (the window's panel shows them small), and
/// the depth complexity where asked for.
#[derive(Clone, Copy)]
struct Pictures<'p> {
    depth: &'p wgpu::TextureView,
    stencil: &'p wgpu::TextureView,
    complexity: Option<&'p wgpu::TextureView>,
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
            draw: None,
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
            complexity: None,
            raw_depth,
        });
        Self { pictures, ..self }
    }

    /// With the depth complexity painted into `complexity` too, counted in a frame of its own
    /// recorded and submitted before this one (after [`FrameRequest::pictures`]).
    pub fn complexity(mut self, complexity: &'r wgpu::TextureView) -> Self {
        if let Some(pictures) = &mut self.pictures {
            pictures.complexity = Some(complexity);
        }
        self
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

    /// With [`Show::Tests`], the test map of this draw of the step (its index in the step, from 0)
    /// rather than of every draw in it.
    pub fn draw(self, draw: Option<usize>) -> Self {
        Self { draw, ..self }
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

/// The palette a view paints the stencil buffer in.
fn palette(show: Show) -> Palette {
    match show {
        Show::Complexity => Palette::Heat,
        _ => Palette::Values,
    }
}

/// Fails where a test map was asked for and not drawn: its step drew into the lesson's own target,
/// or its draw is past the step's last.
fn mapped(probe: &Probe, steps: &[&str]) -> Result<()> {
    let Probing::Fates { step, draw } = probe.probing else {
        return Ok(());
    };
    let (number, name) = (step + 1, steps[step]);
    if probe.map_drawn {
        let count = probe.draws.iter().filter(|d| d.step == step).count();
        match draw {
            Some(draw) if draw >= count => anyhow::bail!(
                "step {number} ({name}) has {count} draw{}: --draw takes 1 to {count}, or none for \
                 every draw of the step",
                if count == 1 { "" } else { "s" }
            ),
            _ => return Ok(()),
        }
    }
    anyhow::bail!(
        "step {number} ({name}) draws into the lesson's own texture: a test map shows a step drawn \
         into the frame's target"
    )
}

fn depth_bind_group(gpu: &Gpu, scene: &Scene, target: &DepthStencil) -> Option<wgpu::BindGroup> {
    let pipelines = scene.depth_view.as_ref()?;
    Some(pipelines.bind_group(&gpu.device, target))
}
