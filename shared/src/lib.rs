//! The framework of the Mirror & Stencil Workbook.
//!
//! Everything that is not a lesson lives here once: GPU setup, the window and headless runners, the
//! one command line, the room of Luna's Mirror demo, meshes and textures, and the named pipeline
//! recipes. A lesson implements [`Lesson`] and its `main` is `workbook::main::<TheLesson>()`.

pub mod camera;
pub mod cli;
pub mod gpu;
pub mod headless;
pub mod knobs;
pub mod lesson;
pub mod mesh;
pub mod mirror;
pub mod reflect;
pub mod runner;
pub mod scene;
pub mod shapes;
pub mod states;
pub mod stencil;
pub mod steps;
pub mod testing;
pub mod texture;
pub mod views;
pub mod window;

pub use cli::main;
pub use gpu::Gpu;
pub use knobs::{Knob, Knobs};
pub use lesson::{Frame, Lesson};
pub use scene::Scene;
pub use states::Recipe;
pub use steps::{Show, Stop};

pub use glam;
pub use wgpu;
