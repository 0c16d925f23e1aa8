//! Every lesson by its package name, in the book's order: the one place that lists the lessons and
//! maps a lesson's name to its type, for the tools that take a name (`cargo screenshots`, the
//! benchmark, the tests) and for the web edition's module, which runs whichever lesson its page names.
//!
//! The list is this crate's `[dependencies]` (Cargo.toml): a lesson is added by its folder and one
//! line there. build.rs reads those lines into one call of `lessons!` (below); each lesson's crate is
//! re-exported here (`lessons::two_mirrors`), so that no other crate names a lesson's crate.

use anyhow::{Result, bail};
use workbook::Lesson;

/// Something to do with a lesson's type, given its package name: see [`for_lesson`].
pub trait ForLesson {
    type Output;
    fn run<L: Lesson>(self) -> Self::Output;
}

/// Makes [`LESSONS`], [`for_lesson`], the re-exports and, with the feature `exercises`, the
/// exercise solutions' modules, from the lessons as build.rs writes them: each lesson's package
/// name, crate, lesson type and its solutions (`exercise_K "path/to/exercise-N-K.rs"`).
macro_rules! lessons {
    ($($name:literal $krate:ident $lesson:ident [$($exercise:ident $file:tt)*],)*) => {
        /// Every lesson by package name, in the book's order.
        pub const LESSONS: &[&str] = &[$($name),*];

        $(pub use ::$krate;)*

        /// Runs `task` with the lesson called `lesson`.
        pub fn for_lesson<T: ForLesson>(lesson: &str, task: T) -> Result<T::Output> {
            Ok(match lesson {
                $($name => task.run::<$krate::$lesson>(),)*
                other => bail!("there is no lesson called `{other}`"),
            })
        }

        /// Every lesson's exercise solutions, `exercises::two_mirrors::exercise_1` the one of
        /// chapters/11-two-mirrors/examples/exercise-11-1.rs (their `main` goes unused).
        #[cfg(feature = "exercises")]
        pub mod exercises {
            $(pub mod $krate {
                $(#[path = $file] #[allow(dead_code)] pub mod $exercise;)*
            })*
        }
    };
}

include!(concat!(env!("OUT_DIR"), "/lessons.rs"));
