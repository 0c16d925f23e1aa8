//! The window runner (winit 0.30): the lesson in a window, an orbit camera on the mouse, knobs on the
//! number keys, the frame's steps on `[` and `]`, the buffer shown on `Tab`, and all of it in the
//! title. It survives minimising, resizing, and surfaces that go `Outdated` or `Lost`.

use std::sync::Arc;

use anyhow::{Context, Result, anyhow};
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, KeyEvent, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::keyboard::{Key, ModifiersState, NamedKey, PhysicalKey};
use winit::window::{Window, WindowId};

use crate::app::args::Args;
use crate::app::headless::check_size;
use crate::app::runner::Runner;
use crate::gpu::{self, Gpu};
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::room::camera::Camera;

/// Opens the lesson in a window and runs until it is closed (or `--frames` frames were shown).
pub fn run<L: Lesson>(args: &Args, knobs: Knobs, camera: Camera) -> Result<()> {
    let event_loop = EventLoop::new().map_err(|error| {
        // winit says e.g. "os error at <file>:<line>: neither WAYLAND_DISPLAY nor ... is set."
        let text = error.to_string();
        let reason = text.rsplit(": ").next().unwrap_or(&text).trim().trim_end_matches('.');
        anyhow!("cannot open a window: no display ({reason}); render without one with --screenshot out.png")
    })?;
    let mut app = App::<L> {
        args,
        knobs: Some(knobs),
        camera,
        backends: gpu::backend_choices(args.backend.as_deref())?,
        state: None,
        error: None,
        frames: 0,
    };
    event_loop
        .run_app(&mut app)
        .context("the window's event loop failed")?;
    match app.error {
        Some(error) => Err(error),
        None => Ok(()),
    }
}

struct App<'a, L: Lesson> {
    args: &'a Args,
    knobs: Option<Knobs>,
    camera: Camera,
    backends: Vec<wgpu::Backends>,
    state: Option<State<L>>,
    error: Option<anyhow::Error>,
    frames: u64,
}

struct State<L: Lesson> {
    window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    runner: Runner<L>,
    /// The step the frame stops after, and the buffer shown.
    stop: Stop,
    show: Show,
    drag_from: Option<PhysicalPosition<f64>>,
    cursor: PhysicalPosition<f64>,
    modifiers: ModifiersState,
}

impl<L: Lesson> App<'_, L> {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        self.error.get_or_insert(error);
        event_loop.exit();
    }

    fn open(&mut self, event_loop: &ActiveEventLoop) -> Result<State<L>> {
        let (width, height) = self.args.size;
        let attributes = Window::default_attributes()
            .with_title(L::TITLE)
            .with_inner_size(PhysicalSize::new(width, height));
        let window = Arc::new(
            event_loop
                .create_window(attributes)
                .context("cannot open a window")?,
        );
        let (gpu, surface) = self.connect(event_loop, &window)?;
        let size = window.inner_size();
        let mut config = surface
            .get_default_config(&gpu.adapter, size.width.max(1), size.height.max(1))
            .context("the GPU cannot draw into this window")?;
        let caps = surface.get_capabilities(&gpu.adapter);
        if let Some(srgb) = caps.formats.iter().find(|f| f.is_srgb()) {
            config.format = *srgb;
        }
        config.present_mode = wgpu::PresentMode::AutoVsync;
        check_size(&gpu, config.width, config.height)?;
        surface.configure(&gpu.device, &config);
        let knobs = self.knobs.take().context("the window was opened twice")?;
        let runner = Runner::new(
            std::sync::Arc::new(gpu),
            config.format,
            &self.args.scene(),
            knobs,
            self.camera,
            (config.width, config.height),
        )?;
        let (stop, show) = (self.args.step, self.args.show::<L>());
        stop.resolve(&runner.steps())?;
        if !runner.can_show(show) {
            anyhow::bail!(crate::gpu::views::DepthViewPipelines::UNSUPPORTED);
        }
        let state = State {
            window,
            surface,
            config,
            runner,
            stop,
            show,
            drag_from: None,
            cursor: PhysicalPosition::new(0.0, 0.0),
            modifiers: ModifiersState::empty(),
        };
        state.update_title();
        Ok(state)
    }
}

impl<L: Lesson> App<'_, L> {
    /// A device that can present to the window, from the first backend choice that has one.
    fn connect(
        &self,
        event_loop: &ActiveEventLoop,
        window: &Arc<Window>,
    ) -> Result<(Gpu, wgpu::Surface<'static>)> {
        let mut failure = anyhow!("no backend to try");
        for &backends in &self.backends {
            let display = Box::new(event_loop.owned_display_handle());
            let instance = gpu::instance(backends, Some(display));
            let surface = instance
                .create_surface(window.clone())
                .context("cannot draw into the window")?;
            match Gpu::new(instance, backends, Some(&surface), self.args.verbose) {
                Ok(gpu) => return Ok((gpu, surface)),
                Err(error) => failure = error,
            }
        }
        Err(failure)
    }
}

impl<L: Lesson> State<L> {
    fn update_title(&self) {
        let steps = self.runner.steps();
        let number = self.stop.resolve(&steps).unwrap_or(steps.len());
        let step = steps.get(number.wrapping_sub(1)).unwrap_or(&"");
        let knobs: Vec<String> = self
            .runner
            .knobs
            .pairs()
            .enumerate()
            .map(|(i, (name, value))| format!("[{}] {name}={value}", i + 1))
            .collect();
        self.window.set_title(&format!(
            "{} — step {number}/{}: {step} — showing {} — {} — camera {}",
            L::NAME,
            steps.len(),
            self.show.name(),
            knobs.join(" "),
            self.runner.camera
        ));
    }

    fn resize(&mut self, size: PhysicalSize<u32>) {
        // A minimised window is 0×0: keep the old surface until it comes back.
        if size.width == 0 || size.height == 0 {
            return;
        }
        self.config.width = size.width;
        self.config.height = size.height;
        self.surface
            .configure(&self.runner.gpu.device, &self.config);
        self.runner.resize(size.width, size.height);
    }

    /// Draws one frame; returns whether one was shown.
    fn redraw(&mut self) -> Result<bool> {
        let size = self.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return Ok(false);
        }
        let frame = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame) => frame,
            wgpu::CurrentSurfaceTexture::Suboptimal(frame) => {
                // Show this one, then configure again for the next.
                drop(frame);
                self.resize(size);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Outdated => {
                self.resize(size);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Lost => {
                self.surface = self
                    .runner
                    .gpu
                    .instance
                    .create_surface(self.window.clone())
                    .context("the window's surface was lost and cannot be made again")?;
                self.resize(size);
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Validation => {
                self.runner.gpu.check_errors()?;
                return Err(anyhow!("the window's surface reported a validation error"));
            }
        };
        let view = frame.texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("window frame view"),
            ..Default::default()
        });
        let (encoder, _) = self.runner.record(&view, self.stop, self.show, &view)?;
        self.runner.gpu.queue.submit([encoder.finish()]);
        self.window.pre_present_notify();
        self.runner.gpu.queue.present(frame);
        self.runner.gpu.check_errors()?;
        Ok(true)
    }

    /// Number keys cycle the knobs; returns whether anything changed.
    fn key(&mut self, event: &KeyEvent) -> Result<bool> {
        let PhysicalKey::Code(code) = event.physical_key else {
            return Ok(false);
        };
        use winit::keyboard::KeyCode::*;
        let digits = [
            Digit1, Digit2, Digit3, Digit4, Digit5, Digit6, Digit7, Digit8, Digit9,
        ];
        if let Some(index) = digits.iter().position(|d| *d == code) {
            let mut knobs = self.runner.knobs.clone();
            if knobs.cycle(index, !self.modifiers.shift_key()) {
                self.runner.set_knobs(knobs)?;
                // Other knobs may make a frame of fewer steps.
                let count = self.runner.steps().len();
                if matches!(self.stop, Stop::After(n) if n >= count) {
                    self.stop = Stop::Last;
                }
                return Ok(true);
            }
        }
        if code == BracketLeft || code == BracketRight {
            let count = self.runner.steps().len();
            let number = self.stop.resolve(&self.runner.steps()).unwrap_or(count);
            let number = match code {
                BracketLeft => number.saturating_sub(1).max(1),
                _ => (number + 1).min(count),
            };
            self.stop = if number == count {
                Stop::Last
            } else {
                Stop::After(number)
            };
            return Ok(true);
        }
        if code == Tab {
            self.show = self.show.next();
            if !self.runner.can_show(self.show) {
                self.show = self.show.next();
            }
            return Ok(true);
        }
        if code == KeyC {
            println!("--camera {}", self.runner.camera);
        }
        Ok(false)
    }
}

impl<L: Lesson> ApplicationHandler for App<'_, L> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.state.is_some() || self.error.is_some() {
            return;
        }
        match self.open(event_loop) {
            Ok(state) => {
                state.window.request_redraw();
                self.state = Some(state);
            }
            Err(error) => self.fail(event_loop, error),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _: WindowId, event: WindowEvent) {
        let Some(state) = self.state.as_mut() else {
            return;
        };
        let mut changed = false;
        let result: Result<()> = (|| {
            match event {
                WindowEvent::CloseRequested => event_loop.exit(),
                WindowEvent::Resized(size) => {
                    state.resize(size);
                    changed = true;
                }
                WindowEvent::RedrawRequested => {
                    if state.redraw()? {
                        self.frames += 1;
                    }
                    match self.args.frames {
                        Some(limit) if self.frames >= limit => event_loop.exit(),
                        // Counting frames: keep drawing.
                        Some(_) => state.window.request_redraw(),
                        None => {}
                    }
                }
                WindowEvent::ModifiersChanged(modifiers) => state.modifiers = modifiers.state(),
                WindowEvent::KeyboardInput { event, .. }
                    if event.state == ElementState::Pressed =>
                {
                    if event.logical_key == Key::Named(NamedKey::Escape) {
                        event_loop.exit();
                    }
                    changed = state.key(&event)?;
                }
                WindowEvent::MouseInput {
                    state: button_state,
                    button: MouseButton::Left,
                    ..
                } => {
                    state.drag_from =
                        (button_state == ElementState::Pressed).then_some(state.cursor);
                }
                WindowEvent::CursorMoved { position, .. } => {
                    state.cursor = position;
                    if let Some(from) = state.drag_from {
                        let (dx, dy) = (position.x - from.x, position.y - from.y);
                        state.runner.camera.orbit(dx as f32, dy as f32);
                        state.drag_from = Some(position);
                        changed = true;
                    }
                }
                WindowEvent::MouseWheel { delta, .. } => {
                    let steps = match delta {
                        MouseScrollDelta::LineDelta(_, y) => y,
                        MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                    };
                    state.runner.camera.zoom(steps);
                    changed = true;
                }
                _ => {}
            }
            Ok(())
        })();
        if let Err(error) = result {
            self.fail(event_loop, error);
        } else if changed {
            state.update_title();
            state.window.request_redraw();
        }
    }
}
