//! The application around a lesson: the one command line, the window (with its workbench panel) and
//! headless runners, and the
//! helpers the lessons' command-line tests share. Both runners drive a lesson through [`runner`].

pub mod args;
pub mod cli;
pub mod headless;
pub mod runner;
pub mod testing;
pub mod window;
pub mod workbench;
