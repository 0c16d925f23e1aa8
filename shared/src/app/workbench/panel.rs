//! The side panel itself: egui widgets drawn from what the lesson is now ([`Model`]), answering with
//! what the user asked for ([`Action`]). It holds no GPU object and changes nothing, so it can be
//! driven without a window (the test suite clicks it with `egui_kittest`).

use egui::{Align, Color32, Layout, RichText, TextureId, Ui};

use crate::lesson::knobs::{Knob, Knobs};
use crate::lesson::steps::Show;
use crate::lesson::story::Story;
use crate::room::camera::Camera;

/// The panel's width in points (times `--ui-scale` in pixels): the view gets the rest.
pub const WIDTH: f32 = 330.0;

/// What the user asked for.
#[derive(Debug, Clone, PartialEq)]
pub enum Action {
    /// Set knob number `index` (from 0) to `value`.
    Knob(usize, &'static str),
    ResetKnobs,
    /// Stop the frame after step `number` (from 1).
    Step(usize),
    Show(Show),
    /// Show the test map of this draw of the step (from 0), or of every draw in it.
    Draw(Option<usize>),
    Camera(Camera),
    PrintCamera,
    CopyCamera,
    Screenshot,
    /// Turn to the settings of the book's screenshot number `index` of [`Model::book_shots`].
    BookShot(usize),
    ShowDifference(bool),
    /// Stop following the picked pixel.
    Unpick,
    Hide,
    /// Draw the lesson at half the view's resolution, or at full.
    HalfResolution(bool),
}

/// The pixel picked in the view (a right-click) and its story, or why it cannot be told.
pub struct Picked<'a> {
    pub pixel: (u32, u32),
    pub story: Result<&'a Story, &'a str>,
}

/// What the book comparison has found for the current settings.
#[derive(Debug, Clone, PartialEq)]
pub enum Book {
    /// No screenshot of the book has these settings.
    NoMatch,
    /// Rendering the book's screenshot `name` to compare.
    Comparing(String),
    Compared {
        name: String,
        summary: String,
        matches: bool,
    },
    /// The book's screenshot `name` is the driver's own choice: `why` says so.
    NotCompared {
        name: String,
        why: String,
    },
    Failed(String),
}

/// The GPU time of a frame, or only its CPU time.
#[derive(Debug, Clone, PartialEq)]
pub struct Cost {
    /// Each step's GPU time in milliseconds, from timestamp queries; `None` without them.
    pub steps_ms: Option<Vec<f64>>,
    /// The CPU's time to record and submit the frame (lesson and panel), in milliseconds.
    pub cpu_ms: f64,
    /// From one frame to the next, over the last second, when the window draws continuously;
    /// `None` when it draws only on change.
    pub frame_ms: Option<f64>,
    pub fps: Option<f64>,
}

/// Everything the panel shows.
pub struct Model<'a> {
    pub title: &'a str,
    pub knob_list: &'static [Knob],
    pub knobs: &'a Knobs,
    pub steps: &'a [&'static str],
    /// The step the frame stops after, from 1.
    pub step: usize,
    pub show: Show,
    /// The step's draws, named, where its test map is shown; the one shown (`None`: every one).
    pub draws: &'a [String],
    pub draw: Option<usize>,
    /// Whether this backend can show the depth buffer (GL cannot).
    pub can_show_depth: bool,
    /// The colour, depth, stencil and complexity pictures at the current step, and the view's
    /// aspect ratio.
    pub thumbnails: Option<([TextureId; 4], f32)>,
    pub cost: Option<&'a Cost>,
    /// The adapter's name and backend.
    pub adapter: &'a str,
    pub camera: Camera,
    /// Named camera poses: the lesson's own, the book's.
    pub poses: &'a [(String, Camera)],
    /// The names of the book's screenshots of this lesson.
    pub book_shots: &'a [String],
    pub book: &'a Book,
    pub show_difference: bool,
    /// The last thing the panel did that the user should read (a screenshot written, say).
    pub message: Option<&'a str>,
    /// The pixel whose story the panel tells, if one is picked.
    pub picked: Option<Picked<'a>>,
    /// Whether the lesson is drawn at half resolution; `None` hides the choice (a GPU that is not
    /// a software one, at full resolution).
    pub half_resolution: Option<bool>,
}

/// Draws the panel on the right of `ui`; returns what the user asked for.
pub fn show(ui: &mut Ui, model: &Model<'_>) -> Vec<Action> {
    let mut actions = Vec::new();
    egui::Panel::right("workbench panel")
        .exact_size(WIDTH)
        .resizable(false)
        .show(ui, |ui| {
            egui::ScrollArea::vertical().show(ui, |ui| {
                ui.heading(model.title);
                // First, where a window of 720 pixels shows it without scrolling.
                ui.horizontal(|ui| {
                    ui.label("H hides this panel.");
                    if ui.small_button("Hide").clicked() {
                        actions.push(Action::Hide);
                    }
                    if ui
                        .small_button("Screenshot")
                        .on_hover_text("write the PNG --screenshot would, and print the command")
                        .clicked()
                    {
                        actions.push(Action::Screenshot);
                    }
                });
                knobs(ui, model, &mut actions);
                steps(ui, model, &mut actions);
                pixel(ui, model, &mut actions);
                cost(ui, model, &mut actions);
                camera(ui, model, &mut actions);
                book(ui, model, &mut actions);
                if let Some(message) = model.message {
                    ui.separator();
                    ui.label(RichText::new(message).monospace());
                }
            });
        });
    actions
}

fn section(ui: &mut Ui, title: &str) {
    ui.add_space(6.0);
    ui.separator();
    ui.label(RichText::new(title).strong().size(16.0));
}

/// A dropdown per knob, its meaning as the tooltip, the default marked.
fn knobs(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    section(ui, "Knobs");
    if model.knob_list.is_empty() {
        ui.label("This lesson has no knobs.");
    }
    egui::Grid::new("knobs").num_columns(2).show(ui, |ui| {
        for (index, (knob, (_, value))) in
            model.knob_list.iter().zip(model.knobs.pairs()).enumerate()
        {
            let key = if index < 9 {
                format!("[{}] ", index + 1)
            } else {
                String::new()
            };
            ui.label(format!("{key}{}", knob.name))
                .on_hover_text(knob.meaning);
            let marked = |v: &str| match v == knob.default {
                true => format!("{v} (default)"),
                false => v.to_string(),
            };
            egui::ComboBox::new(knob.name, "")
                .selected_text(marked(value))
                .show_ui(ui, |ui| {
                    for &choice in knob.values {
                        if ui
                            .selectable_label(choice == value, marked(choice))
                            .clicked()
                            && choice != value
                        {
                            actions.push(Action::Knob(index, choice));
                        }
                    }
                })
                .response
                .on_hover_text(knob.meaning);
            ui.end_row();
        }
    });
    let all_default = model.knobs.changed().is_empty();
    if ui
        .add_enabled(!all_default, egui::Button::new("Reset to defaults"))
        .clicked()
    {
        actions.push(Action::ResetKnobs);
    }
}

/// The frame's steps (click one to stop there), the buffer shown, and the three buffers small.
fn steps(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    section(ui, "The frame's steps");
    for (index, name) in model.steps.iter().enumerate() {
        let number = index + 1;
        let text = format!("{number}. {name}");
        if ui.selectable_label(number == model.step, text).clicked() && number != model.step {
            actions.push(Action::Step(number));
        }
    }
    ui.horizontal_wrapped(|ui| {
        for show in Show::VIEWS.into_iter().chain([Show::RawDepth]) {
            let depth = matches!(show, Show::Depth | Show::RawDepth);
            let enabled = !depth || model.can_show_depth;
            let button = egui::Button::selectable(model.show == show, show.name());
            if ui.add_enabled(enabled, button).clicked() && model.show != show {
                actions.push(Action::Show(show));
            }
        }
    });
    if model.show == Show::Tests {
        test_map(ui, model, actions);
    }
    if let Some((ids, aspect)) = model.thumbnails {
        let width = (ui.available_width() - 3.0 * ui.spacing().item_spacing.x) / 4.0;
        let size = egui::vec2(width, width / aspect.max(0.1));
        ui.horizontal(|ui| {
            let shows = [Show::Color, Show::Depth, Show::Stencil, Show::Complexity];
            for (id, show) in ids.into_iter().zip(shows) {
                ui.vertical(|ui| {
                    let image = egui::Image::new((id, size)).sense(egui::Sense::click());
                    let response = ui.add(image).on_hover_text(format!("show {}", show.name()));
                    if response.clicked() && model.show != show {
                        actions.push(Action::Show(show));
                    }
                    ui.label(RichText::new(show.name()).small());
                });
            }
        });
        if !model.can_show_depth {
            ui.label("This backend cannot read the depth buffer in a shader: no depth picture.");
        }
    }
}

/// The test map's draw (every draw of the step, or one) and what its colours mean.
fn test_map(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    let name = |draw: Option<usize>| match draw {
        None => "every draw of the step".to_string(),
        Some(index) => model.draws.get(index).cloned().unwrap_or_default(),
    };
    egui::ComboBox::from_label("draw")
        .selected_text(name(model.draw))
        .show_ui(ui, |ui| {
            let choices = std::iter::once(None).chain((0..model.draws.len()).map(Some));
            for choice in choices {
                let chosen = ui.selectable_label(model.draw == choice, name(choice));
                if chosen.clicked() && model.draw != choice {
                    actions.push(Action::Draw(choice));
                }
            }
        });
    ui.horizontal_wrapped(|ui| {
        use crate::gpu::pipelines::Fate;
        let fates = [
            (Fate::Passes, "passed"),
            (Fate::DepthFails, "failed depth"),
            (Fate::StencilFails, "failed stencil"),
            (Fate::Culled, "culled"),
        ];
        for (fate, text) in fates {
            let [r, g, b] = crate::gpu::maps::fate_colour(fate);
            ui.label(RichText::new(format!("■ {text}")).color(egui::Color32::from_rgb(r, g, b)));
        }
    });
}

/// The picked pixel's story (`--pixel`): each step's values there, the steps that changed it
/// highlighted, and every draw that reaches it with its tests written out.
fn pixel(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    let Some(picked) = &model.picked else {
        section(ui, "One pixel");
        ui.label("Right-click the view to follow one pixel through the frame (as --pixel X,Y).");
        return;
    };
    let (x, y) = picked.pixel;
    section(ui, &format!("Pixel ({x}, {y})"));
    if ui.small_button("Forget the pixel").clicked() {
        actions.push(Action::Unpick);
    }
    let story = match picked.story {
        Ok(story) => story,
        Err(why) => {
            ui.label(why);
            return;
        }
    };
    let mut before = None;
    for (index, step) in story.steps.iter().enumerate() {
        let after = step.after;
        let changed = before.is_some_and(|b| b != after);
        let line = format!(
            "{}. {}: {} {:.4} {}",
            index + 1,
            step.name,
            crate::lesson::story::hex(after.color),
            after.depth,
            after.stencil
        );
        let text = RichText::new(line).monospace().small();
        ui.label(match changed {
            true => text.strong().color(Color32::from_rgb(255, 210, 80)),
            false => text,
        });
        for draw in &step.draws {
            for (row, words) in draw.describe().into_iter().enumerate() {
                let indent = if row == 0 { "  · " } else { "      " };
                // The panel's monospace font has no arrow.
                let words = words.replace('→', "->");
                let text = RichText::new(format!("{indent}{words}"))
                    .monospace()
                    .small();
                ui.label(match draw.fragments.is_empty() {
                    true => text.weak(),
                    false => text,
                });
            }
        }
        before = Some(after);
    }
}

/// GPU time per step where the adapter has timestamp queries, otherwise the CPU's frame time.
fn cost(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    section(ui, "What it costs");
    ui.label(RichText::new(model.adapter).small());
    if let Some(half) = model.half_resolution {
        let mut checked = half;
        let said = match half {
            true => "software GPU: drawing at half resolution (R)",
            false => "drawing at full resolution (R)",
        };
        if ui.checkbox(&mut checked, said).changed() {
            actions.push(Action::HalfResolution(checked));
        }
    }
    let Some(cost) = model.cost else {
        ui.label("Measuring…");
        return;
    };
    match &cost.steps_ms {
        Some(times) => {
            ui.label("GPU time per step (timestamp queries):");
            egui::Grid::new("step times").num_columns(2).show(ui, |ui| {
                for (name, ms) in model.steps.iter().zip(times) {
                    ui.label(*name);
                    ui.with_layout(Layout::right_to_left(Align::Center), |ui| {
                        ui.label(milliseconds(*ms));
                    });
                    ui.end_row();
                }
                ui.label(RichText::new("all steps").strong());
                ui.with_layout(Layout::right_to_left(Align::Center), |ui| {
                    ui.label(milliseconds(times.iter().sum()).strong());
                });
                ui.end_row();
            });
        }
        None => {
            ui.label(
                "CPU time only: this adapter has no timestamp queries, so the steps cannot be timed \
                 on the GPU.",
            );
        }
    }
    ui.label(format!("CPU, record and submit: {:.2} ms", cost.cpu_ms));
    match (cost.frame_ms, cost.fps) {
        (Some(ms), Some(fps)) => ui.label(format!("Frame: {ms:.1} ms · {fps:.0} frames/s")),
        _ => ui.label("Frame: drawn on change (drag the view for frames/s)"),
    };
}

/// A time in a column of times: monospace and of one width, so that the column keeps its width
/// from frame to frame (a grid whose columns change width asks egui for another frame, and the
/// window would never rest).
fn milliseconds(ms: f64) -> RichText {
    RichText::new(format!("{ms:>8.3} ms")).monospace()
}

/// The pose as `--camera` takes it, and the book's poses.
fn camera(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    section(ui, "Camera");
    ui.label(RichText::new(format!("--camera {}", model.camera)).monospace());
    ui.horizontal(|ui| {
        if ui
            .button("Print")
            .on_hover_text("print --camera … on the terminal")
            .clicked()
        {
            actions.push(Action::PrintCamera);
        }
        if ui
            .button("Copy")
            .on_hover_text("copy --camera … to the clipboard")
            .clicked()
        {
            actions.push(Action::CopyCamera);
        }
    });
    ui.horizontal_wrapped(|ui| {
        for (name, pose) in model.poses {
            if ui.selectable_label(*pose == model.camera, name).clicked() && *pose != model.camera {
                actions.push(Action::Camera(*pose));
            }
        }
    });
}

/// Whether the view is one of the book's pictures, and how close.
fn book(ui: &mut Ui, model: &Model<'_>, actions: &mut Vec<Action>) {
    section(ui, "Compare with the book");
    match model.book {
        Book::NoMatch => {
            ui.label("No picture of the book has these settings. Its pictures of this lesson:");
        }
        Book::Comparing(name) => {
            ui.label(format!("This is the book's `{name}`: comparing…"));
        }
        Book::Compared {
            name,
            summary,
            matches,
        } => {
            let (verdict, colour) = match matches {
                true => ("matches the book", Color32::from_rgb(80, 200, 120)),
                false => ("DIFFERS from the book", Color32::from_rgb(240, 90, 80)),
            };
            ui.label(format!("This is the book's `{name}`:"));
            ui.label(RichText::new(verdict).color(colour).strong());
            ui.label(RichText::new(summary).small());
            let mut shown = model.show_difference;
            if ui
                .checkbox(&mut shown, "show FLIP's difference over the view")
                .changed()
            {
                actions.push(Action::ShowDifference(shown));
            }
        }
        Book::NotCompared { name, why } => {
            ui.label(format!("This is the book's `{name}`: {why}."));
        }
        Book::Failed(error) => {
            ui.label(format!("Could not compare: {error}"));
        }
    }
    ui.horizontal_wrapped(|ui| {
        for (index, name) in model.book_shots.iter().enumerate() {
            if ui
                .small_button(name)
                .on_hover_text("turn to this picture's settings")
                .clicked()
            {
                actions.push(Action::BookShot(index));
            }
        }
    });
}
