//! The workbench: the lesson's window with a side panel (egui) of its knobs, the frame's steps, the
//! three buffers small, what the frame costs, the camera, a screenshot button and the comparison with
//! the book. The view beside the panel is the lesson's own render at the view's size, drawn pixel
//! for pixel; with the panel hidden (`H`) the window draws as it did without one.
//!
//! [`panel`] draws the widgets and says what was asked; this module owns the GPU side (the three
//! buffers as egui textures, the step timer, egui's renderer) and carries the asks out.

pub mod headless;
pub mod panel;

use std::collections::VecDeque;
use std::sync::mpsc::{Receiver, channel};
use std::time::Instant;

use anyhow::{Context, Result};

use crate::app::args::Args;
use crate::app::runner::Runner;
use crate::book::check::{self, Verdict};
use crate::book::shots::{self, BookShot, Setting};
use crate::gpu::Picture;
use crate::gpu::timing::LateTimer;
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::lesson::story::Story;
use crate::room::camera::{self, Camera};
use crate::room::scene::SceneOptions;
use panel::{Action, Book, Cost, Model, Picked};

/// The frame time and rate are over the frames of the last this many seconds; fewer than three
/// frames in it, and the window draws only on change.
const CONTINUOUS_S: f64 = 1.5;

/// How often the depth and stencil thumbnails follow a moving camera, in seconds.
const PICTURES_EVERY_S: f64 = 0.5;

/// What the window and the panel both change: where the frame stops and what is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Viewing {
    pub stop: Stop,
    pub show: Show,
}

/// The three buffers of the view, painted to be seen, each an egui texture.
struct Buffers {
    size: (u32, u32),
    /// Colour, depth, stencil pictures (copied into the window, and a pixel's story reads the
    /// colours through the first).
    textures: [wgpu::Texture; 3],
    /// Views of the same.
    views: [wgpu::TextureView; 3],
    /// The same, as egui samples them (sRGB-encoded values, not decoded).
    encoded: [wgpu::TextureView; 3],
}

pub struct Workbench<L: Lesson> {
    pub visible: bool,
    ctx: egui::Context,
    renderer: egui_wgpu::Renderer,
    buffers: Buffers,
    ids: [egui::TextureId; 3],
    timer: Option<LateTimer>,
    cost: Option<Cost>,
    /// The cost as the panel shows it: the latest, twice a second.
    shown_cost: Option<Cost>,
    /// The camera as the panel shows it: while the view is dragged, twice a second.
    shown_camera: Option<Camera>,
    /// The panel as last painted (see `draw`).
    panel_picture: Option<PanelPicture>,
    /// The panel as egui last laid it out (see `draw`).
    laid_out: Option<LaidOut>,
    /// How many frames egui laid the panel out in (the others were idle).
    pub layouts: u64,
    presented: VecDeque<Instant>,
    /// The frame's step names as the last frame recorded them, and what for.
    steps: Option<((Knobs, Camera), Vec<&'static str>)>,
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
    /// The pixel picked in the view (a right-click), and its story with what it was told for.
    picked: Option<(u32, u32)>,
    story: Option<(StoryFor, Result<Story, String>)>,
    story_at: Instant,
    /// Whether the lesson is drawn at half the view's resolution and scaled up (a software GPU's
    /// window, see `--resolution`).
    pub half_resolution: bool,
    /// Whether the adapter is a CPU's (the panel then says how many pixels it draws).
    software_gpu: bool,
    /// Where the lesson draws at half resolution while the panel is hidden.
    half_picture: Picture,
    _lesson: std::marker::PhantomData<L>,
}

/// What a pixel's story depends on: the knobs, the camera, the view's size and the pixel.
type StoryFor = (Knobs, Camera, (u32, u32), (u32, u32));

/// What one frame of the workbench asks of whoever shows it.
pub struct Drawn {
    /// Something changed (a knob, a step, a comparison under way): draw again, for the panel to
    /// show it.
    pub again: bool,
    /// egui asks for the next frame now (an animation, a tooltip).
    pub repaint_now: bool,
    /// What egui asks of the platform: the clipboard, the cursor.
    pub platform: egui::PlatformOutput,
}

impl<L: Lesson> Workbench<L> {
    /// A workbench for `runner`; it draws into any target, a window's or a texture.
    pub fn new(runner: &Runner<L>, args: &Args) -> Result<Self> {
        let gpu = &runner.gpu;
        let ctx = egui::Context::default();
        ctx.set_zoom_factor(args.ui_scale);
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
            renderer,
            buffers,
            ids,
            timer: LateTimer::new(gpu),
            cost: None,
            shown_cost: None,
            shown_camera: None,
            panel_picture: None,
            laid_out: None,
            layouts: 0,
            presented: VecDeque::new(),
            steps: None,
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
            picked: None,
            story: None,
            story_at: Instant::now(),
            // A software GPU's window draws at half resolution unless told otherwise.
            half_resolution: args.resolution.half(&info),
            software_gpu: info.device_type == wgpu::DeviceType::Cpu,
            half_picture: Picture::new("half-resolution frame", runner.scene.color_format),
            _lesson: std::marker::PhantomData,
        })
    }

    /// What the panel's cost section shows: the last frame's.
    pub fn cost(&self) -> Option<&Cost> {
        self.cost.as_ref()
    }

    /// Whether a comparison with the book is under way (on a thread of its own).
    pub fn comparing(&self) -> bool {
        self.verdicts.is_some()
    }

    /// The egui context, for the window's input to feed.
    /// Picks the view's pixel under `cursor` (in the window's pixels) for the panel to tell its
    /// story; returns whether the cursor was over the view.
    pub fn pick(&mut self, (x, y): (f64, f64)) -> bool {
        let Some(laid_out) = &self.laid_out else {
            return false;
        };
        let ppp = laid_out.pixels_per_point as f64;
        let (left, top) = (
            laid_out.view_rect.min.x as f64 * ppp,
            laid_out.view_rect.min.y as f64 * ppp,
        );
        // The picked pixel is one of the lesson's: at half resolution, one of four of the view's.
        let scale = self.scale() as f64;
        let (px, py) = (((x - left) / scale).floor(), ((y - top) / scale).floor());
        let (width, height) = self.buffers.size;
        if px < 0.0 || py < 0.0 || px >= width as f64 || py >= height as f64 {
            return false;
        }
        self.picked = Some((px as u32, py as u32));
        true
    }

    /// Tells the picked pixel's story again where what it depends on changed: at once for a new
    /// pixel, knobs or size, at most twice a second while the camera moves (a story records the
    /// frame once per draw that reaches the pixel: a software GPU takes a good part of a second).
    /// Before the frame is recorded: the story's frames draw into the view's buffers.
    fn tell_story(&mut self, runner: &Runner<L>) {
        let Some(pixel) = self.picked else {
            self.story = None;
            return;
        };
        let size = self.buffers.size;
        let key: StoryFor = (runner.knobs.clone(), runner.camera, size, pixel);
        let Some((told, _)) = &self.story else {
            return self.tell(runner, key);
        };
        if *told == key {
            return;
        }
        let moving_only = (&told.0, told.2, told.3) == (&key.0, key.2, key.3);
        if !moving_only || self.story_at.elapsed().as_secs_f64() > PICTURES_EVERY_S {
            self.tell(runner, key);
        }
    }

    fn tell(&mut self, runner: &Runner<L>, key: StoryFor) {
        let (_, _, size, pixel) = key;
        // The runner draws at the view's size once the view has been drawn at it.
        if runner.depth_stencil.size() != size {
            return;
        }
        let settings = runner.knobs.changed();
        let story = crate::app::pixel::story(runner, &self.buffers.textures[0], pixel, settings);
        self.story = Some((key, story.map_err(|error| format!("{error:#}"))));
        self.story_at = Instant::now();
    }

    /// The picked pixel's story as the panel shows it, once told (or why it could not be).
    pub fn story(&self) -> Option<&Result<Story, String>> {
        self.story.as_ref().map(|(_, story)| story)
    }

    /// The size the lesson is drawn at beside the panel, in pixels: the view's, or at half
    /// resolution half of it.
    pub fn view_size(&self) -> (u32, u32) {
        self.buffers.size
    }

    /// Draws the lesson alone into `target` (`size` pixels), with the panel hidden: straight into
    /// it, as the headless runner draws, or at half resolution and scaled up.
    pub fn draw_alone(
        &mut self,
        runner: &mut Runner<L>,
        Viewing { stop, show }: Viewing,
        target: &wgpu::TextureView,
        size: (u32, u32),
    ) -> Result<()> {
        if !self.half_resolution {
            return runner.draw_alone(target, size, stop, show);
        }
        let half = (size.0.div_ceil(2), size.1.div_ceil(2));
        let picture = self.half_picture.at(&runner.gpu.device, half);
        runner.draw_through((&picture, half), target, stop, show)
    }

    /// Draws the lesson at half the view's resolution, or at full (`R`, the panel's box).
    pub fn set_half_resolution(&mut self, half: bool) {
        if half != self.half_resolution {
            self.half_resolution = half;
            // A picked pixel was one of the other resolution's.
            self.picked = None;
            self.story = None;
        }
    }

    /// How many of the view's pixels a side of one of the lesson's covers.
    fn scale(&self) -> u32 {
        if self.half_resolution { 2 } else { 1 }
    }

    pub fn context(&self) -> &egui::Context {
        &self.ctx
    }

    /// Draws one frame into `target` (a window's surface texture or any texture of the colour
    /// format, `size` pixels): the panel and, beside it, the lesson at the view's size. Carries out
    /// what the panel asked (given `input`, egui's events since the last frame) and submits.
    pub fn draw(
        &mut self,
        input: egui::RawInput,
        runner: &mut Runner<L>,
        viewing: &mut Viewing,
        target: &wgpu::Texture,
    ) -> Result<Drawn> {
        let start = Instant::now();
        let raw_input = input;
        let size = (target.width(), target.height());
        self.tell_story(runner);
        // The step names as the last frame recorded them, unless what they follow changed: asking
        // the lesson records a frame of no steps, an encoder made and dropped every frame.
        let steps_key = (runner.knobs.clone(), runner.camera);
        let steps = match &self.steps {
            Some((key, steps)) if *key == steps_key => steps.clone(),
            _ => runner.steps(),
        };
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
            cost: self.shown_cost.as_ref(),
            adapter: &self.adapter,
            camera: self.shown_camera.unwrap_or(runner.camera),
            poses: &self.poses,
            book_shots: &self.book_names,
            book: &self.book,
            show_difference: self.show_difference,
            message: self.message.as_deref(),
            half_resolution: (self.software_gpu || self.half_resolution)
                .then_some(self.half_resolution),
            picked: self.picked.map(|pixel| Picked {
                pixel,
                story: match &self.story {
                    Some((_, Ok(story))) => Ok(story),
                    Some((_, Err(why))) => Err(why.as_str()),
                    None => Err("telling its story…"),
                },
            }),
        };
        let difference = self
            .difference
            .as_ref()
            .filter(|_| self.show_difference)
            .map(|d| (d.id(), d.size_vec2()));
        // An idle frame — no input, egui waiting for nothing, the panel's contents as last laid
        // out — needs no new layout: egui's pass costs 0.3-0.4 ms on a fast GPU's machine, as much
        // as the lesson's frame. The last one's shapes and the view's place are kept.
        let shown = Shown::of(&model, size, difference.is_some());
        let idle = raw_input.events.is_empty()
            && !self.ctx.has_requested_repaint()
            && self.panel_picture.is_some()
            && self
                .laid_out
                .as_ref()
                .is_some_and(|last| last.shown == shown);
        let mut actions = Vec::new();
        let output = if idle {
            let last = self.laid_out.as_ref().expect("checked above");
            egui::FullOutput {
                pixels_per_point: last.pixels_per_point,
                ..Default::default()
            }
        } else {
            let mut view_rect = egui::Rect::NOTHING;
            let picked = self.picked;
            let scale = self.scale() as f32;
            let ctx = self.ctx.clone();
            let output = ctx.run_ui(raw_input, |ui| {
                actions = panel::show(ui, &model);
                view_rect =
                    pixel_rect(ui.available_rect_before_wrap(), ui.ctx().pixels_per_point());
                let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
                let painter = ui.painter();
                // The picked pixel, marked with a cross in the view.
                if let Some((x, y)) = picked {
                    let ppp = ui.ctx().pixels_per_point();
                    let pixel = egui::vec2(x as f32 + 0.5, y as f32 + 0.5) * scale;
                    let centre = view_rect.min + pixel / ppp;
                    let stroke = egui::Stroke::new(2.0 / ppp, egui::Color32::from_rgb(255, 220, 0));
                    for direction in [egui::vec2(1.0, 0.0), egui::vec2(0.0, 1.0)] {
                        for sign in [-1.0, 1.0] {
                            let (near, far) = (3.0 / ppp, 10.0 / ppp);
                            let from = centre + direction * sign * near;
                            let to = centre + direction * sign * far;
                            painter.line_segment([from, to], stroke);
                        }
                    }
                }
                if let Some((id, picture)) = difference {
                    let fit = (view_rect.width() / picture.x).min(view_rect.height() / picture.y);
                    let rect = egui::Rect::from_center_size(view_rect.center(), picture * fit);
                    painter.image(id, rect, uv, egui::Color32::WHITE);
                }
            });
            self.layouts += 1;
            self.laid_out = Some(LaidOut {
                shown,
                view_rect,
                pixels_per_point: output.pixels_per_point,
            });
            output
        };
        let view_rect = self
            .laid_out
            .as_ref()
            .map_or(egui::Rect::NOTHING, |l| l.view_rect);
        let changed = !actions.is_empty();
        for action in actions {
            self.act(action, runner, viewing)?;
        }

        // The view: the rest of the window, in whole pixels.
        let ppp = output.pixels_per_point;
        let max = runner.gpu.max_size();
        let view_size = (
            ((view_rect.width() * ppp).round() as u32).clamp(1, max),
            ((view_rect.height() * ppp).round() as u32).clamp(1, max),
        );
        // At half resolution the lesson draws a quarter of the pixels, scaled up into the view.
        let scale = self.scale();
        let drawn = (view_size.0.div_ceil(scale), view_size.1.div_ceil(scale));
        if drawn != self.buffers.size {
            self.buffers = Buffers::new(&runner.gpu, runner.scene.color_format, drawn);
            for (view, id) in self.buffers.encoded.iter().zip(self.ids) {
                self.renderer.update_egui_texture_from_wgpu_texture(
                    &runner.gpu.device,
                    view,
                    wgpu::FilterMode::Nearest,
                    id,
                );
            }
        }
        // The lesson drew at the window's full size while the panel was hidden.
        runner.resize(drawn.0, drawn.1);
        let [color, depth, stencil] = &self.buffers.views;
        let raw_depth = viewing.show == Show::RawDepth;
        // The depth and stencil pictures cost a third of the frame on a software GPU (the stencil
        // one is nine full-window passes): paint them when what they show changed, when one is the
        // view, and otherwise (the camera moving) twice a second.
        // The panel's own picture (its small buffers among it) follows them.
        let key = (runner.knobs.clone(), *viewing, drawn);
        let due = self.pictures_for.as_ref() != Some(&key)
            || self.pictures_at.elapsed().as_secs_f64() > PICTURES_EVERY_S;
        let fresh = due || viewing.show != Show::Color;
        let pictures = fresh.then_some([depth, stencil]);
        // The steps are timed with the pictures too, twice a second: a timed frame records a pass
        // a step with timestamps, where the others record the whole frame in one pass (timing every
        // frame cost an H100 up to a third of a window's frame with the panel).
        let timer = match &mut self.timer {
            Some(timer) if due => Some(timer.for_next_frame(&runner.gpu.device)?),
            _ => None,
        };
        let timed = timer.is_some();
        let (mut encoder, steps) =
            runner.record_buffers(color, pictures, viewing.stop, raw_depth, timer)?;
        self.steps = Some(((runner.knobs.clone(), runner.camera), steps.clone()));
        if due {
            self.pictures_for = Some(key);
            self.pictures_at = Instant::now();
        }
        let viewport = [
            (view_rect.min.x * ppp).round(),
            (view_rect.min.y * ppp).round(),
            view_size.0 as f32,
            view_size.1 as f32,
        ];
        let fits = viewport[0] + viewport[2] <= size.0 as f32
            && viewport[1] + viewport[3] <= size.1 as f32;
        // The panel. egui's shader costs a software GPU 12 ms a frame for the panel's 330x720
        // pixels alone, so the panel is painted into a picture of its own when it changed (a
        // hover, a knob, the small buffers and the cost twice a second) and copied beside
        // the view otherwise. What egui paints outside the panel (a dropdown's list, the FLIP
        // difference over the view) is painted straight over the frame, as is everything where
        // the target cannot be copied to.
        let panel_left = if fits {
            (viewport[0] + viewport[2]) as u32
        } else {
            0
        };
        let panel = egui::Rect::from_min_max(
            egui::pos2(panel_left as f32 / ppp, 0.0),
            egui::pos2(size.0 as f32 / ppp, size.1 as f32 / ppp),
        );
        let inside = output.shapes.iter().all(|clipped| {
            let bounds = clipped
                .shape
                .visual_bounding_rect()
                .intersect(clipped.clip_rect);
            !bounds.is_positive() || panel.expand(0.5).contains_rect(bounds)
        });
        let copy_dst = target.usage().contains(wgpu::TextureUsages::COPY_DST);
        let panel_copied = idle || (fits && inside && copy_dst);
        // The view, pixel for pixel. Where the view and the panel's picture tile the target, it is
        // copied, as the picture is: drawn by a render pass (with a bind group made each frame) it
        // cost an H100 most of the tenth of a millisecond the panel added to its frame. Otherwise
        // (half resolution, a view that does not fit) it is drawn, and the rest cleared. (Through
        // egui's shader the view cost a software GPU 29 ms a frame at 1280x720.)
        let shown = match viewing.show {
            Show::Color => 0,
            Show::Depth | Show::RawDepth => 1,
            Show::Stencil => 2,
        };
        let tiles = panel_copied
            && self.scale() == 1
            && viewport[..2] == [0.0, 0.0]
            && (panel_left, size.1) == view_size;
        if tiles {
            let whole = wgpu::Extent3d {
                width: view_size.0,
                height: view_size.1,
                depth_or_array_layers: 1,
            };
            let source = &self.buffers.textures[shown];
            encoder.copy_texture_to_texture(source.as_image_copy(), target.as_image_copy(), whole);
        } else {
            runner.scene.blit.draw_in(
                &runner.gpu.device,
                &mut encoder,
                &self.buffers.views[shown],
                &target_view(target),
                fits.then_some(viewport),
                wgpu::FilterMode::Nearest,
            );
        }
        let mut textures = output.textures_delta;
        self.update_textures(runner, &textures);
        if idle {
            // Nothing new to paint but the small buffers when they are due (the shapes are the
            // picture's own).
            if due && let Some(picture) = self.panel_picture.take() {
                let shapes = picture.shapes.clone();
                self.paint(runner, &mut encoder, shapes, ppp, &picture.view, size);
                self.panel_picture = Some(picture);
            }
            if let Some(picture) = &self.panel_picture {
                picture.copy(&mut encoder, target, panel_left);
            }
        } else if panel_copied {
            let stale = due
                || !textures.is_empty()
                || self.panel_picture.as_ref().is_none_or(|picture| {
                    picture.size != size
                        || picture.pixels_per_point != ppp
                        || picture.shapes != output.shapes
                });
            if stale {
                let picture = match self.panel_picture.take() {
                    Some(picture) if picture.size == size => picture,
                    _ => PanelPicture::new(&runner.gpu.device, target.format(), size),
                };
                let shapes = output.shapes.clone();
                self.paint(
                    runner,
                    &mut encoder,
                    output.shapes,
                    ppp,
                    &picture.view,
                    size,
                );
                self.panel_picture = Some(PanelPicture {
                    shapes,
                    pixels_per_point: ppp,
                    ..picture
                });
            }
            if let Some(picture) = &self.panel_picture {
                picture.copy(&mut encoder, target, panel_left);
            }
        } else {
            self.panel_picture = None;
            let target = target_view(target);
            self.paint(runner, &mut encoder, output.shapes, ppp, &target, size);
        }
        for id in &textures.free {
            self.renderer.free_texture(id);
        }
        // Applied: egui checks that no delta is dropped unapplied.
        textures.clear();
        runner.gpu.queue.submit([encoder.finish()]);
        let cpu_ms = start.elapsed().as_secs_f64() * 1000.0;
        // The steps' times arrive when the GPU has run the frame, usually by the next one: the
        // window never waits for the GPU to report a statistic.
        let steps_ms = match &mut self.timer {
            Some(timer) => {
                if timed {
                    timer.submitted(steps.len().min(viewing.stop.count()));
                }
                timer.latest(&runner.gpu.device)?.map(<[f64]>::to_vec)
            }
            None => None,
        };
        // Frames drawn one after another (a drag, `--frames`) have a frame time and a rate: the
        // mean interval over the last second and a half. A window that draws only on change has
        // neither.
        self.presented.push_back(start);
        while self
            .presented
            .front()
            .is_some_and(|t| t.elapsed().as_secs_f64() > CONTINUOUS_S)
        {
            self.presented.pop_front();
        }
        let frame_ms = (self.presented.len() > 2).then(|| {
            let (first, count) = (self.presented[0], self.presented.len() - 1);
            (start - first).as_secs_f64() * 1000.0 / count as f64
        });
        self.cost = Some(Cost {
            steps_ms,
            cpu_ms,
            frame_ms,
            fps: frame_ms.map(|ms| 1000.0 / ms),
        });
        // Figures that change every frame cannot be read, and would paint the panel every frame.
        // The first step times arrive a frame or two after the first timed frame: shown when they do.
        let first_times = self
            .shown_cost
            .as_ref()
            .is_some_and(|shown| shown.steps_ms.is_none())
            && self
                .cost
                .as_ref()
                .is_some_and(|cost| cost.steps_ms.is_some());
        if self.shown_cost.is_none() || due || first_times {
            self.shown_cost = self.cost.clone();
            self.shown_camera = Some(runner.camera);
        }
        // A pose the panel shows that is no longer the camera's: draw until it is.
        let stale_camera = self.shown_camera != Some(runner.camera);
        // A story told for an older camera: draw until it is told again.
        let stale_story = self.picked.is_some()
            && self
                .story
                .as_ref()
                .is_none_or(|(told, _)| told.1 != runner.camera || told.2 != self.buffers.size);
        // Timed but no times yet: draw until they come (a frame or two), for the panel to show them.
        let awaiting_times = self.timer.is_some()
            && self
                .shown_cost
                .as_ref()
                .is_some_and(|shown| shown.steps_ms.is_none());
        Ok(Drawn {
            again: changed
                || self.verdicts.is_some()
                || stale_camera
                || stale_story
                || awaiting_times,
            repaint_now: output
                .viewport_output
                .values()
                .any(|v| v.repaint_delay.is_zero()),
            platform: output.platform_output,
        })
    }

    /// Gives egui's renderer the textures egui made or changed (its fonts, the FLIP difference).
    fn update_textures(&mut self, runner: &Runner<L>, textures: &egui::TexturesDelta) {
        let (device, queue) = (&runner.gpu.device, &runner.gpu.queue);
        for (id, deltas) in &textures.set {
            for delta in deltas {
                self.renderer.update_texture(device, queue, *id, delta);
            }
        }
    }

    /// egui's triangles, drawn over `target` of `(width, height)` pixels.
    fn paint(
        &mut self,
        runner: &Runner<L>,
        encoder: &mut wgpu::CommandEncoder,
        shapes: Vec<egui::epaint::ClippedShape>,
        pixels_per_point: f32,
        target: &wgpu::TextureView,
        (width, height): (u32, u32),
    ) {
        let (device, queue) = (&runner.gpu.device, &runner.gpu.queue);
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
    }

    /// Carries out one ask of the panel.
    fn act(&mut self, action: Action, runner: &mut Runner<L>, viewing: &mut Viewing) -> Result<()> {
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
            Action::Camera(pose) => {
                runner.camera = pose;
                self.shown_camera = None;
            }
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
            Action::Unpick => {
                self.picked = None;
                self.story = None;
            }
            Action::Hide => self.visible = false,
            Action::HalfResolution(half) => self.set_half_resolution(half),
        }
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
        arguments.extend(Args::scene_arguments(&self.scene));
        arguments.extend(["--screenshot".to_string(), path.display().to_string()]);
        if let Some(backend) = &self.backend {
            arguments.extend(["--backend".to_string(), backend.clone()]);
        }
        let command = format!("cargo run -p {} -- {}", L::NAME, arguments.join(" "));
        // The very arguments printed, parsed as the lesson's command line parses them.
        let program = std::iter::once(L::NAME.to_string());
        let args = Args::parse_for::<L>(program.chain(arguments))?;
        let knobs = Knobs::from_settings(L::KNOBS, &args.settings)?;
        crate::app::headless::run::<L>(&args, knobs, args.camera::<L>()?)?;
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
        if let Some(reason) = &shot.driver_dependent {
            self.book = Book::NotCompared {
                name: shot.name.clone(),
                why: check::not_compared(reason),
            };
            self.verdicts = None;
            return;
        }
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

/// A view of the workbench's target, for the passes that draw into it.
fn target_view(target: &wgpu::Texture) -> wgpu::TextureView {
    target.create_view(&wgpu::TextureViewDescriptor {
        label: Some("workbench target"),
        ..Default::default()
    })
}

/// `rect` with its corners moved to whole pixels.
fn pixel_rect(rect: egui::Rect, pixels_per_point: f32) -> egui::Rect {
    let round =
        |p: egui::Pos2| (p.to_vec2() * pixels_per_point).round().to_pos2() / pixels_per_point;
    egui::Rect::from_min_max(round(rect.min), round(rect.max))
}

/// What the panel showed when egui last laid it out, and where that put the view.
struct LaidOut {
    shown: Shown,
    view_rect: egui::Rect,
    pixels_per_point: f32,
}

/// Everything the panel shows that can change while no input comes: equal, and the last layout
/// still holds.
#[derive(Clone, PartialEq)]
struct Shown {
    size: (u32, u32),
    knobs: Knobs,
    steps: Vec<&'static str>,
    step: usize,
    show: Show,
    can_show_depth: bool,
    aspect: Option<f32>,
    cost: Option<Cost>,
    camera: Camera,
    book: Book,
    show_difference: bool,
    difference_shown: bool,
    message: Option<String>,
    half_resolution: Option<bool>,
    /// The picked pixel and its story as told.
    picked: Option<((u32, u32), String)>,
}

impl Shown {
    fn of(model: &Model<'_>, size: (u32, u32), difference_shown: bool) -> Self {
        Self {
            size,
            knobs: model.knobs.clone(),
            steps: model.steps.to_vec(),
            step: model.step,
            show: model.show,
            can_show_depth: model.can_show_depth,
            aspect: model.thumbnails.map(|(_, aspect)| aspect),
            cost: model.cost.cloned(),
            camera: model.camera,
            book: model.book.clone(),
            show_difference: model.show_difference,
            difference_shown,
            message: model.message.map(str::to_string),
            half_resolution: model.half_resolution,
            picked: model.picked.as_ref().map(|picked| {
                let story = match picked.story {
                    Ok(story) => story.text(),
                    Err(why) => why.to_string(),
                };
                (picked.pixel, story)
            }),
        }
    }
}

/// The panel as last painted, to be copied into frames in which it did not change.
struct PanelPicture {
    texture: wgpu::Texture,
    view: wgpu::TextureView,
    size: (u32, u32),
    pixels_per_point: f32,
    /// What egui painted into it.
    shapes: Vec<egui::epaint::ClippedShape>,
}

impl PanelPicture {
    /// A picture of the whole target's size (egui's coordinates are the target's).
    fn new(device: &wgpu::Device, format: wgpu::TextureFormat, size: (u32, u32)) -> Self {
        let texture = crate::gpu::target_texture(
            device,
            "workbench panel picture",
            format,
            size,
            wgpu::TextureUsages::COPY_SRC,
        );
        Self {
            view: texture.create_view(&Default::default()),
            texture,
            size,
            pixels_per_point: 0.0,
            shapes: Vec::new(),
        }
    }

    /// Copies the panel's part, from `left` to the right edge, into the same place of `target`.
    fn copy(&self, encoder: &mut wgpu::CommandEncoder, target: &wgpu::Texture, left: u32) {
        let at = |texture| wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d {
                x: left,
                y: 0,
                z: 0,
            },
            aspect: wgpu::TextureAspect::All,
        };
        let extent = wgpu::Extent3d {
            width: self.size.0.saturating_sub(left),
            height: self.size.1,
            depth_or_array_layers: 1,
        };
        if extent.width > 0 {
            encoder.copy_texture_to_texture(at(&self.texture), at(target), extent);
        }
    }
}

impl Buffers {
    fn new(gpu: &crate::Gpu, format: wgpu::TextureFormat, size: (u32, u32)) -> Self {
        // egui samples its textures as sRGB-encoded values: it gets views of the same texels
        // without the sRGB decoding (through an sRGB view the thumbnails came out too dark).
        let encoded = format.remove_srgb_suffix();
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT
            | wgpu::TextureUsages::TEXTURE_BINDING
            | wgpu::TextureUsages::COPY_SRC;
        let texture = |label, usage| {
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
                usage,
                view_formats: &[encoded],
            })
        };
        let textures = [
            texture("workbench colour", usage),
            texture("workbench depth picture", usage),
            texture("workbench stencil picture", usage),
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
            textures,
        }
    }
}
