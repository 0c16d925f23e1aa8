//! The web edition's module: every lesson of the workbook in one WebAssembly module, for the book's
//! pages. The page's script (`book/theme/live.js`) calls [`start`] with its canvas and its lesson's
//! name, then drives the [`LiveLesson`] it gets: a frame per animation frame, the mouse, the
//! controls it builds from [`LiveLesson::describe`].
//!
//! The lessons are the native ones, unchanged; the runner is the framework's
//! (`workbook::app::web`). This crate only maps names to lessons and errors to JavaScript.
#![cfg(target_arch = "wasm32")]

use std::cell::RefCell;
use std::future::Future;
use std::pin::Pin;
use std::rc::Rc;

use lessons::{ForLesson, for_lesson};
use wasm_bindgen::prelude::*;
use workbook::Lesson;
use workbook::app::heap;
use workbook::app::web::{self, Backend, Page};

/// Counts the Rust heap's live bytes, which a long session in a page measures ([`heap_bytes`]).
#[global_allocator]
static ALLOCATOR: heap::Counting = heap::Counting;

/// A lesson running in a canvas. Shared, because a pixel's story is awaited: its promise holds the
/// lesson until the story is read, and the lesson is busy until then (the page waits for it).
#[wasm_bindgen]
pub struct LiveLesson {
    page: Rc<RefCell<Box<dyn Page>>>,
}

/// The names of every lesson this module runs, in the book's order.
#[wasm_bindgen]
pub fn lessons() -> Vec<String> {
    lessons::LESSONS
        .iter()
        .map(|name| name.to_string())
        .collect()
}

/// The bytes live on the module's Rust heap: what `cargo web-test --soak` watches over a long
/// session (the module's memory itself only grows, by 64 KiB pages, so it hides a slow leak).
#[wasm_bindgen]
pub fn heap_bytes() -> f64 {
    heap::live_bytes() as f64
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
    Ok(LiveLesson {
        page: Rc::new(RefCell::new(page)),
    })
}

#[wasm_bindgen]
impl LiveLesson {
    /// The page's controls as JSON (see `workbook::app::web::Page::describe`).
    pub fn describe(&self) -> Result<String, JsError> {
        self.with(|page| Ok(page.describe()))
    }

    /// Draws a frame.
    pub fn draw(&self) -> Result<(), JsError> {
        self.with(|page| page.draw())
    }

    /// Draws a frame and returns the canvas as a `data:image/png` URL.
    pub fn capture(&self) -> Result<String, JsError> {
        self.with(|page| page.capture())
    }

    pub fn resize(&self, width: u32, height: u32) -> Result<(), JsError> {
        self.with(|page| {
            page.resize(width, height);
            Ok(())
        })
    }

    pub fn orbit(&self, dx: f32, dy: f32) -> Result<(), JsError> {
        self.with(|page| {
            page.orbit(dx, dy);
            Ok(())
        })
    }

    pub fn zoom(&self, steps: f32) -> Result<(), JsError> {
        self.with(|page| {
            page.zoom(steps);
            Ok(())
        })
    }

    pub fn set_camera(&self, pose: &str) -> Result<(), JsError> {
        self.with(|page| page.set_camera(pose))
    }

    pub fn reset_camera(&self) -> Result<(), JsError> {
        self.with(|page| {
            page.reset_camera();
            Ok(())
        })
    }

    pub fn set_knob(&self, name: &str, value: &str) -> Result<(), JsError> {
        self.with(|page| page.set_knob(name, value))
    }

    /// Stops the frame after step `step` (from 1); 0 draws it whole.
    pub fn set_step(&self, step: usize) -> Result<(), JsError> {
        self.with(|page| page.set_step(step))
    }

    pub fn set_show(&self, buffer: &str) -> Result<(), JsError> {
        self.with(|page| page.set_show(buffer))
    }

    /// The draw (from 1) whose test map is shown, or every draw of the step with 0.
    pub fn set_draw(&self, draw: usize) -> Result<(), JsError> {
        self.with(|page| page.set_draw(draw))
    }

    /// The native command that draws the canvas's picture.
    pub fn command_line(&self) -> Result<String, JsError> {
        self.with(|page| Ok(page.command_line()))
    }

    /// The story of the canvas's pixel (`x`, `y`) through the whole frame, as `--pixel X,Y` tells
    /// it (a promise of its text).
    #[allow(
        clippy::await_holding_refcell_ref,
        reason = "the story holds the lesson until it is read: every other call in between is told \
                  that the lesson is busy (`with`), none panics"
    )]
    pub fn story(&self, x: u32, y: u32) -> js_sys::Promise {
        let page = self.page.clone();
        wasm_bindgen_futures::future_to_promise(async move {
            let mut page = page.try_borrow_mut().map_err(|_| busy())?;
            match page.story(x, y).await {
                Ok(text) => Ok(JsValue::from(text)),
                Err(failure) => Err(error(failure).into()),
            }
        })
    }
}

impl LiveLesson {
    /// Runs `work` on the lesson, unless a pixel's story holds it.
    fn with<T>(&self, work: impl FnOnce(&mut dyn Page) -> anyhow::Result<T>) -> Result<T, JsError> {
        let mut page = self.page.try_borrow_mut().map_err(|_| busy())?;
        work(page.as_mut()).map_err(error)
    }
}

/// What a call made while a pixel's story is read gets.
fn busy() -> JsError {
    JsError::new("the lesson is busy telling a pixel's story: wait for it")
}

/// An error as JavaScript sees it: one line, its causes after colons.
fn error(error: anyhow::Error) -> JsError {
    JsError::new(&format!("{error:#}"))
}
