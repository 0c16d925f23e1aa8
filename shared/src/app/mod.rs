//! The application around a lesson: the one command line, the window (with its workbench panel) and
//! headless runners, and the
//! helpers the lessons' command-line tests share. Both runners drive a lesson through [`runner`].

pub mod args;
#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
#[cfg(not(target_arch = "wasm32"))]
pub mod headless;
pub mod heap;
#[cfg(not(target_arch = "wasm32"))]
pub mod output;
pub mod pixel;
pub mod runner;
pub mod testing;
#[cfg(target_arch = "wasm32")]
pub mod web;
#[cfg(not(target_arch = "wasm32"))]
pub mod window;
#[cfg(not(target_arch = "wasm32"))]
pub mod workbench;
