//! The workbench: the lesson's window with a side panel (egui) of its knobs, the frame's steps, the
//! three buffers small, what the frame costs, the camera, a screenshot button and the comparison with
//! the book. The view beside the panel is the lesson's own render at the view's size, drawn pixel
//! for pixel; with the panel hidden (`H`) the window draws as it did without one.
//!
//! [`panel`] draws the widgets and says what was asked; this module owns the GPU side (the three
//! buffers as egui textures, the step timer, egui's renderer) and carries the asks out.

pub mod panel;

use std::collections::VecDeque;
use std::sync::mpsc::{Receiver, channel};
use std::time::Instant;

use anyhow::{Context, Result};
use winit::event::WindowEvent;
use winit::window::Window;

use crate::app::args::Args;
use crate::app::runner::Runner;
use crate::book::check::{self, Verdict};
use crate::book::shots::{self, BookShot, Setting};
use crate::gpu::timing::StepTimer;
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::room::camera::{self, Camera};
use crate::room::scene::SceneOptions;
use panel::{Action, Book, Cost, Model};

/// How often the depth and stencil thumbnails follow a moving camera, in seconds.
const PICTURES_EVERY_S: f64 = 0.25;

/// What the window and the panel both change: where the frame stops and what is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Viewing {
    pub stop: Stop,
    pub show: Show,
}

/// The three buffers of the view, painted to be seen, each an egui texture.
struct Buffers {
    size: (u32, u32),
    /// Colour, depth, stencil.
    views: [wgpu::TextureView; 3],
    /// The same, as egui samples them (sRGB-encoded values, not decoded).
    encoded: [wgpu::TextureView; 3],
}

pub struct Workbench<L: Lesson> {
    pub visible: bool,
    ctx: egui::Context,
    input: egui_winit::State,
    renderer: egui_wgpu::Renderer,
    buffers: Buffers,
    ids: [egui::TextureId; 3],
    timer: Option<StepTimer>,
    cost: Option<Cost>,
    presented: VecDeque<Instant>,
    /// What the depth and stencil pictures were last painted for, and when.
    pictures_for: Option<(Knobs, Viewing, (u32, u32))>,
    pictures_at: Instant,
    adapter: String,
    poses: Vec<(String, Camera)>,
    book_shots: Vec<BookShot>,
    book_names: Vec<String>,
    book: Book,
    /// The settings the book comparison is for, and the comparison under way.
    compared: Option<Setting>,
    verdicts: Option<Receiver<Result<Verdict>>>,
    difference: Option<egui::TextureHandle>,
    show_difference: bool,
    message: Option<String>,
    scene: SceneOptions,
    backend: Option<String>,
    _lesson: std::marker::PhantomData<L>,
}

impl<L: Lesson> Workbench<L> {
    pub fn new(window: &Window, runner: &Runner<L>, args: &Args) -> Result<Self> {
        let gpu = &runner.gpu;
        let ctx = egui::Context::default();
        ctx.set_zoom_factor(args.ui_scale);
        let max_texture = gpu.max_size() as usize;
        let input = egui_winit::State::new(
            ctx.clone(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            window.theme(),
            Some(max_texture),
        );
        // No dithering: the view must show the lesson's pixels as they are.
        let options = egui_wgpu::RendererOptions {
            dithering: false,
            ..Default::default()
        };
        let mut renderer =
            egui_wgpu::Renderer::new(&gpu.device, runner.scene.color_format, options);
        let buffers = Buffers::new(gpu, runner.scene.color_format, runner.depth_stencil.size());
        let ids = buffers.encoded.each_ref().map(|view| {
            renderer.register_native_texture(&gpu.device, view, wgpu::FilterMode::Nearest)
        });
        let info = gpu.adapter.get_info();
        let book_shots = shots::of_lesson::<L>().unwrap_or_default();
        let mut poses = vec![("lesson".to_string(), L::CAMERA)];
        for (name, pose) in camera::POSES {
            if !poses.iter().any(|(_, p)| p == pose) {
                poses.push((name.to_string(), *pose));
            }
        }
        for shot in &book_shots {
            if let Ok(setting) = shot.setting::<L>(&[])
                && !poses.iter().any(|(_, p)| *p == setting.camera)
            {
                poses.push((format!("as in {}", shot.name), setting.camera));
            }
        }
        Ok(Self {
            visible: !args.no_panel,
            ctx,
            input,
            renderer,
            buffers,
            ids,
            timer: StepTimer::new(gpu),
            cost: None,
            presented: VecDeque::new(),
            pictures_for: None,
            pictures_at: Instant::now(),
            adapter: format!("{} ({:?})", info.name, info.backend),
            poses,
            book_names: book_shots.iter().map(|s| s.name.clone()).collect(),
            book_shots,
            book: Book::NoMatch,
            compared: None,
            verdicts: None,
            difference: None,
            show_difference: false,
            message: None,
            scene: args.scene(),
            backend: args.backend.clone(),
            _lesson: std::marker::PhantomData,
        })
    }

    /// Gives egui the event; returns whether egui wants it for itself (a click on the panel).
    pub fn on_event(&mut self, window: &Window, event: &WindowEvent) -> bool {
        if !self.visible {
            return false;
        }
        let response = self.input.on_window_event(window, event);
        if response.repaint {
            window.request_redraw();
        }
        match event {
            WindowEvent::MouseInput { .. } | WindowEvent::MouseWheel { .. } => {
                self.ctx.is_pointer_over_egui()
            }
            _ => false,
        }
    }

    /// Draws one frame into `target` (the window's surface texture, `size` pixels): the panel and,
    /// beside it, the lesson at the view's size. Carries out what the panel asked; returns whether
    /// anything changed (the window then draws again, for the panel to show it) and submits.
    pub fn draw(
        &mut self,
        window: &Window,
        runner: &mut Runner<L>,
        viewing: &mut Viewing,
        target: &wgpu::TextureView,
        size: (u32, u32),
    ) -> Result<bool> {
        let start = Instant::now();
        let raw_input = self.input.take_egui_input(window);
        let steps = runner.steps();
        let step = viewing.stop.resolve(&steps).unwrap_or(steps.len());
        let setting = setting(runner, *viewing);
        self.follow_book(&setting);
        let aspect = self.buffers.size.0 as f32 / self.buffers.size.1 as f32;
        let model = Model {
            title: L::TITLE,
            knob_list: L::KNOBS,
            knobs: &runner.knobs,
            steps: &steps,
            step,
            show: viewing.show,
            can_show_depth: runner.can_show(Show::Depth),
            thumbnails: Some((self.ids, aspect)),
            cost: self.cost.as_ref(),
            adapter: &self.adapter,
            camera: runner.camera,
            poses: &self.poses,
            book_shots: &self.book_names,
            book: &self.book,
            show_difference: self.show_difference,
            message: self.message.as_deref(),
        };
        let difference = self
            .difference
            .as_ref()
            .filter(|_| self.show_difference)
            .map(|d| (d.id(), d.size_vec2()));
        let mut actions = Vec::new();
        let mut view_rect = egui::Rect::NOTHING;
        let ctx = self.ctx.clone();
        let output = ctx.run_ui(raw_input, |ui| {
            actions = panel::show(ui, &model);
            view_rect = pixel_rect(ui.available_rect_before_wrap(), ui.ctx().pixels_per_point());
            let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
            let painter = ui.painter();
            if let Some((id, picture)) = difference {
                let fit = (view_rect.width() / picture.x).min(view_rect.height() / picture.y);
                let rect = egui::Rect::from_center_size(view_rect.center(), picture * fit);
                painter.image(id, rect, uv, egui::Color32::WHITE);
            }
        });
        self.input
            .handle_platform_output(window, output.platform_output);
        let changed = !actions.is_empty();
        for action in actions {
            self.act(action, runner, viewing, window)?;
        }

        // The view: the rest of the window, in whole pixels.
        let ppp = output.pixels_per_point;
        let max = runner.gpu.max_size();
        let view_size = (
            ((view_rect.width() * ppp).round() as u32).clamp(1, max),
            ((view_rect.height() * ppp).round() as u32).clamp(1, max),
        );
        if view_size != self.buffers.size {
            self.buffers = Buffers::new(&runner.gpu, runner.scene.color_format, view_size);
            for (view, id) in self.buffers.encoded.iter().zip(self.ids) {
                self.renderer.update_egui_texture_from_wgpu_texture(
                    &runner.gpu.device,
                    view,
                    wgpu::FilterMode::Nearest,
                    id,
                );
            }
            runner.resize(view_size.0, view_size.1);
        }
        let [color, depth, stencil] = &self.buffers.views;
        let raw_depth = viewing.show == Show::RawDepth;
        // The depth and stencil pictures cost a third of the frame on a software GPU (the stencil
        // one is nine full-window passes): paint them when what they show changed, when one is the
        // view, and otherwise (the camera moving) four times a second.
        let key = (runner.knobs.clone(), *viewing, view_size);
        let fresh = self.pictures_for.as_ref() != Some(&key)
            || viewing.show != Show::Color
            || self.pictures_at.elapsed().as_secs_f64() > PICTURES_EVERY_S;
        let pictures = fresh.then_some([depth, stencil]);
        let (mut encoder, steps) = runner.record_buffers(
            color,
            pictures,
            viewing.stop,
            raw_depth,
            self.timer.as_ref(),
        )?;
        if fresh {
            self.pictures_for = Some(key);
            self.pictures_at = Instant::now();
        }
        // The view, pixel for pixel, by a plain copy (through egui's shader it cost a software GPU
        // 29 ms a frame at 1280x720); then the panel over the rest.
        let viewport = [
            (view_rect.min.x * ppp).round(),
            (view_rect.min.y * ppp).round(),
            view_size.0 as f32,
            view_size.1 as f32,
        ];
        let fits = viewport[0] + viewport[2] <= size.0 as f32
            && viewport[1] + viewport[3] <= size.1 as f32;
        let shown = &self.buffers.views[match viewing.show {
            Show::Color => 0,
            Show::Depth | Show::RawDepth => 1,
            Show::Stencil => 2,
        }];
        let blit = &runner.scene.blit;
        blit.draw_in(
            &runner.gpu.device,
            &mut encoder,
            shown,
            target,
            fits.then_some(viewport),
        );
        self.paint(
            runner,
            &mut encoder,
            output.shapes,
            output.textures_delta,
            ppp,
            target,
            size,
        );
        runner.gpu.queue.submit([encoder.finish()]);
        let recorded = steps.len().min(viewing.stop.count());
        let steps_ms = match &self.timer {
            Some(timer) => Some(timer.read(&runner.gpu.device, recorded)?),
            None => {
                runner
                    .gpu
                    .device
                    .poll(wgpu::PollType::wait_indefinitely())
                    .context("waiting for the GPU failed")?;
                None
            }
        };
        self.presented.push_back(Instant::now());
        while self
            .presented
            .front()
            .is_some_and(|t| t.elapsed().as_secs_f64() > 1.0)
        {
            self.presented.pop_front();
        }
        self.cost = Some(Cost {
            steps_ms,
            frame_ms: start.elapsed().as_secs_f64() * 1000.0,
            fps: (self.presented.len() > 2).then_some(self.presented.len() as f64),
        });
        if output
            .viewport_output
            .values()
            .any(|v| v.repaint_delay.is_zero())
        {
            window.request_redraw();
        }
        Ok(changed || self.verdicts.is_some())
    }

    /// egui's textures and triangles, drawn over the whole target (the view is one of its images).
    #[allow(clippy::too_many_arguments)]
    fn paint(
        &mut self,
        runner: &Runner<L>,
        encoder: &mut wgpu::CommandEncoder,
        shapes: Vec<egui::epaint::ClippedShape>,
        mut textures: egui::TexturesDelta,
        pixels_per_point: f32,
        target: &wgpu::TextureView,
        (width, height): (u32, u32),
    ) {
        let (device, queue) = (&runner.gpu.device, &runner.gpu.queue);
        for (id, deltas) in &textures.set {
            for delta in deltas {
                self.renderer.update_texture(device, queue, *id, delta);
            }
        }
        let jobs = self.ctx.tessellate(shapes, pixels_per_point);
        let screen = egui_wgpu::ScreenDescriptor {
            size_in_pixels: [width, height],
            pixels_per_point,
        };
        let commands = self
            .renderer
            .update_buffers(device, queue, encoder, &jobs, &screen);
        queue.submit(commands);
        let mut pass = encoder
            .begin_render_pass(&wgpu::RenderPassDescriptor {
                label: Some("workbench panel"),
                color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                    view: target,
                    depth_slice: None,
                    resolve_target: None,
                    ops: wgpu::Operations {
                        load: wgpu::LoadOp::Load,
                        store: wgpu::StoreOp::Store,
                    },
                })],
                depth_stencil_attachment: None,
                timestamp_writes: None,
                occlusion_query_set: None,
                multiview_mask: None,
            })
            .forget_lifetime();
        self.renderer.render(&mut pass, &jobs, &screen);
        drop(pass);
        for id in &textures.free {
            self.renderer.free_texture(id);
        }
        // Applied: egui checks that no delta is dropped unapplied.
        textures.clear();
    }

    /// Carries out one ask of the panel.
    fn act(
        &mut self,
        action: Action,
        runner: &mut Runner<L>,
        viewing: &mut Viewing,
        window: &Window,
    ) -> Result<()> {
        match action {
            Action::Knob(index, value) => {
                let mut knobs = runner.knobs.clone();
                knobs.apply(&format!("{}={value}", L::KNOBS[index].name))?;
                set_knobs(runner, viewing, knobs)?;
            }
            Action::ResetKnobs => set_knobs(runner, viewing, Knobs::defaults(L::KNOBS))?,
            Action::Step(number) => {
                let count = runner.steps().len();
                viewing.stop = if number >= count {
                    Stop::Last
                } else {
                    Stop::After(number)
                };
            }
            Action::Show(show) => viewing.show = show,
            Action::Camera(pose) => runner.camera = pose,
            Action::PrintCamera => println!("--camera {}", runner.camera),
            Action::CopyCamera => {
                self.ctx.copy_text(format!("--camera {}", runner.camera));
                self.message = Some(format!("copied: --camera {}", runner.camera));
            }
            Action::Screenshot => self.screenshot(runner, *viewing)?,
            Action::BookShot(index) => {
                let shot = &self.book_shots[index];
                let setting = shot.setting::<L>(&[])?;
                set_knobs(runner, viewing, setting.knobs)?;
                runner.camera = setting.camera;
                *viewing = Viewing {
                    stop: setting.stop,
                    show: setting.show,
                };
            }
            Action::ShowDifference(shown) => self.show_difference = shown,
            Action::Hide => self.visible = false,
        }
        window.request_redraw();
        Ok(())
    }

    /// Writes the PNG `--screenshot` writes with the view's size and the current settings, by running
    /// the very command it prints.
    fn screenshot(&mut self, runner: &Runner<L>, viewing: Viewing) -> Result<()> {
        let path = (1..)
            .map(|n| std::path::PathBuf::from(format!("screenshot-{}-{n}.png", L::NAME)))
            .find(|p| !p.exists())
            .context("no free screenshot name")?;
        let (width, height) = self.buffers.size;
        let mut arguments = vec!["--size".to_string(), format!("{width}x{height}")];
        arguments.extend(setting(runner, viewing).arguments::<L>());
        arguments.extend(["--screenshot".to_string(), path.display().to_string()]);
        if let Some(backend) = &self.backend {
            arguments.extend(["--backend".to_string(), backend.clone()]);
        }
        let command = format!("cargo run -p {} -- {}", L::NAME, arguments.join(" "));
        let program = std::iter::once(L::NAME.to_string());
        crate::app::cli::run::<L>(program.chain(arguments).map(Into::into))?;
        println!("wrote {}: {command}", path.display());
        self.message = Some(format!("wrote {}:\n{command}", path.display()));
        Ok(())
    }

    /// Starts comparing with the book when the settings became one of its pictures; picks up a
    /// comparison that finished.
    fn follow_book(&mut self, setting: &Setting) {
        if let Some(verdicts) = &self.verdicts
            && let Ok(verdict) = verdicts.try_recv()
        {
            self.verdicts = None;
            self.book = match verdict {
                Ok(verdict) => {
                    let difference =
                        image::DynamicImage::ImageRgb8(verdict.comparison.difference.clone())
                            .to_rgba8();
                    let size = [difference.width() as usize, difference.height() as usize];
                    let picture = egui::ColorImage::from_rgba_unmultiplied(size, &difference);
                    self.difference = Some(self.ctx.load_texture(
                        "FLIP difference",
                        picture,
                        egui::TextureOptions::LINEAR,
                    ));
                    Book::Compared {
                        matches: verdict.matches(),
                        summary: verdict.comparison.summary(),
                        name: verdict.name,
                    }
                }
                Err(error) => Book::Failed(format!("{error:#}")),
            };
        }
        if self.compared.as_ref() == Some(setting) {
            return;
        }
        self.compared = Some(setting.clone());
        self.difference = None;
        let Some(shot) = check::matching::<L>(&self.book_shots, setting) else {
            self.book = Book::NoMatch;
            self.verdicts = None;
            return;
        };
        self.book = Book::Comparing(shot.name.clone());
        let (sender, receiver) = channel();
        let (setting, scene, backend) = (setting.clone(), self.scene.clone(), self.backend.clone());
        std::thread::spawn(move || {
            let verdict = check::compare::<L>(&shot, &setting, &scene, backend.as_deref());
            let _ = sender.send(verdict);
        });
        self.verdicts = Some(receiver);
    }
}

/// The settings the window is in.
fn setting<L: Lesson>(runner: &Runner<L>, viewing: Viewing) -> Setting {
    Setting {
        knobs: runner.knobs.clone(),
        camera: runner.camera,
        show: viewing.show,
        stop: viewing.stop,
    }
}

/// New knob values; a frame of fewer steps stops at its last.
pub fn set_knobs<L: Lesson>(
    runner: &mut Runner<L>,
    viewing: &mut Viewing,
    knobs: Knobs,
) -> Result<()> {
    runner.set_knobs(knobs)?;
    let count = runner.steps().len();
    if matches!(viewing.stop, Stop::After(n) if n >= count) {
        viewing.stop = Stop::Last;
    }
    Ok(())
}

/// `rect` with its corners moved to whole pixels.
fn pixel_rect(rect: egui::Rect, pixels_per_point: f32) -> egui::Rect {
    let round =
        |p: egui::Pos2| (p.to_vec2() * pixels_per_point).round().to_pos2() / pixels_per_point;
    egui::Rect::from_min_max(round(rect.min), round(rect.max))
}

impl Buffers {
    fn new(gpu: &crate::Gpu, format: wgpu::TextureFormat, size: (u32, u32)) -> Self {
        // egui samples its textures as sRGB-encoded values: it gets views of the same texels
        // without the sRGB decoding (through an sRGB view the thumbnails came out too dark).
        let encoded = format.remove_srgb_suffix();
        let texture = |label| {
            gpu.device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: size.0,
                    height: size.1,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                    | wgpu::TextureUsages::TEXTURE_BINDING,
                view_formats: &[encoded],
            })
        };
        let textures = [
            texture("workbench colour"),
            texture("workbench depth picture"),
            texture("workbench stencil picture"),
        ];
        Self {
            size,
            views: textures
                .each_ref()
                .map(|t| t.create_view(&Default::default())),
            encoded: textures.each_ref().map(|t| {
                t.create_view(&wgpu::TextureViewDescriptor {
                    label: Some("workbench picture for egui"),
                    format: Some(encoded),
                    ..Default::default()
                })
            }),
        }
    }
}
