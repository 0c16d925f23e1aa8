//! The web edition's module: every lesson of the workbook in one WebAssembly module, for the book's
//! pages. The page's script (`book/theme/live.js`) calls [`start`] with its canvas and its lesson's
//! name, then drives the [`LiveLesson`] it gets: a frame per animation frame, the mouse, the
//! controls it builds from [`LiveLesson::describe`].
//!
//! The lessons are the native ones, unchanged; the runner is the framework's
//! (`workbook::app::web`). This crate only maps names to lessons and errors to JavaScript.
#![cfg(target_arch = "wasm32")]

use std::future::Future;
use std::pin::Pin;

use lessons::{ForLesson, for_lesson};
use wasm_bindgen::prelude::*;
use workbook::Lesson;
use workbook::app::web::{self, Backend, Page};

/// A lesson running in a canvas.
#[wasm_bindgen]
pub struct LiveLesson {
    page: Box<dyn Page>,
}

/// The names of every lesson this module runs, in the book's order.
#[wasm_bindgen]
pub fn lessons() -> Vec<String> {
    lessons::LESSONS
        .iter()
        .map(|name| name.to_string())
        .collect()
}

/// Starts the lesson called `lesson` in `canvas`, its room built from the files at the URL `assets`;
/// `backend` is `webgpu`, `webgl2`, or anything else for WebGPU where the browser has it.
#[wasm_bindgen]
pub async fn start(
    canvas: web_sys::HtmlCanvasElement,
    lesson: String,
    assets: String,
    backend: String,
) -> Result<LiveLesson, JsError> {
    std::panic::set_hook(Box::new(|panic| {
        web_sys::console::error_1(&panic.to_string().into());
    }));
    type Starting = Pin<Box<dyn Future<Output = anyhow::Result<Box<dyn Page>>>>>;
    struct Start(web_sys::HtmlCanvasElement, String, Backend);
    impl ForLesson for Start {
        type Output = Starting;
        fn run<L: Lesson>(self) -> Starting {
            let Start(canvas, assets, backend) = self;
            Box::pin(async move { web::start::<L>(canvas, &assets, backend).await })
        }
    }
    let starting =
        for_lesson(&lesson, Start(canvas, assets, Backend::parse(&backend))).map_err(error)?;
    let page = starting.await.map_err(error)?;
    Ok(LiveLesson { page })
}

#[wasm_bindgen]
impl LiveLesson {
    /// The page's controls as JSON (see `workbook::app::web::Page::describe`).
    pub fn describe(&self) -> String {
        self.page.describe()
    }

    /// Draws a frame.
    pub fn draw(&mut self) -> Result<(), JsError> {
        self.page.draw().map_err(error)
    }

    /// Draws a frame and returns the canvas as a `data:image/png` URL.
    pub fn capture(&mut self) -> Result<String, JsError> {
        self.page.capture().map_err(error)
    }

    pub fn resize(&mut self, width: u32, height: u32) {
        self.page.resize(width, height);
    }

    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.page.orbit(dx, dy);
    }

    pub fn zoom(&mut self, steps: f32) {
        self.page.zoom(steps);
    }

    pub fn set_camera(&mut self, pose: &str) -> Result<(), JsError> {
        self.page.set_camera(pose).map_err(error)
    }

    pub fn reset_camera(&mut self) {
        self.page.reset_camera();
    }

    pub fn set_knob(&mut self, name: &str, value: &str) -> Result<(), JsError> {
        self.page.set_knob(name, value).map_err(error)
    }

    /// Stops the frame after step `step` (from 1); 0 draws it whole.
    pub fn set_step(&mut self, step: usize) -> Result<(), JsError> {
        self.page.set_step(step).map_err(error)
    }

    pub fn set_show(&mut self, buffer: &str) -> Result<(), JsError> {
        self.page.set_show(buffer).map_err(error)
    }

    /// The native command that draws the canvas's picture.
    pub fn command_line(&self) -> String {
        self.page.command_line()
    }
}

/// An error as JavaScript sees it: one line, its causes after colons.
fn error(error: anyhow::Error) -> JsError {
    JsError::new(&format!("{error:#}"))
}
