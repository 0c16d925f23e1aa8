//! The web runner: a lesson live in its book page, drawn into the page's canvas by the same
//! [`Runner`] the window and the headless runner use, on the browser's WebGPU or, where the browser
//! has none, its WebGL2.
//!
//! The page drives it: it asks for a frame on every animation frame, passes the mouse on (drag to
//! orbit, wheel to zoom) and builds its controls from [`Page::describe`] — a select per knob, the
//! frame's steps, the buffer shown — and shows [`Page::command_line`], the native command that draws
//! the same picture. A click on the canvas asks for that pixel's story ([`Page::story`]). The bindings the page's script calls are the `web` crate's (`book/web`), which
//! maps a lesson's name to its type and calls [`start`].

use std::fmt::Write as _;
use std::pin::Pin;
use std::sync::Arc;

use anyhow::{Context, Result, anyhow, bail};
use wasm_bindgen::JsCast;
use wasm_bindgen_futures::JsFuture;

use crate::app::runner::Runner;
use crate::book::shots::Setting;
use crate::gpu::{Gpu, Picture};
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::lesson::story::Story;
use crate::room::assets::{Assets, MODEL_FILE, TEXTURE_FILES};
use crate::room::camera::Camera;
use crate::room::scene::{DEFAULT_ANISOTROPY, Scene};

/// Which of the browser's backends to draw with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Backend {
    /// WebGPU where the browser has an adapter for it, else WebGL2.
    Any,
    WebGpu,
    WebGl2,
}

impl Backend {
    /// `webgpu`, `webgl2`, or anything else for either.
    pub fn parse(name: &str) -> Self {
        match name {
            "webgpu" => Self::WebGpu,
            "webgl2" => Self::WebGl2,
            _ => Self::Any,
        }
    }

    fn backends(self) -> wgpu::Backends {
        match self {
            Self::Any => wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL,
            Self::WebGpu => wgpu::Backends::BROWSER_WEBGPU,
            Self::WebGl2 => wgpu::Backends::GL,
        }
    }
}

/// A lesson running in a page, whichever lesson it is (the page's bindings hold it as a `dyn Page`).
pub trait Page {
    /// Everything the page's controls are made from, as JSON: the lesson's name and title, its knobs
    /// (values, default, meaning, the value chosen, the values this GPU cannot draw and why), the
    /// frame's steps and the one stopped after, the buffers (and why one cannot be shown), the
    /// backend and the adapter, and the camera.
    fn describe(&self) -> String;
    /// Draws a frame into the canvas.
    fn draw(&mut self) -> Result<()>;
    /// Draws a frame and reads the canvas back in the same task, as a `data:image/png` URL (a
    /// WebGPU canvas is blank once the task that drew it has ended).
    fn capture(&mut self) -> Result<String>;
    /// The canvas's new size in pixels.
    fn resize(&mut self, width: u32, height: u32);
    /// A drag by (dx, dy) pixels, as in the window.
    fn orbit(&mut self, dx: f32, dy: f32);
    /// Wheel steps, as in the window.
    fn zoom(&mut self, steps: f32);
    /// A pose as `--camera` takes it: `YAW,PITCH,DISTANCE`.
    fn set_camera(&mut self, pose: &str) -> Result<()>;
    /// The camera back where the lesson starts.
    fn reset_camera(&mut self);
    /// `--set name=value`.
    fn set_knob(&mut self, name: &str, value: &str) -> Result<()>;
    /// `--step N` (from 1), or the whole frame with 0.
    fn set_step(&mut self, step: usize) -> Result<()>;
    /// `--show color|depth|stencil|complexity|tests`.
    fn set_show(&mut self, name: &str) -> Result<()>;
    /// `--draw N` (from 1) with `--show tests`, or every draw of the step with 0.
    fn set_draw(&mut self, draw: usize) -> Result<()>;
    /// The command that draws the canvas's picture natively: `cargo run -p … -- --size … --set …`.
    fn command_line(&self) -> String;
    /// The story of the canvas's pixel (`x`, `y`) through the whole frame, as `--pixel X,Y` tells
    /// it: read back from the GPU, so it is awaited.
    fn story(&mut self, x: u32, y: u32) -> Pin<Box<dyn Future<Output = Result<String>> + '_>>;
}

/// A lesson in a canvas.
pub struct Live<L: Lesson> {
    runner: Runner<L>,
    canvas: web_sys::HtmlCanvasElement,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// The sRGB view of the canvas's format that the lesson draws through.
    view_format: wgpu::TextureFormat,
    stop: Stop,
    show: Show,
    /// The draw a test map shows (its index in the step), or every draw of the step.
    draw: Option<usize>,
    /// Where a frame is drawn on WebGL2 before it is copied onto the canvas.
    webgl2_picture: Picture,
}

/// Starts lesson `L` in `canvas` on `backend`, its room built from the files in the folder at
/// the URL `assets` (the book's copy of `assets/`).
pub async fn start<L: Lesson>(
    canvas: web_sys::HtmlCanvasElement,
    assets: &str,
    backend: Backend,
) -> Result<Box<dyn Page>> {
    // Every file is asked for at once; the browser caches them for the next page.
    let url = |name: &str| format!("{}/{name}", assets.trim_end_matches('/'));
    let model = fetch(url(MODEL_FILE));
    let textures = TEXTURE_FILES.map(|name| fetch(url(name)));

    // Plain `Instance::new` picks WebGPU wherever `navigator.gpu` exists, even where it gives no
    // adapter; this asks for one first and falls back to WebGL2.
    let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
    descriptor.backends = backend.backends();
    let instance = wgpu::util::new_instance_with_webgpu_detection(descriptor).await;
    if !wgpu::util::is_browser_webgpu_supported().await || backend == Backend::WebGl2 {
        opaque_webgl2_context(&canvas)?;
    }
    let (width, height) = (canvas.width().max(1), canvas.height().max(1));
    let surface = instance
        .create_surface(wgpu::SurfaceTarget::Canvas(canvas.clone()))
        .map_err(|error| anyhow!("this browser cannot draw into the canvas: {error}"))?;
    let gpu = Gpu::open(instance, backend.backends(), Some(&surface), false).await?;

    let mut config = surface
        .get_default_config(&gpu.adapter, width, height)
        .context("this GPU cannot draw into the canvas")?;
    // A WebGPU canvas offers only Rgba8Unorm and Bgra8Unorm: the lesson draws through an sRGB
    // view of it, as into the window's sRGB surface.
    let view_format = config.format.add_srgb_suffix();
    if view_format != config.format {
        config.view_formats.push(view_format);
    }
    config.present_mode = wgpu::PresentMode::Fifo;
    surface.configure(&gpu.device, &config);

    let mut files = Vec::with_capacity(textures.len());
    let model = model.await?;
    for texture in textures {
        files.push(texture.await?);
    }
    let files: [Vec<u8>; 6] = files.try_into().expect("one file per texture");
    let assets = Assets::decode(MODEL_FILE, &model, &files)?;
    let scene = Scene::with_assets(&gpu, view_format, &assets, DEFAULT_ANISOTROPY);
    let knobs = Knobs::defaults(L::KNOBS);
    // The runner shares the device as the native runners do; in the page there is one thread.
    #[allow(clippy::arc_with_non_send_sync)]
    let gpu = Arc::new(gpu);
    let runner = Runner::<L>::with_scene(gpu, scene, knobs, L::CAMERA, (width, height))?;
    runner.gpu.check_errors()?;
    Ok(Box::new(Live {
        runner,
        canvas,
        surface,
        config,
        view_format,
        stop: Stop::Last,
        show: L::SHOWS,
        draw: None,
        webgl2_picture: Picture::new("WebGL2 frame", view_format),
    }))
}

/// Gives the canvas its WebGL2 context before wgpu asks for one (and gets this one): opaque, where
/// the browser's default would let the page show through wherever the lesson writes an alpha below
/// one (the mirror's 0.5), and keeping its picture after it is shown, so that it can be read back.
fn opaque_webgl2_context(canvas: &web_sys::HtmlCanvasElement) -> Result<()> {
    let options = js_sys::Object::new();
    for (name, value) in [
        ("alpha", false),
        ("antialias", false),
        ("preserveDrawingBuffer", true),
    ] {
        js_sys::Reflect::set(&options, &name.into(), &value.into())
            .map_err(|error| js_error("cannot make WebGL2's options", error))?;
    }
    canvas
        .get_context_with_context_options("webgl2", &options)
        .map_err(|error| js_error("this browser has no WebGL2", error))?
        .context("this browser has no WebGL2")?;
    Ok(())
}

/// The bytes of the file at `url`.
fn fetch(url: String) -> impl Future<Output = Result<Vec<u8>>> {
    // The request leaves now; the answer is awaited later.
    let request = web_sys::window().map(|window| window.fetch_with_str(&url));
    async move {
        let request = request.context("no window to fetch from")?;
        let response = JsFuture::from(request)
            .await
            .map_err(|error| js_error(&format!("cannot fetch {url}"), error))?;
        let response: web_sys::Response = response
            .dyn_into()
            .map_err(|error| js_error("not a response", error))?;
        if !response.ok() {
            bail!("cannot fetch {url}: HTTP {}", response.status());
        }
        let body = response
            .array_buffer()
            .map_err(|error| js_error("no body", error))?;
        let body = JsFuture::from(body)
            .await
            .map_err(|error| js_error(&format!("cannot read {url}"), error))?;
        Ok(js_sys::Uint8Array::new(&body).to_vec())
    }
}

fn js_error(what: &str, error: wasm_bindgen::JsValue) -> anyhow::Error {
    anyhow!(
        "{what}: {}",
        error.as_string().unwrap_or_else(|| format!("{error:?}"))
    )
}

impl<L: Lesson> Live<L> {
    fn backend(&self) -> &'static str {
        match self.runner.gpu.adapter.get_info().backend {
            wgpu::Backend::BrowserWebGpu => "WebGPU",
            _ => "WebGL2",
        }
    }

    /// Why this backend cannot show a buffer, where it cannot.
    fn cannot_show(&self, show: Show) -> Option<&'static str> {
        (!self.runner.can_show(show))
            .then_some("WebGL2 cannot read the depth buffer in a shader: run on WebGPU")
    }

    /// The draws of the step the frame stops after, named as a quoted JSON string each, where its
    /// test map is shown (listing them records a frame).
    fn step_draws(&self) -> Vec<String> {
        if self.show != Show::Tests {
            return Vec::new();
        }
        let steps = self.runner.steps();
        let step = self.stop.resolve(&steps).unwrap_or(steps.len());
        let (device, format) = (&self.runner.gpu.device, self.runner.scene.color_format);
        let size = self.runner.depth_stencil.size();
        let usage = wgpu::TextureUsages::empty();
        let texture = crate::gpu::target_texture(device, "draws' listing", format, size, usage);
        let draws =
            crate::app::pixel::draws(&self.runner, &texture.create_view(&Default::default()));
        draws
            .iter()
            .filter(|draw| draw.step + 1 == step)
            .enumerate()
            .map(|(index, draw)| quote(&crate::gpu::pass::draw_name(index, draw)))
            .collect()
    }

    fn setting(&self) -> Setting {
        Setting {
            knobs: self.runner.knobs.clone(),
            camera: self.runner.camera,
            show: self.show,
            stop: self.stop,
            draw: self.draw,
        }
    }

    /// The frame's steps with the current knobs; the stop moved to the last step if the knobs
    /// took the step it was on away.
    fn keep_stop_in_frame(&mut self) {
        let steps = self.runner.steps().len();
        if let Stop::After(number) = self.stop
            && number > steps
        {
            self.stop = Stop::After(steps);
        }
    }
}

impl<L: Lesson> Live<L> {
    /// Draws a frame into the canvas; says why it did not where the canvas had no texture to give.
    fn draw_frame(&mut self) -> Result<Option<&'static str>> {
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame)
            | wgpu::CurrentSurfaceTexture::Suboptimal(frame) => frame,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface
                    .configure(&self.runner.gpu.device, &self.config);
                return Ok(Some("outdated or lost"));
            }
            wgpu::CurrentSurfaceTexture::Timeout => return Ok(Some("timeout")),
            wgpu::CurrentSurfaceTexture::Occluded => return Ok(Some("occluded")),
            wgpu::CurrentSurfaceTexture::Validation => {
                self.runner.gpu.check_errors()?;
                bail!("the canvas reported a validation error");
            }
        };
        let view = frame.texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("canvas view"),
            format: Some(self.view_format),
            ..Default::default()
        });
        let size = (self.config.width, self.config.height);
        if self.runner.gpu.adapter.get_info().backend == wgpu::Backend::Gl {
            // WebGL2: the lesson draws into a texture of its own, copied onto the canvas. wgpu
            // (30.0.1) shows a WebGL2 frame by drawing it onto the canvas under the colour mask the
            // frame's last draw left — and a frame that ends marking the mirror (no colour
            // writes) would never reach the canvas. The copy's own draw writes every colour.
            let picture = self.webgl2_picture.at(&self.runner.gpu.device, size);
            self.runner
                .draw_through((&picture, size), &view, (self.stop, self.show, self.draw))?;
        } else {
            let asked = (self.stop, self.show, self.draw);
            self.runner.draw_alone(&view, size, asked)?;
        }
        self.runner.gpu.queue.present(frame);
        self.runner.gpu.check_errors()?;
        Ok(None)
    }
}

impl<L: Lesson> Page for Live<L> {
    fn describe(&self) -> String {
        let mut json = String::from("{");
        let _ = write!(
            json,
            "\"lesson\":{},\"title\":{},\"backend\":{},\"adapter\":{},\"camera\":{},",
            quote(L::NAME),
            quote(L::TITLE),
            quote(self.backend()),
            quote(&self.runner.gpu.adapter.get_info().name),
            quote(&self.runner.camera.to_string()),
        );
        json.push_str("\"knobs\":[");
        for (index, knob) in L::KNOBS.iter().enumerate() {
            if index > 0 {
                json.push(',');
            }
            let values: Vec<String> = knob.values.iter().map(|v| quote(v)).collect();
            let unavailable: Vec<String> = knob
                .values
                .iter()
                .filter_map(|value| {
                    L::unavailable(&self.runner.scene, knob.name, value)
                        .map(|why| format!("{}:{}", quote(value), quote(why)))
                })
                .collect();
            let _ = write!(
                json,
                "{{\"name\":{},\"values\":[{}],\"default\":{},\"meaning\":{},\"chosen\":{},\"unavailable\":{{{}}}}}",
                quote(knob.name),
                values.join(","),
                quote(knob.default),
                quote(knob.meaning),
                quote(self.runner.knobs.get(knob.name)),
                unavailable.join(","),
            );
        }
        let steps: Vec<String> = self.runner.steps().iter().map(|s| quote(s)).collect();
        let step = match self.stop {
            Stop::Last => 0,
            Stop::After(number) => number,
        };
        let _ = write!(json, "],\"steps\":[{}],\"step\":{step},", steps.join(","));
        let shows: Vec<String> = Show::VIEWS
            .iter()
            .map(|show| {
                let why = self.cannot_show(*show).map_or("null".to_string(), quote);
                format!("{{\"name\":{},\"unavailable\":{why}}}", quote(show.name()))
            })
            .collect();
        let _ = write!(
            json,
            "\"shows\":[{}],\"show\":{},\"draws\":[{}],\"draw\":{},\"command\":{}}}",
            shows.join(","),
            quote(self.show.name()),
            self.step_draws().join(","),
            self.draw.map_or(0, |draw| draw + 1),
            quote(&self.command_line()),
        );
        json
    }

    fn draw(&mut self) -> Result<()> {
        self.draw_frame().map(|_| ())
    }

    fn capture(&mut self) -> Result<String> {
        if let Some(skipped) = self.draw_frame()? {
            bail!("no frame to read: the canvas answered {skipped}");
        }
        self.canvas
            .to_data_url()
            .map_err(|error| js_error("cannot read the canvas", error))
    }

    fn resize(&mut self, width: u32, height: u32) {
        let (width, height) = (width.max(1), height.max(1));
        if (width, height) != (self.config.width, self.config.height) {
            self.canvas.set_width(width);
            self.canvas.set_height(height);
            self.config.width = width;
            self.config.height = height;
            self.surface
                .configure(&self.runner.gpu.device, &self.config);
        }
    }

    fn orbit(&mut self, dx: f32, dy: f32) {
        self.runner.camera.orbit(dx, dy);
    }

    fn zoom(&mut self, steps: f32) {
        self.runner.camera.zoom(steps);
    }

    fn set_camera(&mut self, pose: &str) -> Result<()> {
        self.runner.camera = Camera::parse(pose)?;
        Ok(())
    }

    fn reset_camera(&mut self) {
        self.runner.camera = L::CAMERA;
    }

    fn set_knob(&mut self, name: &str, value: &str) -> Result<()> {
        if let Some(why) = L::unavailable(&self.runner.scene, name, value) {
            bail!("{name}={value}: {why}");
        }
        let mut knobs = self.runner.knobs.clone();
        knobs.apply(&format!("{name}={value}"))?;
        self.runner.set_knobs(knobs)?;
        self.keep_stop_in_frame();
        self.runner.gpu.check_errors()
    }

    fn set_step(&mut self, step: usize) -> Result<()> {
        let stop = match step {
            0 => Stop::Last,
            number => Stop::After(number),
        };
        stop.resolve(&self.runner.steps())?;
        self.stop = stop;
        self.draw = None;
        Ok(())
    }

    fn set_draw(&mut self, draw: usize) -> Result<()> {
        self.draw = draw.checked_sub(1);
        Ok(())
    }

    fn set_show(&mut self, name: &str) -> Result<()> {
        let show = Show::VIEWS
            .into_iter()
            .find(|show| show.name() == name)
            .with_context(|| {
                format!("no view `{name}`: color, depth, stencil, complexity or tests")
            })?;
        if let Some(why) = self.cannot_show(show) {
            bail!("{why}");
        }
        self.show = show;
        Ok(())
    }

    fn command_line(&self) -> String {
        let (width, height) = (self.config.width, self.config.height);
        let mut arguments = vec!["--size".to_string(), format!("{width}x{height}")];
        arguments.extend(self.setting().arguments::<L>());
        format!("cargo run -p {} -- {}", L::NAME, arguments.join(" "))
    }

    fn story(&mut self, x: u32, y: u32) -> Pin<Box<dyn Future<Output = Result<String>> + '_>> {
        Box::pin(async move {
            let size = (self.config.width, self.config.height);
            self.runner.resize(size.0, size.1);
            let color = crate::gpu::target_texture(
                &self.runner.gpu.device,
                "a pixel's story: the frame",
                self.view_format,
                size,
                wgpu::TextureUsages::COPY_SRC,
            );
            let settings = Story::settings(&self.runner.knobs, self.runner.camera, L::CAMERA);
            let story = crate::app::pixel::tell(&self.runner, &color, (x, y), settings).await;
            self.runner.gpu.check_errors()?;
            Ok(story?.text())
        })
    }
}

/// `text` as a JSON string.
fn quote(text: &str) -> String {
    let mut quoted = String::with_capacity(text.len() + 2);
    quoted.push('"');
    for c in text.chars() {
        match c {
            '"' => quoted.push_str("\\\""),
            '\\' => quoted.push_str("\\\\"),
            '\n' => quoted.push_str("\\n"),
            c if (c as u32) < 0x20 => {
                let _ = write!(quoted, "\\u{:04x}", c as u32);
            }
            c => quoted.push(c),
        }
    }
    quoted.push('"');
    quoted
}
