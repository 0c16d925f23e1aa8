//! The window runner (winit 0.30): the lesson in a window beside the workbench's side panel (`H`
//! hides it), an orbit camera on the mouse, knobs on the number keys, the frame's steps on `[` and
//! `]`, the buffer shown on `Tab`, and all of it in the title. It survives minimising, resizing (to 1×1, or past the GPU's largest texture), and surfaces
//! that go `Outdated` or `Lost` (lesson 1's `tests/storm.rs` puts it through these on X11, where
//! a minimised window is unmapped rather than 0×0).

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
use crate::app::workbench::{self, Viewing, Workbench};
use crate::gpu::{self, Gpu};
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::Stop;
use crate::room::camera::Camera;
use crate::room::scene::SceneReading;

/// Opens the lesson in a window and runs until it is closed (or `--frames` frames were shown).
pub fn run<L: Lesson>(args: &Args, knobs: Knobs, camera: Camera) -> Result<()> {
    let mut builder = EventLoop::builder();
    // X11 and Wayland serve a window from any thread: tests open lessons' windows from theirs.
    #[cfg(all(unix, not(target_vendor = "apple")))]
    {
        winit::platform::x11::EventLoopBuilderExtX11::with_any_thread(&mut builder, true);
        winit::platform::wayland::EventLoopBuilderExtWayland::with_any_thread(&mut builder, true);
    }
    let event_loop = builder.build().map_err(|error| {
        // winit says e.g. "os error at <file>:<line>: neither WAYLAND_DISPLAY nor ... is set."
        let text = error.to_string();
        let reason = text.rsplit(": ").next().unwrap_or(&text).trim().trim_end_matches('.');
        anyhow!("cannot open a window: no display ({reason}); render without one with --screenshot out.png")
    })?;
    let mut app = App::<L> {
        args,
        // Read while the window and the GPU open.
        scene: Some(args.scene().start_reading()),
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
    scene: Option<SceneReading>,
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
    viewing: Viewing,
    workbench: Workbench<L>,
    /// The window's events, as egui takes them.
    panel_input: egui_winit::State,
    drag_from: Option<PhysicalPosition<f64>>,
    cursor: PhysicalPosition<f64>,
    modifiers: ModifiersState,
    /// Test hook: surface answers still to pretend, last first (see [`injected_surface_errors`]).
    injected: Vec<&'static str>,
}

impl<L: Lesson> App<'_, L> {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: anyhow::Error) {
        self.error.get_or_insert(error);
        event_loop.exit();
    }

    /// Draws a frame and counts it; with `--frames`, asks for the next until there are that many.
    fn redraw_requested(&mut self, event_loop: &ActiveEventLoop) -> Result<()> {
        let Some(state) = self.state.as_mut() else {
            return Ok(());
        };
        if state.redraw()? {
            self.frames += 1;
            // `RUST_LOG=workbook::frames=debug` lists the frames: a test checks that
            // an idle window draws none.
            log::debug!(target: "workbook::frames", "frame {} drawn", self.frames);
        }
        match self.args.frames {
            Some(limit) if self.frames >= limit => event_loop.exit(),
            // Counting frames: keep drawing.
            Some(_) => state.window.request_redraw(),
            None => {}
        }
        Ok(())
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
        // The workbench copies its panel's picture into the frame where it may.
        if caps.usages.contains(wgpu::TextureUsages::COPY_DST) {
            config.usage |= wgpu::TextureUsages::COPY_DST;
        }
        check_size(&gpu, config.width, config.height)?;
        surface.configure(&gpu.device, &config);
        let knobs = self.knobs.take().context("the window was opened twice")?;
        let scene = self.scene.take().context("the window was opened twice")?;
        let runner = Runner::new(
            std::sync::Arc::new(gpu),
            config.format,
            scene,
            knobs,
            self.camera,
            (config.width, config.height),
        )?;
        let (stop, show) = (self.args.step, self.args.show::<L>());
        stop.resolve(&runner.steps())?;
        if !runner.can_show(show) {
            anyhow::bail!(crate::gpu::views::DepthViewPipelines::UNSUPPORTED);
        }
        let workbench = Workbench::new(&runner, self.args)?;
        let panel_input = egui_winit::State::new(
            workbench.context().clone(),
            egui::ViewportId::ROOT,
            &window,
            Some(window.scale_factor() as f32),
            window.theme(),
            Some(runner.gpu.max_size() as usize),
        );
        let state = State {
            window,
            surface,
            config,
            runner,
            viewing: Viewing {
                stop,
                show,
                draw: self.args.draw,
            },
            workbench,
            panel_input,
            drag_from: None,
            cursor: PhysicalPosition::new(0.0, 0.0),
            modifiers: ModifiersState::empty(),
            injected: injected_surface_errors()?,
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

/// The surface answers `WORKBOOK_INJECT_SURFACE_ERRORS` asks for, a test hook: with
/// `WORKBOOK_INJECT_SURFACE_ERRORS=lost,outdated,timeout,suboptimal` the first frames'
/// `get_current_texture` answers those, one each, in order, so that tests can check the runner
/// recovers from answers a real surface seldom gives (`tests/storm.rs` in lesson 1). Read once, when
/// the window opens: unset, the list is empty and the runner asks the surface as always. Returned
/// last first, to be popped.
fn injected_surface_errors() -> Result<Vec<&'static str>> {
    const VARIABLE: &str = "WORKBOOK_INJECT_SURFACE_ERRORS";
    let Some(list) = std::env::var_os(VARIABLE) else {
        return Ok(Vec::new());
    };
    let list = list.to_string_lossy();
    let names = list
        .split(',')
        .map(str::trim)
        .filter(|name| !name.is_empty());
    let known = ["lost", "outdated", "timeout", "suboptimal"];
    let mut injected = names
        .map(|name| {
            known.into_iter().find(|k| *k == name).with_context(|| {
                format!(
                    "{VARIABLE}: unknown surface answer `{name}` (use {})",
                    known.join(", ")
                )
            })
        })
        .collect::<Result<Vec<_>>>()?;
    injected.reverse();
    Ok(injected)
}

/// One pretended answer of `get_current_texture` (see [`injected_surface_errors`]); `suboptimal`
/// wraps a real frame. Says so on stdout, for the test to see it happened.
fn inject(name: &str, surface: &wgpu::Surface<'_>) -> wgpu::CurrentSurfaceTexture {
    println!("injected surface answer: {name}");
    match name {
        "lost" => wgpu::CurrentSurfaceTexture::Lost,
        "outdated" => wgpu::CurrentSurfaceTexture::Outdated,
        "timeout" => wgpu::CurrentSurfaceTexture::Timeout,
        _ => match surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(frame) => {
                wgpu::CurrentSurfaceTexture::Suboptimal(frame)
            }
            other => other,
        },
    }
}

impl<L: Lesson> State<L> {
    fn update_title(&self) {
        let steps = self.runner.steps();
        let number = self.viewing.stop.resolve(&steps).unwrap_or(steps.len());
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
            self.viewing.show.name(),
            knobs.join(" "),
            self.runner.camera
        ));
    }

    fn resize(&mut self, size: PhysicalSize<u32>) {
        // A minimised window is 0×0: keep the old surface until it comes back.
        if size.width == 0 || size.height == 0 {
            return;
        }
        // A window larger than the GPU's textures may be (16384 pixels a side on llvmpipe, 8192 on
        // many GPUs: a window stretched across monitors) failed validation and ended the lesson.
        // Draw at the largest size allowed instead; the window shows it in part, or scaled.
        let max = self.runner.gpu.max_size();
        let (width, height) = (size.width.min(max), size.height.min(max));
        self.config.width = width;
        self.config.height = height;
        self.surface
            .configure(&self.runner.gpu.device, &self.config);
        if !self.workbench.visible {
            self.runner.resize(width, height);
        }
    }

    /// Draws one frame; returns whether one was shown.
    fn redraw(&mut self) -> Result<bool> {
        let size = self.window.inner_size();
        if size.width == 0 || size.height == 0 {
            return Ok(false);
        }
        let Some((frame, suboptimal)) = self.next_frame(size)? else {
            return Ok(false);
        };
        let again = self.draw_frame(&frame)?;
        self.window.pre_present_notify();
        self.runner.gpu.queue.present(frame);
        self.runner.gpu.check_errors()?;
        if suboptimal {
            self.resize(size);
        }
        if again {
            // The panel changed something: draw again, for the panel to show it.
            self.update_title();
            self.window.request_redraw();
        }
        Ok(true)
    }

    /// The surface's next frame, and whether the surface is suboptimal (to be configured again once
    /// the frame is shown); none when the surface has no frame to give this time.
    fn next_frame(
        &mut self,
        size: PhysicalSize<u32>,
    ) -> Result<Option<(wgpu::SurfaceTexture, bool)>> {
        let current = match self.injected.pop() {
            None => self.surface.get_current_texture(),
            Some(name) => inject(name, &self.surface),
        };
        // Without `--frames` the window draws only when something changes: after an answer that
        // is no frame but is recovered from at once (timeout, outdated, lost), ask for the frame
        // again, or the window stays blank (or stale) until the mouse moves. Not when occluded:
        // that would spin while the window is hidden.
        match current {
            wgpu::CurrentSurfaceTexture::Success(frame) => Ok(Some((frame, false))),
            // Still a frame: show it, then configure again for the next. (Dropping it showed
            // nothing while a surface stayed suboptimal, and `--frames` never ended.)
            wgpu::CurrentSurfaceTexture::Suboptimal(frame) => Ok(Some((frame, true))),
            wgpu::CurrentSurfaceTexture::Occluded => Ok(None),
            wgpu::CurrentSurfaceTexture::Timeout => {
                self.window.request_redraw();
                Ok(None)
            }
            wgpu::CurrentSurfaceTexture::Outdated => {
                self.resize(size);
                self.window.request_redraw();
                Ok(None)
            }
            wgpu::CurrentSurfaceTexture::Lost => {
                self.surface = self
                    .runner
                    .gpu
                    .instance
                    .create_surface(self.window.clone())
                    .context("the window's surface was lost and cannot be made again")?;
                self.resize(size);
                self.window.request_redraw();
                Ok(None)
            }
            wgpu::CurrentSurfaceTexture::Validation => {
                self.runner.gpu.check_errors()?;
                Err(anyhow!("the window's surface reported a validation error"))
            }
        }
    }

    /// Draws into the surface's `frame`: the lesson beside the workbench's panel, or alone. Returns
    /// whether the panel changed something (to be drawn again).
    fn draw_frame(&mut self, frame: &wgpu::SurfaceTexture) -> Result<bool> {
        let view = frame.texture.create_view(&wgpu::TextureViewDescriptor {
            label: Some("window frame view"),
            ..Default::default()
        });
        let mut again = false;
        if self.workbench.visible {
            let (runner, viewing) = (&mut self.runner, &mut self.viewing);
            let input = self.panel_input.take_egui_input(&self.window);
            let drawn = self
                .workbench
                .draw(input, runner, viewing, &frame.texture)?;
            self.panel_input
                .handle_platform_output(&self.window, drawn.platform);
            if drawn.repaint_now {
                self.window.request_redraw();
            }
            again = drawn.again;
        } else {
            // The lesson alone, straight into the window, as the headless runner draws it (or at
            // half resolution, scaled up).
            let size = (self.config.width, self.config.height);
            let (runner, viewing) = (&mut self.runner, self.viewing);
            self.workbench.draw_alone(runner, viewing, &view, size)?;
        }
        Ok(again)
    }

    /// Gives the panel the event; returns whether the panel takes it for itself (a click or a wheel
    /// over the panel).
    fn panel_event(&mut self, event: &WindowEvent) -> bool {
        // egui asks for a frame after each frame drawn (it takes RedrawRequested for input):
        // the window would never rest.
        if !self.workbench.visible || matches!(event, WindowEvent::RedrawRequested) {
            return false;
        }
        let response = self.panel_input.on_window_event(&self.window, event);
        if response.repaint {
            self.window.request_redraw();
        }
        match event {
            WindowEvent::MouseInput { .. } | WindowEvent::MouseWheel { .. } => {
                self.workbench.context().is_pointer_over_egui()
            }
            _ => false,
        }
    }

    /// Every event but a redraw: the keys, the camera on the mouse, a resize, closing. Returns
    /// whether anything changed (the title and the frame to be drawn again).
    fn on_event(
        &mut self,
        event_loop: &ActiveEventLoop,
        event: WindowEvent,
        over_panel: bool,
    ) -> Result<bool> {
        match event {
            WindowEvent::CloseRequested => event_loop.exit(),
            WindowEvent::Resized(size) => {
                self.resize(size);
                return Ok(true);
            }
            WindowEvent::ModifiersChanged(modifiers) => self.modifiers = modifiers.state(),
            // Not the presses winit makes up for keys held as the window gains focus: a key
            // pressed just as the window got focus came twice (`H` hid the panel and showed it
            // again at once).
            WindowEvent::KeyboardInput {
                event,
                is_synthetic: false,
                ..
            } if event.state == ElementState::Pressed => {
                if event.logical_key == Key::Named(NamedKey::Escape) {
                    event_loop.exit();
                }
                return self.key(&event);
            }
            WindowEvent::MouseInput { .. } | WindowEvent::MouseWheel { .. } if over_panel => {}
            WindowEvent::MouseInput {
                state: button_state,
                button: MouseButton::Left,
                ..
            } => {
                self.drag_from = (button_state == ElementState::Pressed).then_some(self.cursor);
            }
            // A right-click on the view picks the pixel whose story the panel tells.
            WindowEvent::MouseInput {
                state: ElementState::Pressed,
                button: MouseButton::Right,
                ..
            } if self.workbench.visible => {
                return Ok(self.workbench.pick((self.cursor.x, self.cursor.y)));
            }
            WindowEvent::CursorMoved { position, .. } => {
                self.cursor = position;
                if let Some(from) = self.drag_from {
                    let (dx, dy) = (position.x - from.x, position.y - from.y);
                    self.runner.camera.orbit(dx as f32, dy as f32);
                    self.drag_from = Some(position);
                    return Ok(true);
                }
            }
            WindowEvent::MouseWheel { delta, .. } => {
                let steps = match delta {
                    MouseScrollDelta::LineDelta(_, y) => y,
                    MouseScrollDelta::PixelDelta(p) => p.y as f32 / 40.0,
                };
                self.runner.camera.zoom(steps);
                return Ok(true);
            }
            _ => {}
        }
        Ok(false)
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
                // Other knobs may make a frame of fewer steps.
                workbench::set_knobs(&mut self.runner, &mut self.viewing, knobs)?;
                return Ok(true);
            }
        }
        if code == BracketLeft || code == BracketRight {
            let count = self.runner.steps().len();
            let number = self
                .viewing
                .stop
                .resolve(&self.runner.steps())
                .unwrap_or(count);
            let number = match code {
                BracketLeft => number.saturating_sub(1).max(1),
                _ => (number + 1).min(count),
            };
            self.viewing.stop = if number == count {
                Stop::Last
            } else {
                Stop::After(number)
            };
            return Ok(true);
        }
        if code == Tab {
            let viewing = &mut self.viewing;
            viewing.show = viewing.show.next();
            if !self.runner.can_show(viewing.show) {
                viewing.show = viewing.show.next();
            }
            return Ok(true);
        }
        if code == KeyH {
            self.workbench.visible = !self.workbench.visible;
            return Ok(true);
        }
        if code == KeyR {
            let half = !self.workbench.half_resolution;
            self.workbench.set_half_resolution(half);
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
        // The panel sees every event first; a click or a wheel over it is not the camera's.
        let over_panel = state.panel_event(&event);
        let result = match event {
            WindowEvent::RedrawRequested => self.redraw_requested(event_loop).map(|()| false),
            event => state.on_event(event_loop, event, over_panel),
        };
        let changed = match result {
            Ok(changed) => changed,
            Err(error) => {
                self.fail(event_loop, error);
                return;
            }
        };
        if let (true, Some(state)) = (changed, self.state.as_ref()) {
            state.update_title();
            state.window.request_redraw();
        }
    }
}
