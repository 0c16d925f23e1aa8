//! The headless runner: one frame at W×H into a texture, read back as an image, and on request the
//! stencil and depth buffers too (where the backend can copy them; the GL backend cannot). It also
//! films the frame: every step's colour, depth and stencil buffers as images.

use anyhow::{Context, Result, bail};
use image::RgbaImage;

use crate::app::args::Args;
use crate::app::runner::{FrameRequest, Recorded, Runner};
use crate::gpu::timing::StepTimer;
use crate::gpu::views::DEPTH_COPY_FORMAT;
use crate::gpu::{Gpu, HEADLESS_FORMAT, Offscreen};
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{self, Show, Stop};
use crate::lesson::story::Story;
use crate::lesson::{Lesson, Passes};
use crate::room::camera::Camera;
use crate::room::scene::SceneOptions;

/// What to render.
#[derive(Debug, Clone)]
pub struct Request {
    pub width: u32,
    pub height: u32,
    pub knobs: Knobs,
    pub camera: Camera,
    pub scene: SceneOptions,
    /// Also read back the stencil buffer.
    pub read_stencil: bool,
    /// Also read back the depth buffer.
    pub read_depth: bool,
    /// The step the frame stops after.
    pub stop: Stop,
    /// The buffer the colour image shows.
    pub show: Show,
    /// With [`Show::Tests`], the draw of the step whose test map is shown (its index in the step);
    /// every draw of the step for `None`.
    pub draw: Option<usize>,
    pub backend: Option<String>,
    pub verbose: bool,
    /// How the frame records its steps when nothing looks between them: in one render pass (the
    /// default), or in a pass each, as the film and the timers do.
    pub passes: Passes,
}

impl Request {
    /// The default picture of lesson `L` at 1280×720, changed by `name=value` knob settings.
    pub fn new<L: Lesson>(settings: &[impl AsRef<str>]) -> Result<Self> {
        Ok(Self {
            width: 1280,
            height: 720,
            knobs: Knobs::from_settings(L::KNOBS, settings)?,
            camera: L::CAMERA,
            scene: SceneOptions::default(),
            read_stencil: false,
            read_depth: false,
            stop: Stop::Last,
            show: L::SHOWS,
            draw: None,
            backend: None,
            verbose: false,
            passes: Passes::default(),
        })
    }
}

/// What came back.
#[derive(Debug, Clone)]
pub struct Capture {
    /// The picture of the buffer the request showed (the colours, unless told otherwise), alpha set
    /// to opaque as a window shows it.
    pub color: RgbaImage,
    /// One stencil value per pixel, rows top to bottom.
    pub stencil: Option<Vec<u8>>,
    /// One depth value per pixel (0 near .. 1 far), rows top to bottom.
    pub depth: Option<Vec<f32>>,
}

impl Capture {
    pub fn width(&self) -> u32 {
        self.color.width()
    }
    pub fn stencil_at(&self, x: u32, y: u32) -> Option<u8> {
        let stencil = self.stencil.as_ref()?;
        Some(stencil[(y * self.width() + x) as usize])
    }
    pub fn depth_at(&self, x: u32, y: u32) -> Option<f32> {
        let depth = self.depth.as_ref()?;
        Some(depth[(y * self.width() + x) as usize])
    }
}

/// What one measured frame cost.
#[derive(Debug, Clone)]
pub struct FrameTiming {
    pub steps: Vec<&'static str>,
    /// Each step's GPU time in milliseconds, where the adapter has timestamp queries.
    pub gpu_ms: Option<Vec<f64>>,
    /// CPU time to record the frame's commands and submit them.
    pub record_and_submit: std::time::Duration,
    /// Of which the submission (the driver's share, mostly).
    pub submit: std::time::Duration,
    /// From the start of recording until the GPU has finished the frame.
    pub frame: std::time::Duration,
}

/// One step of a film: the three buffers after the step.
#[derive(Debug, Clone)]
pub struct Still {
    /// The step's name.
    pub step: &'static str,
    /// The colours, the depth buffer linearised to grey, the stencil buffer in false colour, and
    /// the depth complexity so far as heat.
    pub color: RgbaImage,
    pub depth: RgbaImage,
    pub stencil: RgbaImage,
    pub complexity: RgbaImage,
}

impl Still {
    /// The image of one of the buffers, or of the complexity (a film has no test maps: the
    /// colours stand for them).
    pub fn image(&self, show: Show) -> &RgbaImage {
        match show {
            Show::Depth | Show::RawDepth => &self.depth,
            Show::Stencil => &self.stencil,
            Show::Complexity => &self.complexity,
            Show::Color | Show::Tests => &self.color,
        }
    }
}

/// Renders one frame of lesson `L`.
pub fn render<L: Lesson>(request: &Request) -> Result<Capture> {
    Headless::<L>::new(request)?.capture()
}

/// A lesson ready to render headless, again and again: tests step through knob values with
/// [`Headless::set_knobs`] without building the GPU and the room each time.
pub struct Headless<L: Lesson> {
    runner: Runner<L>,
    color: wgpu::Texture,
    /// Where the depth and the stencil buffer are painted to be seen.
    depth_picture: wgpu::Texture,
    stencil_picture: wgpu::Texture,
    /// Where the colours of a step drawn into a lesson's own target are shown in a film.
    offscreen_picture: wgpu::Texture,
    read_stencil: bool,
    read_depth: bool,
    stop: Stop,
    show: Show,
    draw: Option<usize>,
}

impl<L: Lesson> Headless<L> {
    pub fn new(request: &Request) -> Result<Self> {
        let scene = request.scene.start_reading();
        let gpu = Gpu::shared_headless(request.backend.as_deref(), request.verbose)?;
        check_size(&gpu, request.width, request.height)?;
        if (request.read_stencil || request.read_depth) && !gpu.can_copy_depth_stencil() {
            bail!(
                "this backend ({:?}) cannot copy depth or stencil to a buffer; use Vulkan",
                gpu.adapter.get_info().backend
            );
        }
        let size = (request.width, request.height);
        gpu.clone().scoped(|| {
            let mut runner = Runner::<L>::new(
                gpu,
                HEADLESS_FORMAT,
                scene,
                request.knobs.clone(),
                request.camera,
                size,
            )?;
            runner.passes = request.passes;
            let device = &runner.gpu.device;
            let picture = |label| target(device, label, HEADLESS_FORMAT, size);
            Ok(Self {
                color: picture("headless colour target"),
                depth_picture: picture("depth picture"),
                stencil_picture: picture("stencil picture"),
                offscreen_picture: picture("offscreen picture"),
                runner,
                read_stencil: request.read_stencil,
                read_depth: request.read_depth,
                stop: request.stop,
                show: request.show,
                draw: request.draw,
            })
        })
    }

    /// Where the next captures stop, what they show, and the draw a test map shows.
    pub fn set_view(&mut self, stop: Stop, show: Show, draw: Option<usize>) {
        (self.stop, self.show, self.draw) = (stop, show, draw);
    }

    /// Rebuilds the lesson for other knob values.
    pub fn set_knobs(&mut self, knobs: Knobs) -> Result<()> {
        let gpu = self.runner.gpu.clone();
        gpu.scoped(|| self.runner.set_knobs(knobs))
    }

    /// The adapter's name, backend and driver, as a benchmark names them.
    pub fn device_info(&self) -> String {
        let info = self.runner.gpu.adapter.get_info();
        format!("{} ({:?}, {})", info.name, info.backend, info.driver_info)
    }

    /// A timer for this lesson's device, where it has timestamp queries.
    pub fn timer(&self) -> Option<StepTimer> {
        StepTimer::new(&self.runner.gpu)
    }

    /// The device the lesson renders with (for wgpu's own counters, say).
    pub fn device(&self) -> &wgpu::Device {
        &self.runner.gpu.device
    }

    /// The names of the frame's steps with the current knobs.
    pub fn steps(&self) -> Vec<&'static str> {
        self.runner.steps()
    }

    /// Renders `count` whole frames without reading anything back, each waited for before the next
    /// (as a window waits for the display): what a long run does, to see that nothing grows.
    pub fn render_frames(&self, count: u64) -> Result<()> {
        self.runner.gpu.scoped(|| {
            let runner = &self.runner;
            let color_view = self.color.create_view(&Default::default());
            for _ in 0..count {
                let request = FrameRequest::to(&color_view).stop(self.stop);
                let recorded = runner.record(request.show(Show::Color, &color_view))?;
                runner.gpu.queue.submit([recorded.encoder.finish()]);
                runner
                    .gpu
                    .device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .context("waiting for the GPU failed")?;
            }
            Ok(())
        })
    }

    /// Renders one whole frame and measures it: the CPU time to record and submit it, the wall time
    /// until the GPU has finished it, and with a timer each step's GPU time.
    pub fn timed_frame(&self, timer: Option<&StepTimer>) -> Result<FrameTiming> {
        self.runner.gpu.scoped(|| {
            let (runner, device) = (&self.runner, &self.runner.gpu.device);
            let color_view = self.color.create_view(&Default::default());
            let start = std::time::Instant::now();
            let request = FrameRequest::to(&color_view).show(Show::Color, &color_view);
            let Recorded { encoder, steps } = runner.record(request.timed(timer))?;
            let commands = encoder.finish();
            let recorded = start.elapsed();
            runner.gpu.queue.submit([commands]);
            let record_and_submit = start.elapsed();
            let gpu_ms = timer.map(|t| t.read(device, steps.len())).transpose()?;
            device
                .poll(wgpu::PollType::wait_indefinitely())
                .context("waiting for the GPU failed")?;
            Ok(FrameTiming {
                steps,
                gpu_ms,
                record_and_submit,
                submit: record_and_submit - recorded,
                frame: start.elapsed(),
            })
        })
    }

    /// Renders a frame and reads back what the request asked for.
    pub fn capture(&self) -> Result<Capture> {
        self.runner.gpu.scoped(|| self.capture_unscoped())
    }

    /// The story of one pixel through the frame: every step's and every draw's values there, read
    /// back from the GPU (see [`crate::app::pixel`]). `settings` heads the story.
    pub fn story(&self, pixel: (u32, u32), settings: String) -> Result<Story> {
        crate::app::pixel::story(&self.runner, &self.color, pixel, settings)
    }

    /// Every draw of the frame, as a pixel's story meets them: step, recipe and object.
    pub fn draws(&self) -> Vec<crate::gpu::pass::Draw> {
        crate::app::pixel::draws(&self.runner, &view_of(&self.color))
    }

    /// Renders the frame once, reading back the colour, depth and stencil buffers after every step.
    pub fn film(&self) -> Result<Vec<Still>> {
        self.runner.gpu.scoped(|| self.film_unscoped())
    }

    fn film_unscoped(&self) -> Result<Vec<Still>> {
        let (runner, device) = (&self.runner, &self.runner.gpu.device);
        if !runner.can_show(Show::Depth) {
            bail!(crate::gpu::views::DepthViewPipelines::UNSUPPORTED);
        }
        let view = |texture: &wgpu::Texture| texture.create_view(&Default::default());
        let (depth_view, stencil_view) = (view(&self.depth_picture), view(&self.stencil_picture));
        let offscreen_view = view(&self.offscreen_picture);
        let mut readbacks = Vec::new();
        let mut failure = None;
        let color = view(&self.color);
        let mut after_step =
            |encoder: &mut wgpu::CommandEncoder, _, offscreen: Option<&Offscreen>| {
                // A step drawn into the lesson's own target is seen in that target's buffers.
                let shown = match offscreen {
                    Some(target) => [
                        (Show::Color, &offscreen_view),
                        (Show::Depth, &depth_view),
                        (Show::Stencil, &stencil_view),
                    ]
                    .into_iter()
                    .try_for_each(|(show, output)| {
                        runner.show_offscreen(encoder, show, target, output)
                    }),
                    None => runner
                        .show(encoder, Show::Depth, &depth_view)
                        .and_then(|()| runner.show(encoder, Show::Stencil, &stencil_view)),
                };
                if let Err(error) = shown {
                    failure.get_or_insert(error);
                }
                let color = match offscreen {
                    Some(_) => &self.offscreen_picture,
                    None => &self.color,
                };
                let pictures = [color, &self.depth_picture, &self.stencil_picture];
                let all = wgpu::TextureAspect::All;
                readbacks.push(pictures.map(|t| Readback::new(device, encoder, t, all, 4)));
            };
        let request = FrameRequest::to(&color).each_step(&mut after_step);
        let Recorded { encoder, steps } = runner.record(request)?;
        if let Some(error) = failure {
            return Err(error);
        }
        runner.gpu.queue.submit([encoder.finish()]);
        let complexity = self.film_complexity()?;
        steps
            .into_iter()
            .zip(readbacks)
            .zip(complexity)
            .map(|((step, readbacks), complexity)| {
                let [color, depth, stencil] =
                    readbacks.map(|readback| picture(readback.read(device)?, &self.color));
                Ok(Still {
                    step,
                    color: color?,
                    depth: depth?,
                    stencil: stencil?,
                    complexity,
                })
            })
            .collect()
    }

    /// The frame replayed with every draw counted, the count painted as heat after every step (in
    /// a step drawn into the lesson's own target, that target's count).
    fn film_complexity(&self) -> Result<Vec<RgbaImage>> {
        let (runner, device) = (&self.runner, &self.runner.gpu.device);
        let (color, heat) = (&self.color, &self.stencil_picture);
        let (color_view, heat_view) = (view_of(color), view_of(heat));
        let mut readbacks = Vec::new();
        let mut failure = None;
        let mut after_step =
            |encoder: &mut wgpu::CommandEncoder, _, offscreen: Option<&Offscreen>| {
                let shown = match offscreen {
                    Some(target) => {
                        runner.show_offscreen(encoder, Show::Complexity, target, &heat_view)
                    }
                    None => runner.show(encoder, Show::Complexity, &heat_view),
                };
                if let Err(error) = shown {
                    failure.get_or_insert(error);
                }
                let all = wgpu::TextureAspect::All;
                readbacks.push(Readback::new(device, encoder, heat, all, 4));
            };
        let request = FrameRequest::to(&color_view).each_step(&mut after_step);
        let request = request.show(Show::Complexity, &heat_view);
        let Recorded { encoder, .. } = runner.record(request)?;
        if let Some(error) = failure {
            return Err(error);
        }
        runner.gpu.queue.submit([encoder.finish()]);
        readbacks
            .into_iter()
            .map(|readback| picture(readback.read(device)?, color))
            .collect()
    }

    fn capture_unscoped(&self) -> Result<Capture> {
        let (runner, size) = (&self.runner, (self.color.width(), self.color.height()));
        let device = &runner.gpu.device;
        let color_view = self.color.create_view(&Default::default());
        let shown = match self.show {
            Show::Color => &self.color,
            Show::Depth | Show::RawDepth => &self.depth_picture,
            Show::Stencil | Show::Complexity => &self.stencil_picture,
            Show::Tests => &self.color,
        };
        let output = shown.create_view(&Default::default());
        let request = FrameRequest::to(&color_view)
            .stop(self.stop)
            .draw(self.draw);
        let mut encoder = runner.record(request.show(self.show, &output))?.encoder;

        let all = wgpu::TextureAspect::All;
        let mut readbacks = vec![Readback::new(device, &mut encoder, shown, all, 4)];
        if self.read_stencil {
            let stencil = &runner.depth_stencil.texture;
            let aspect = wgpu::TextureAspect::StencilOnly;
            readbacks.push(Readback::new(device, &mut encoder, stencil, aspect, 1));
        }
        if self.read_depth {
            let depth_copy = target(device, "depth copy", DEPTH_COPY_FORMAT, size);
            runner.copy_depth(&mut encoder, &depth_copy.create_view(&Default::default()))?;
            readbacks.push(Readback::new(device, &mut encoder, &depth_copy, all, 4));
        }
        runner.gpu.queue.submit([encoder.finish()]);
        let mut bytes = readbacks
            .into_iter()
            .map(|readback| readback.read(device))
            .collect::<Result<Vec<_>>>()?
            .into_iter();

        let color = picture(bytes.next().unwrap(), shown)?;
        let stencil = self.read_stencil.then(|| bytes.next().unwrap());
        let depth = self
            .read_depth
            .then(|| bytemuck::pod_collect_to_vec(&bytes.next().unwrap()));
        Ok(Capture {
            color,
            stencil,
            depth,
        })
    }
}

/// The bytes of an RGBA texture as an image, alpha set to opaque as a window shows it.
fn picture(mut bytes: Vec<u8>, texture: &wgpu::Texture) -> Result<RgbaImage> {
    // On the bytes, not through the image's pixel iterator: the `image` crate is not optimised in a
    // debug build, where its iterator took 16 ms of a 1280x720 screenshot's start-up; this, 1.
    for alpha in bytes.iter_mut().skip(3).step_by(4) {
        *alpha = 255;
    }
    RgbaImage::from_raw(texture.width(), texture.height(), bytes)
        .context("colour readback has the wrong size")
}

/// Refuses sizes the device cannot make.
pub fn check_size(gpu: &Gpu, width: u32, height: u32) -> Result<()> {
    let max = gpu.max_size();
    if width > max || height > max {
        bail!("size {width}x{height} is larger than this GPU allows ({max} pixels a side)");
    }
    Ok(())
}

/// A target the readback can copy from.
fn target(
    device: &wgpu::Device,
    label: &str,
    format: wgpu::TextureFormat,
    size: (u32, u32),
) -> wgpu::Texture {
    crate::gpu::target_texture(device, label, format, size, wgpu::TextureUsages::COPY_SRC)
}

/// Copies one aspect of a texture (mip 0) to the CPU and waits for it: rows top to bottom, without
/// padding. Tests use it for textures of their own.
pub fn read_texture(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    aspect: wgpu::TextureAspect,
    bytes_per_texel: u32,
) -> Result<Vec<u8>> {
    gpu.scoped(|| read_texture_unscoped(gpu, texture, aspect, bytes_per_texel))
}

fn read_texture_unscoped(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    aspect: wgpu::TextureAspect,
    bytes_per_texel: u32,
) -> Result<Vec<u8>> {
    let mut encoder = gpu
        .device
        .create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("readback"),
        });
    let readback = Readback::new(&gpu.device, &mut encoder, texture, aspect, bytes_per_texel);
    gpu.queue.submit([encoder.finish()]);
    readback.read(&gpu.device)
}

/// A texture copied into a mappable buffer, rows padded to 256 bytes as wgpu requires.
struct Readback {
    buffer: wgpu::Buffer,
    row_bytes: u32,
    padded_row_bytes: u32,
    height: u32,
}

impl Readback {
    fn new(
        device: &wgpu::Device,
        encoder: &mut wgpu::CommandEncoder,
        texture: &wgpu::Texture,
        aspect: wgpu::TextureAspect,
        bytes_per_texel: u32,
    ) -> Self {
        let (width, height) = (texture.width(), texture.height());
        let row_bytes = width * bytes_per_texel;
        let padded_row_bytes = row_bytes.next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback buffer"),
            size: (padded_row_bytes * height) as u64,
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row_bytes),
                    rows_per_image: Some(height),
                },
            },
            texture.size(),
        );
        Self {
            buffer,
            row_bytes,
            padded_row_bytes,
            height,
        }
    }

    /// Waits for the copy and returns the rows without their padding.
    fn read(self, device: &wgpu::Device) -> Result<Vec<u8>> {
        let mapped = map(device, &self.buffer)?;
        let mut bytes = Vec::with_capacity((self.row_bytes * self.height) as usize);
        for row in mapped.chunks(self.padded_row_bytes as usize) {
            bytes.extend_from_slice(&row[..self.row_bytes as usize]);
        }
        Ok(bytes)
    }
}

fn view_of(texture: &wgpu::Texture) -> wgpu::TextureView {
    texture.create_view(&Default::default())
}

/// Waits for the copies into `buffer` (made `MAP_READ`) and returns its bytes.
pub(crate) fn map(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Result<Vec<u8>> {
    pollster::block_on(crate::gpu::readback::read_buffer(device, buffer))
}

/// Renders as the command line asks when it asks for no window: `--screenshot` (after `--frames`
/// frames), `--film`, `--list-steps`.
pub fn run<L: Lesson>(args: &Args, knobs: Knobs, camera: Camera) -> Result<()> {
    check_args::<L>(args)?;

    let start = std::time::Instant::now();
    let mut request = Request {
        width: args.size.0,
        height: args.size.1,
        knobs,
        camera,
        scene: args.scene(),
        read_stencil: false,
        read_depth: false,
        stop: args.step,
        show: args.show::<L>(),
        draw: args.draw,
        backend: args.backend.clone(),
        verbose: args.verbose,
        passes: Passes::default(),
    };
    if args.list_steps {
        // The steps depend on the knobs, not on the size: list them from a small frame.
        (request.width, request.height) = (16, 16);
        let steps = Headless::<L>::new(&request)?.steps();
        return crate::app::output::say(steps::describe(&steps));
    }
    let headless = Headless::<L>::new(&request)?;
    if args.verbose {
        eprintln!("ready to render in {:.0?}", start.elapsed());
    }
    if let Some(path) = &args.screenshot {
        let frames = args.frames.unwrap_or(1);
        headless.render_frames(frames.saturating_sub(1))?;
        let drawing = std::time::Instant::now();
        let captured = headless.capture()?;
        let (drawn, saving) = (drawing.elapsed(), std::time::Instant::now());
        let startup = crate::gpu::STARTUP;
        log::info!(target: startup, "frame drawn and read back in {drawn:.0?}");
        save_png(&captured.color, path)?;
        log::info!(target: startup, "PNG encoded and written in {:.0?}", saving.elapsed());
        if args.verbose {
            eprintln!("wrote {} in {:.0?}", path.display(), start.elapsed());
        }
    }
    if let Some(pixel) = args.pixel {
        let settings = Story::settings(&request.knobs, request.camera, L::CAMERA);
        let story = headless.story(pixel, settings)?;
        crate::app::output::say(story.text())?;
        if args.verbose {
            eprintln!("told the pixel's story in {:.0?}", start.elapsed());
        }
    }
    if let Some(dir) = &args.film {
        let stills = headless.film()?;
        if args.verbose {
            eprintln!(
                "rendered {} steps in {} ms",
                stills.len(),
                start.elapsed().as_millis()
            );
        }
        save_film(&stills, &Show::FILM, dir)?;
        if args.verbose {
            let count = stills.len() * Show::FILM.len();
            eprintln!(
                "wrote {count} images into {} in {} ms",
                dir.display(),
                start.elapsed().as_millis()
            );
        }
    }
    Ok(())
}

/// Refuses options that do not go together.
fn check_args<L: Lesson>(args: &Args) -> Result<()> {
    if args.frames == Some(0) {
        bail!("--frames must be at least 1");
    }
    if args.pixel.is_some() && (args.frames.is_some() || args.step != Stop::Last) {
        bail!("--pixel tells the story of the whole frame, once: leave out --frames and --step");
    }
    if args.draw.is_some() && args.show::<L>() != Show::Tests {
        bail!("--draw picks the draw a test map shows: add --show tests");
    }
    if args.frames.is_some() && args.film.is_some() {
        bail!("--film records one frame step by step; --frames counts whole frames");
    }
    Ok(())
}

/// Writes a film into `dir` (made if missing): `NN-<step>-<show>.png` for every step and each of
/// `shows` (`--film` writes [`Show::FILM`]), encoded on all cores.
pub fn save_film(stills: &[Still], shows: &[Show], dir: &std::path::Path) -> Result<()> {
    std::fs::create_dir_all(dir)
        .with_context(|| format!("cannot write the film into `{}`", dir.display()))?;
    let files: Vec<_> = stills
        .iter()
        .enumerate()
        .flat_map(|(index, still)| {
            shows.iter().map(move |&show| {
                let path = dir.join(steps::film_file(index + 1, still.step, show));
                (still.image(show), path)
            })
        })
        .collect();
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        let workers: Vec<_> = files
            .chunks(files.len().div_ceil(threads).max(1))
            .map(|chunk| {
                scope.spawn(move || {
                    chunk
                        .iter()
                        .try_for_each(|(image, path)| save_png(image, path))
                })
            })
            .collect();
        workers
            .into_iter()
            .try_for_each(|worker| worker.join().expect("a PNG encoder panicked"))
    })
}

/// How a PNG is written: `Fast` for a learner's screenshot, whose start to PNG counts; `Small` for
/// the book's pictures, which live in git: 8-bit RGB where every pixel is opaque, zlib's best
/// compression, the same pixels. The book's 432 PNGs took 51.0 MB written `Fast`, 38.0 MB `Small`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PngSize {
    Fast,
    Small,
}

/// Writes a PNG for speed: see [`save_png_as`].
pub fn save_png(image: &image::RgbaImage, path: &std::path::Path) -> Result<()> {
    save_png_as(image, path, PngSize::Fast)
}

/// Writes a PNG, saying which file could not be written and why. The image goes to a temporary file
/// beside `path` first and is renamed into place, so an interrupted run never leaves half a PNG
/// where a good one was.
pub fn save_png_as(image: &image::RgbaImage, path: &std::path::Path, size: PngSize) -> Result<()> {
    use image::codecs::png::{CompressionType, FilterType, PngEncoder};
    let name = path.file_name().unwrap_or_default().to_string_lossy();
    let partial = path.with_file_name(format!(".{name}.partial"));
    let written = (|| {
        let file = std::fs::File::create(&partial)?;
        let mut writer = std::io::BufWriter::new(file);
        match size {
            PngSize::Fast => image.write_with_encoder(PngEncoder::new(&mut writer))?,
            PngSize::Small => {
                let opaque = image.pixels().all(|pixel| pixel[3] == 255);
                let encoder = PngEncoder::new_with_quality(
                    &mut writer,
                    CompressionType::Best,
                    FilterType::Adaptive,
                );
                if opaque {
                    let rgb = image::DynamicImage::ImageRgba8(image.clone()).to_rgb8();
                    rgb.write_with_encoder(encoder)?;
                } else {
                    image.write_with_encoder(encoder)?;
                }
            }
        }
        std::io::Write::flush(&mut writer)?;
        std::fs::rename(&partial, path)?;
        anyhow::Ok(())
    })();
    if written.is_err() {
        let _ = std::fs::remove_file(&partial);
    }
    written.with_context(|| format!("cannot write screenshot `{}`", path.display()))
}

/// Rewrites a PNG as the book keeps its pictures ([`PngSize::Small`]): the same pixels.
pub fn compact_png(path: &std::path::Path) -> Result<()> {
    let image = image::open(path).with_context(|| format!("cannot read `{}`", path.display()))?;
    save_png_as(&image.to_rgba8(), path, PngSize::Small)
}
