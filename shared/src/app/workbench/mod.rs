//! The workbench: the lesson's window with a side panel (egui) of its knobs, the frame's steps, the
//! three buffers small, what the frame costs, the camera, a screenshot button and the comparison with
//! the book. The view beside the panel is the lesson's own render at the view's size, drawn pixel
//! for pixel; with the panel hidden (`H`) the window draws as it did without one.
//!
//! [`panel`] draws the widgets and says what was asked; this module owns the GPU side (the three
//! buffers as egui textures, the step timer, egui's renderer) and carries the asks out.

mod frame;
pub mod headless;
pub mod painter;
pub mod panel;
mod pictures;

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
use frame::LaidOut;
use painter::PanelPainter;
use panel::{Action, Book, Cost};
use pictures::{Buffers, PanelPicture};

/// How often the depth and stencil thumbnails follow a moving camera, in seconds.
const PICTURES_EVERY_S: f64 = 0.5;

/// What the window and the panel both change: where the frame stops and what is shown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Viewing {
    pub stop: Stop,
    pub show: Show,
    /// The draw a test map shows (its index in the step), or every draw of the step.
    pub draw: Option<usize>,
}

pub struct Workbench<L: Lesson> {
    pub visible: bool,
    ctx: egui::Context,
    painter: PanelPainter,
    buffers: Buffers,
    ids: [egui::TextureId; 4],
    /// The named draws of a step, for the test map's choice, and the knobs and step they are of.
    draws: Option<((Knobs, usize), Vec<String>)>,
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
        let mut painter = PanelPainter::new(&gpu.device, runner.scene.color_format);
        let buffers = Buffers::new(gpu, runner.scene.color_format, runner.depth_stencil.size());
        let ids = buffers
            .encoded
            .each_ref()
            .map(|view| painter.register(&gpu.device, view));
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
            painter,
            buffers,
            ids,
            draws: None,
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
        Viewing { stop, show, draw }: Viewing,
        target: &wgpu::TextureView,
        size: (u32, u32),
    ) -> Result<()> {
        let asked = (stop, show, draw);
        if !self.half_resolution {
            return runner.draw_alone(target, size, asked);
        }
        let half = (size.0.div_ceil(2), size.1.div_ceil(2));
        let picture = self.half_picture.at(&runner.gpu.device, half);
        runner.draw_through((&picture, half), target, asked)
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
                viewing.draw = None;
            }
            Action::Show(show) => viewing.show = show,
            Action::Draw(draw) => viewing.draw = draw,
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
                    draw: setting.draw,
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
        draw: viewing.draw,
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
