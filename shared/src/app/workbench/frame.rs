//! One frame of the workbench, in phases, the data going one way:
//!
//! 1. **read** what the frame depends on (the steps, the settings, the picked pixel's story),
//!    asking the runner and changing nothing of it;
//! 2. **lay out** the panel with egui, or keep the last layout where nothing it shows changed;
//! 3. **carry out** what the panel asked (knobs, step, view, camera…) and fit the view: the only
//!    phase that changes the runner;
//! 4. **plan**: the sizes, whether pictures and timings are due, the view copied or blitted, the
//!    panel's picture reused, repainted or the panel painted over the frame;
//! 5. **record and submit** the lesson, the view and the panel (egui's textures freed after the
//!    submit);
//! 6. **account**: the cost, the camera shown, whether to draw again.
//!
//! Each speed trick lives in the phase it serves, with its measured reason beside it.

use std::time::Instant;

use anyhow::Result;

use crate::app::runner::{FrameRequest, Recorded, Runner};
use crate::book::shots::Setting;
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::Show;
use crate::room::camera::Camera;

use super::panel::{self, Action, Book, Cost, Model, Picked};
use super::pictures::{Buffers, PanelPicture};
use super::{Drawn, PICTURES_EVERY_S, Viewing, Workbench, setting};

/// The frame time and rate are over the frames of the last this many seconds; fewer than three
/// frames in it, and the window draws only on change.
const CONTINUOUS_S: f64 = 1.5;

/// What the frame depends on, read before anything changes.
struct Reading {
    steps: Vec<&'static str>,
    /// The step the frame stops after (from 1; the step count for the whole frame).
    step: usize,
    setting: Setting,
    /// The draws of that step, named, where its test map is shown.
    draws: Vec<String>,
}

/// The panel of this frame: where it leaves the view, and what egui painted and asked, unless
/// the last layout holds.
struct Layout {
    /// The view's place, in points, with corners on whole pixels.
    view_rect: egui::Rect,
    pixels_per_point: f32,
    /// `None`: nothing to paint anew (the last layout's shapes hold), as egui's own
    /// `Context::run_logic` would say.
    fresh: Option<Fresh>,
}

/// What egui gave for a panel laid out anew.
struct Fresh {
    shapes: Vec<egui::epaint::ClippedShape>,
    textures: egui::TexturesDelta,
    platform: egui::PlatformOutput,
    repaint_now: bool,
    actions: Vec<Action>,
}

/// How the frame is put together on the target.
struct Plan {
    /// The view's size and place in the target's pixels.
    view_size: (u32, u32),
    viewport: [f32; 4],
    /// Whether the viewport lies inside the target (a window in the middle of a resize may not).
    fits: bool,
    /// Where the panel's part of the target begins.
    panel_left: u32,
    /// Whether the depth and stencil pictures and the step timings are due this frame.
    due: bool,
    /// Whether the depth and stencil pictures are painted this frame.
    pictures: bool,
    /// Which of the three buffers is the view.
    shown: usize,
    /// The view copied into the target (it tiles the target with the panel's picture), or drawn.
    copy_view: bool,
    panel: PanelWay,
}

/// How the panel reaches the target.
enum PanelWay {
    /// Its picture copied beside the view, painted first where it is stale.
    Copied { repaint: bool },
    /// Painted straight over the frame.
    Over,
}

impl<L: Lesson> Workbench<L> {
    /// Draws one frame into `target` (a window's surface texture or any texture of the colour
    /// format): the panel and, beside it, the lesson at the view's size. Carries out what the panel
    /// asked (given `input`, egui's events since the last frame) and submits.
    pub fn draw(
        &mut self,
        input: egui::RawInput,
        runner: &mut Runner<L>,
        viewing: &mut Viewing,
        target: &wgpu::Texture,
    ) -> Result<Drawn> {
        let start = Instant::now();
        let size = (target.width(), target.height());
        let reading = self.read(runner, *viewing);
        let mut layout = self.lay_out(input, runner, &reading, size);
        let actions = layout
            .fresh
            .as_mut()
            .map(|f| std::mem::take(&mut f.actions));
        let asked = actions.as_ref().is_some_and(|a| !a.is_empty());
        for action in actions.into_iter().flatten() {
            self.act(action, runner, viewing)?;
        }
        let view_size = self.fit_view(runner, &layout);
        let plan = self.plan(runner, *viewing, &layout, view_size, target);
        let (steps, timed) =
            self.record_and_submit(runner, *viewing, &plan, &mut layout, target)?;
        let fresh = layout.fresh;
        self.account(start, runner, *viewing, (&plan, steps.len(), timed))?;
        Ok(Drawn {
            again: asked || self.still_changing(runner),
            repaint_now: fresh.as_ref().is_some_and(|f| f.repaint_now),
            platform: fresh.map(|f| f.platform).unwrap_or_default(),
        })
    }

    /// Phase 1: the steps, the settings and the picked pixel's story, for the panel to show.
    fn read(&mut self, runner: &Runner<L>, viewing: Viewing) -> Reading {
        self.tell_story(runner);
        // The step names as the last frame recorded them, unless what they follow changed: asking
        // the lesson records a frame of no steps, an encoder made and dropped every frame.
        let steps_key = (runner.knobs.clone(), runner.camera);
        let steps = match &self.steps {
            Some((key, steps)) if *key == steps_key => steps.clone(),
            _ => runner.steps(),
        };
        let step = viewing.stop.resolve(&steps).unwrap_or(steps.len());
        let setting = setting(runner, viewing);
        self.follow_book(&setting);
        let draws = match viewing.show {
            Show::Tests => self.step_draws(runner, step),
            _ => Vec::new(),
        };
        Reading {
            steps,
            step,
            setting,
            draws,
        }
    }

    /// The draws of step `step` (from 1) as the test map's choice names them, kept while the
    /// knobs and the step stay (listing them records a frame).
    fn step_draws(&mut self, runner: &Runner<L>, step: usize) -> Vec<String> {
        let key = (runner.knobs.clone(), step);
        if let Some((made_for, draws)) = &self.draws
            && *made_for == key
        {
            return draws.clone();
        }
        let all = crate::app::pixel::draws(runner, &self.buffers.views[0]);
        let draws: Vec<String> = all
            .iter()
            .filter(|draw| draw.step + 1 == step)
            .enumerate()
            .map(|(index, draw)| crate::gpu::pass::draw_name(index, draw))
            .collect();
        self.draws = Some((key, draws.clone()));
        draws
    }

    /// What the panel shows, from the reading and the workbench's state.
    fn model<'a>(&'a self, runner: &'a Runner<L>, reading: &'a Reading) -> Model<'a> {
        let aspect = self.buffers.size.0 as f32 / self.buffers.size.1 as f32;
        Model {
            title: L::TITLE,
            knob_list: L::KNOBS,
            knobs: &runner.knobs,
            steps: &reading.steps,
            step: reading.step,
            show: reading.setting.show,
            draws: &reading.draws,
            draw: reading.setting.draw,
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
        }
    }

    /// Phase 2: the panel laid out by egui, or the last layout kept. An idle frame — no input,
    /// egui waiting for nothing, the panel's contents as last laid out — needs no new layout:
    /// egui's pass costs 0.3-0.4 ms on a fast GPU's machine, as much as the lesson's frame.
    fn lay_out(
        &mut self,
        input: egui::RawInput,
        runner: &Runner<L>,
        reading: &Reading,
        size: (u32, u32),
    ) -> Layout {
        let model = self.model(runner, reading);
        let difference = self
            .difference
            .as_ref()
            .filter(|_| self.show_difference)
            .map(|d| (d.id(), d.size_vec2()));
        let shown = Shown::of(&model, size, difference.is_some());
        let idle = input.events.is_empty()
            && !self.ctx.has_requested_repaint()
            && self.panel_picture.is_some();
        if let Some(last) = self
            .laid_out
            .as_ref()
            .filter(|last| idle && last.shown == shown)
        {
            return Layout {
                view_rect: last.view_rect,
                pixels_per_point: last.pixels_per_point,
                fresh: None,
            };
        }
        let marks = Marks {
            picked: self.picked,
            scale: self.scale() as f32,
            difference,
        };
        let mut actions = Vec::new();
        let mut view_rect = egui::Rect::NOTHING;
        let output = self.ctx.clone().run_ui(input, |ui| {
            actions = panel::show(ui, &model);
            view_rect = pixel_rect(ui.available_rect_before_wrap(), ui.ctx().pixels_per_point());
            marks.paint(ui, view_rect);
        });
        self.layouts += 1;
        self.laid_out = Some(LaidOut {
            shown,
            view_rect,
            pixels_per_point: output.pixels_per_point,
        });
        let viewports = output.viewport_output.values();
        let repaint_now = viewports.into_iter().any(|v| v.repaint_delay.is_zero());
        Layout {
            view_rect,
            pixels_per_point: output.pixels_per_point,
            fresh: Some(Fresh {
                repaint_now,
                shapes: output.shapes,
                textures: output.textures_delta,
                platform: output.platform_output,
                actions,
            }),
        }
    }

    /// Phase 3, after the actions: the three buffers and the runner's depth-stencil buffer made
    /// the size the lesson draws at (the view's, or at half resolution half of it). Returns the
    /// view's size in the target's pixels.
    fn fit_view(&mut self, runner: &mut Runner<L>, layout: &Layout) -> (u32, u32) {
        let (rect, ppp) = (layout.view_rect, layout.pixels_per_point);
        let max = runner.gpu.max_size();
        let view_size = (
            ((rect.width() * ppp).round() as u32).clamp(1, max),
            ((rect.height() * ppp).round() as u32).clamp(1, max),
        );
        // At half resolution the lesson draws a quarter of the pixels, scaled up into the view.
        let scale = self.scale();
        let drawn = (view_size.0.div_ceil(scale), view_size.1.div_ceil(scale));
        if drawn != self.buffers.size {
            self.buffers = Buffers::new(&runner.gpu, runner.scene.color_format, drawn);
            for (view, id) in self.buffers.encoded.iter().zip(self.ids) {
                self.painter.replace(&runner.gpu.device, id, view);
            }
        }
        // The lesson drew at the window's full size while the panel was hidden.
        runner.resize(drawn.0, drawn.1);
        view_size
    }

    /// Phase 4: how this frame is put together (reads, changes nothing).
    fn plan(
        &self,
        runner: &Runner<L>,
        viewing: Viewing,
        layout: &Layout,
        view_size: (u32, u32),
        target: &wgpu::Texture,
    ) -> Plan {
        let (rect, ppp) = (layout.view_rect, layout.pixels_per_point);
        let size = (target.width(), target.height());
        // The depth and stencil pictures cost a third of the frame on a software GPU (the stencil
        // one is nine full-window passes): paint them when what they show changed, when one is the
        // view, and otherwise (the camera moving) twice a second. The steps are timed with them:
        // a timed frame records a pass a step with timestamps, where the others record the whole
        // frame in one pass (timing every frame cost an H100 up to a third of a window's frame
        // with the panel). The panel's own picture (its small buffers among it) follows them.
        let key = (runner.knobs.clone(), viewing, self.buffers.size);
        let due = self.pictures_for.as_ref() != Some(&key)
            || self.pictures_at.elapsed().as_secs_f64() > PICTURES_EVERY_S;
        let viewport = [
            (rect.min.x * ppp).round(),
            (rect.min.y * ppp).round(),
            view_size.0 as f32,
            view_size.1 as f32,
        ];
        let fits = viewport[0] + viewport[2] <= size.0 as f32
            && viewport[1] + viewport[3] <= size.1 as f32;
        let panel_left = if fits {
            (viewport[0] + viewport[2]) as u32
        } else {
            0
        };
        let panel = self.panel_way(layout, (panel_left, size), due, fits, target);
        // The view, pixel for pixel. Where the view and the panel's picture tile the target, it is
        // copied, as the picture is: drawn by a render pass (with a bind group made each frame) it
        // cost an H100 most of the tenth of a millisecond the panel added to its frame. Otherwise
        // (half resolution, a view that does not fit) it is drawn, and the rest cleared. (Through
        // egui's shader the view cost a software GPU 29 ms a frame at 1280x720.)
        let copy_view = matches!(panel, PanelWay::Copied { .. })
            && self.scale() == 1
            && viewport[..2] == [0.0, 0.0]
            && (panel_left, size.1) == view_size;
        Plan {
            view_size,
            viewport,
            fits,
            panel_left,
            due,
            pictures: due || viewing.show != Show::Color,
            shown: match viewing.show {
                Show::Color | Show::Tests => 0,
                Show::Depth | Show::RawDepth => 1,
                Show::Stencil => 2,
                Show::Complexity => 3,
            },
            copy_view,
            panel,
        }
    }

    /// The panel. egui's shader costs a software GPU 12 ms a frame for the panel's 330x720 pixels
    /// alone, so the panel is painted into a picture of its own when it changed (a hover, a knob,
    /// the small buffers and the cost twice a second) and copied beside the view otherwise. What
    /// egui paints outside the panel (a dropdown's list, the FLIP difference over the view) is
    /// painted straight over the frame, as is everything where the target cannot be copied to.
    fn panel_way(
        &self,
        layout: &Layout,
        (panel_left, size): (u32, (u32, u32)),
        due: bool,
        fits: bool,
        target: &wgpu::Texture,
    ) -> PanelWay {
        let Some(fresh) = &layout.fresh else {
            // Idle: nothing new to paint but the small buffers when they are due.
            return PanelWay::Copied { repaint: due };
        };
        let ppp = layout.pixels_per_point;
        let panel = egui::Rect::from_min_max(
            egui::pos2(panel_left as f32 / ppp, 0.0),
            egui::pos2(size.0 as f32 / ppp, size.1 as f32 / ppp),
        );
        let inside = fresh.shapes.iter().all(|clipped| {
            let bounds = clipped
                .shape
                .visual_bounding_rect()
                .intersect(clipped.clip_rect);
            !bounds.is_positive() || panel.expand(0.5).contains_rect(bounds)
        });
        let copy_dst = target.usage().contains(wgpu::TextureUsages::COPY_DST);
        if !(fits && inside && copy_dst) {
            return PanelWay::Over;
        }
        let stale = due
            || !fresh.textures.is_empty()
            || self.panel_picture.as_ref().is_none_or(|picture| {
                picture.size != size
                    || picture.pixels_per_point != ppp
                    || picture.shapes != fresh.shapes
            });
        PanelWay::Copied { repaint: stale }
    }

    /// Phase 5: the lesson recorded into the three buffers, the view and the panel put on the
    /// target, all submitted. Returns the frame's steps and whether it was timed.
    fn record_and_submit(
        &mut self,
        runner: &Runner<L>,
        viewing: Viewing,
        plan: &Plan,
        layout: &mut Layout,
        target: &wgpu::Texture,
    ) -> Result<(Vec<&'static str>, bool)> {
        let [color, depth, stencil, complexity] = &self.buffers.views;
        let timer = match &mut self.timer {
            Some(timer) if plan.due => Some(timer.for_next_frame(&runner.gpu.device)?),
            _ => None,
        };
        let timed = timer.is_some();
        let mut request = FrameRequest::to(color).stop(viewing.stop);
        if plan.pictures {
            let raw_depth = viewing.show == Show::RawDepth;
            request = request.pictures([depth, stencil], raw_depth);
            request = request.complexity(complexity);
        }
        let request = match viewing.show {
            Show::Tests => request.show(Show::Tests, color).draw(viewing.draw),
            Show::Complexity => request.show(Show::Complexity, complexity),
            _ => request.show(Show::Color, color),
        };
        let request = request.timed(timer);
        let Recorded { mut encoder, steps } = runner.record(request)?;
        self.steps = Some(((runner.knobs.clone(), runner.camera), steps.clone()));
        if plan.due {
            self.pictures_for = Some((runner.knobs.clone(), viewing, self.buffers.size));
            self.pictures_at = Instant::now();
        }
        self.put_view(runner, &mut encoder, plan, target);
        let textures = match layout.fresh.as_mut() {
            Some(fresh) => std::mem::take(&mut fresh.textures),
            None => egui::TexturesDelta::default(),
        };
        self.painter.update_textures(&runner.gpu, &textures);
        self.put_panel(runner, &mut encoder, plan, layout, target);
        self.painter.submit(&runner.gpu, encoder, textures);
        Ok((steps, timed))
    }

    /// The view on the target: copied where it tiles the target with the panel, drawn otherwise.
    fn put_view(
        &self,
        runner: &Runner<L>,
        encoder: &mut wgpu::CommandEncoder,
        plan: &Plan,
        target: &wgpu::Texture,
    ) {
        if plan.copy_view {
            let whole = wgpu::Extent3d {
                width: plan.view_size.0,
                height: plan.view_size.1,
                depth_or_array_layers: 1,
            };
            let source = &self.buffers.textures[plan.shown];
            encoder.copy_texture_to_texture(source.as_image_copy(), target.as_image_copy(), whole);
        } else {
            runner.scene.blit.draw_in(
                &runner.gpu.device,
                encoder,
                &self.buffers.views[plan.shown],
                &target_view(target),
                plan.fits.then_some(plan.viewport),
                wgpu::FilterMode::Nearest,
            );
        }
    }

    /// The panel on the target: its picture (painted first where stale) copied, or painted over.
    fn put_panel(
        &mut self,
        runner: &Runner<L>,
        encoder: &mut wgpu::CommandEncoder,
        plan: &Plan,
        layout: &mut Layout,
        target: &wgpu::Texture,
    ) {
        let ppp = layout.pixels_per_point;
        let size = (target.width(), target.height());
        let shapes = layout.fresh.as_mut().map(|f| std::mem::take(&mut f.shapes));
        let PanelWay::Copied { repaint } = plan.panel else {
            self.panel_picture = None;
            let view = target_view(target);
            let shapes = shapes.unwrap_or_default();
            let ctx = &self.ctx;
            self.painter
                .paint(&runner.gpu, ctx, encoder, shapes, ppp, (&view, size));
            return;
        };
        if repaint {
            let picture = match self.panel_picture.take() {
                Some(picture) if picture.size == size => picture,
                _ => PanelPicture::new(&runner.gpu.device, target.format(), size),
            };
            // An idle frame repaints the picture's own shapes.
            let shapes = shapes.unwrap_or_else(|| picture.shapes.clone());
            let (ctx, view) = (&self.ctx, (&picture.view, size));
            self.painter
                .paint(&runner.gpu, ctx, encoder, shapes.clone(), ppp, view);
            self.panel_picture = Some(PanelPicture {
                shapes,
                pixels_per_point: ppp,
                ..picture
            });
        }
        if let Some(picture) = &self.panel_picture {
            picture.copy(encoder, target, plan.panel_left);
        }
    }

    /// Phase 6: what the frame cost, and the figures the panel shows.
    fn account(
        &mut self,
        start: Instant,
        runner: &Runner<L>,
        viewing: Viewing,
        (plan, step_count, timed): (&Plan, usize, bool),
    ) -> Result<()> {
        let cpu_ms = start.elapsed().as_secs_f64() * 1000.0;
        // The steps' times arrive when the GPU has run the frame, usually by the next one: the
        // window never waits for the GPU to report a statistic.
        let steps_ms = match &mut self.timer {
            Some(timer) => {
                if timed {
                    timer.submitted(step_count.min(viewing.stop.count()));
                }
                timer.latest(&runner.gpu.device)?.map(<[f64]>::to_vec)
            }
            None => None,
        };
        let frame_ms = self.frame_interval(start);
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
        if self.shown_cost.is_none() || plan.due || first_times {
            self.shown_cost = self.cost.clone();
            self.shown_camera = Some(runner.camera);
        }
        Ok(())
    }

    /// Frames drawn one after another (a drag, `--frames`) have a frame time and a rate: the mean
    /// interval over the last second and a half. A window that draws only on change has neither.
    fn frame_interval(&mut self, start: Instant) -> Option<f64> {
        self.presented.push_back(start);
        while self
            .presented
            .front()
            .is_some_and(|t| t.elapsed().as_secs_f64() > CONTINUOUS_S)
        {
            self.presented.pop_front();
        }
        (self.presented.len() > 2).then(|| {
            let (first, count) = (self.presented[0], self.presented.len() - 1);
            (start - first).as_secs_f64() * 1000.0 / count as f64
        })
    }

    /// Whether the panel shows something about to change, so that the window should draw again:
    /// a comparison under way, a pose the panel shows that is no longer the camera's, a story
    /// told for an older camera, step times awaited (a frame or two after a timed frame).
    fn still_changing(&self, runner: &Runner<L>) -> bool {
        let stale_camera = self.shown_camera != Some(runner.camera);
        let stale_story = self.picked.is_some()
            && self
                .story
                .as_ref()
                .is_none_or(|(told, _)| told.1 != runner.camera || told.2 != self.buffers.size);
        let awaiting_times = self.timer.is_some()
            && self
                .shown_cost
                .as_ref()
                .is_some_and(|shown| shown.steps_ms.is_none());
        self.verdicts.is_some() || stale_camera || stale_story || awaiting_times
    }
}

/// What the panel's pass paints over the view: the picked pixel's cross, the FLIP difference.
struct Marks {
    picked: Option<(u32, u32)>,
    /// How many of the view's pixels a side of one of the lesson's covers.
    scale: f32,
    difference: Option<(egui::TextureId, egui::Vec2)>,
}

impl Marks {
    fn paint(&self, ui: &egui::Ui, view_rect: egui::Rect) {
        let painter = ui.painter();
        // The picked pixel, marked with a cross in the view.
        if let Some((x, y)) = self.picked {
            let ppp = ui.ctx().pixels_per_point();
            let pixel = egui::vec2(x as f32 + 0.5, y as f32 + 0.5) * self.scale;
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
        if let Some((id, picture)) = self.difference {
            let uv = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(1.0, 1.0));
            let fit = (view_rect.width() / picture.x).min(view_rect.height() / picture.y);
            let rect = egui::Rect::from_center_size(view_rect.center(), picture * fit);
            painter.image(id, rect, uv, egui::Color32::WHITE);
        }
    }
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
pub(super) struct LaidOut {
    shown: Shown,
    pub(super) view_rect: egui::Rect,
    pub(super) pixels_per_point: f32,
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
