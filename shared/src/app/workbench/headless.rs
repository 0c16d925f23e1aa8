//! The workbench without a window: the panel and the view drawn into a texture, frame after frame,
//! with no input. The benchmark times it against the lesson alone on machines without a display (a
//! real GPU's among them), and tests read what the panel's cost section would say.

use anyhow::{Context, Result};

use crate::app::args::Args;
use crate::app::runner::Runner;
use crate::gpu::{Gpu, HEADLESS_FORMAT, target_texture};
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};

use super::panel::Cost;
use super::{Viewing, Workbench};

pub struct HeadlessWorkbench<L: Lesson> {
    pub runner: Runner<L>,
    pub workbench: Workbench<L>,
    pub viewing: Viewing,
    target: wgpu::Texture,
    size: (u32, u32),
    start: std::time::Instant,
}

impl<L: Lesson> HeadlessWorkbench<L> {
    /// The lesson as `args` set it up (`--size`, `--set`, `--camera`, `--ui-scale`,
    /// `--backend`), its window's surface replaced by a texture of the headless colour format.
    pub fn new(args: &Args) -> Result<Self> {
        let scene = args.scene().start_reading();
        let gpu = Gpu::shared_headless(args.backend.as_deref(), args.verbose)?;
        let knobs = Knobs::from_settings(L::KNOBS, &args.settings)?;
        let runner = Runner::<L>::new(
            gpu,
            HEADLESS_FORMAT,
            scene,
            knobs,
            args.camera::<L>()?,
            args.size,
        )?;
        let workbench = Workbench::new(&runner, args)?;
        // As a window's surface where it can be copied to (see `Workbench::draw`).
        let target = target_texture(
            &runner.gpu.device,
            "headless workbench target",
            HEADLESS_FORMAT,
            args.size,
            wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST,
        );
        Ok(Self {
            runner,
            workbench,
            viewing: Viewing {
                stop: args.step,
                show: args.show::<L>(),
                draw: args.draw,
            },
            target,
            size: args.size,
            start: std::time::Instant::now(),
        })
    }

    /// Draws one frame as the window would (the panel and the view, or with the panel hidden the
    /// lesson alone) and waits for the GPU to finish it, as a window waits for the display.
    /// Returns the CPU's time to build, record and submit it (egui's work included), in ms.
    pub fn frame(&mut self) -> Result<f64> {
        self.frame_with(Vec::new())
    }

    /// [`Self::frame`] with egui's input events since the last frame (a pointer moved, a click).
    pub fn frame_with(&mut self, events: Vec<egui::Event>) -> Result<f64> {
        let gpu = self.runner.gpu.clone();
        gpu.scoped(|| {
            let start = std::time::Instant::now();
            if self.workbench.visible {
                let points = egui::vec2(self.size.0 as f32, self.size.1 as f32);
                let input = egui::RawInput {
                    screen_rect: Some(egui::Rect::from_min_size(egui::Pos2::ZERO, points)),
                    time: Some(self.start.elapsed().as_secs_f64()),
                    events,
                    ..Default::default()
                };
                let (runner, viewing) = (&mut self.runner, &mut self.viewing);
                self.workbench.draw(input, runner, viewing, &self.target)?;
            } else {
                let view = self.target.create_view(&Default::default());
                let (runner, viewing) = (&mut self.runner, self.viewing);
                self.workbench
                    .draw_alone(runner, viewing, &view, self.size)?;
            }
            let recorded = start.elapsed().as_secs_f64() * 1e3;
            self.runner
                .gpu
                .device
                .poll(wgpu::PollType::wait_indefinitely())
                .context("waiting for the GPU failed")?;
            Ok(recorded)
        })
    }

    /// The last frame's picture, as the window would show it: the view and the panel beside it.
    pub fn picture(&self) -> Result<image::RgbaImage> {
        let all = wgpu::TextureAspect::All;
        let bytes = crate::app::headless::read_texture(&self.runner.gpu, &self.target, all, 4)?;
        image::RgbaImage::from_raw(self.size.0, self.size.1, bytes)
            .context("the workbench's picture has the wrong size")
    }

    /// What the panel's cost section shows after the last frame.
    pub fn cost(&self) -> Option<&Cost> {
        self.workbench.cost()
    }

    /// Shows or hides the panel, as `H` does.
    pub fn set_panel(&mut self, shown: bool) {
        self.workbench.visible = shown;
    }

    /// Where the frame stops and what it shows (with the draw a test map shows).
    pub fn view(&mut self, stop: Stop, show: Show, draw: Option<usize>) {
        self.viewing = Viewing { stop, show, draw };
    }
}
