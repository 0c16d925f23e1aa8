//! The framework of the Mirror & Stencil Workbook.
//!
//! Everything that is not a lesson lives here once, in four parts and the lesson contract:
//!
//! - [`lesson`]: the trait a chapter implements, its frame of named steps, its knobs;
//! - [`app`]: the command line, the window and headless runners;
//! - [`gpu`]: device setup, the named pipeline recipes, the buffer views;
//! - [`room`]: the scene of Luna's Mirror demo, meshes, textures, the camera;
//! - [`math`]: the reflection matrix and the stencil model, on the CPU;
//! - [`book`]: the book's screenshots and how a lesson is compared with them (`--check`, the panel).
//!
//! A lesson implements [`Lesson`] and its `main` is `workbook::main::<TheLesson>()`.

pub mod app;
pub mod book;
pub mod gpu;
pub mod lesson;
pub mod math;
pub mod room;

#[cfg(not(target_arch = "wasm32"))]
pub use app::cli::main;
pub use gpu::Gpu;
pub use gpu::pass::Pass;
pub use gpu::states::Recipe;
pub use lesson::knobs::{Knob, Knobs};
pub use lesson::steps::{Show, Stop};
pub use lesson::{Frame, Lesson};
pub use room::scene::Scene;

pub use glam;
pub use wgpu;
