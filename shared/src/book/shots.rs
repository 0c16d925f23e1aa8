//! The book's screenshots as a lesson sees them: `cargo screenshots` writes, beside the images, the
//! list `shots.txt` — one line per picture: its name, its lesson, and the command-line arguments that
//! make it. The window's panel reads it to say when its picture is one of the book's, and `--check`
//! to render a learner's lesson as the book did. (The list is made from the tests' catalogue,
//! `tests/src/shots.rs`, and a test fails when it is out of date.)

use std::path::{Path, PathBuf};

use anyhow::{Context, Result, bail};

use crate::app::args::Args;
use crate::lesson::Lesson;
use crate::lesson::knobs::Knobs;
use crate::lesson::steps::{Show, Stop};
use crate::room::camera::Camera;

/// The size of every screenshot in the book: small enough to keep the repository light, large enough
/// to see a fringe.
pub const SIZE: (u32, u32) = (800, 450);

/// The list's file name, in the images folder.
pub const LIST: &str = "shots.txt";

/// The book's images: `book/src/images` in the workspace.
pub fn images() -> PathBuf {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR"));
    shared.parent().unwrap_or(shared).join("book/src/images")
}

/// One line of the list.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BookShot {
    /// The picture is `<name>.png`.
    pub name: String,
    /// The lesson's name (its package).
    pub lesson: String,
    /// What to add to `cargo run -p <lesson> --` to make it (`--size` included).
    pub arguments: Vec<String>,
    /// Why the picture is the driver's own choice (`z-fighting`), where it is: then it is never
    /// compared pixel for pixel, on any machine (the tests judge it by what it teaches). In the
    /// list, a comment at the line's end: `# driver-dependent: z-fighting`.
    pub driver_dependent: Option<String>,
}

/// The list's mark of a driver-dependent picture, after the arguments.
const DRIVER_DEPENDENT: &str = "# driver-dependent: ";

/// What a picture shows: the settings the window can be in, compared as a whole.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    pub knobs: Knobs,
    pub camera: Camera,
    pub show: Show,
    pub stop: Stop,
    /// The draw a test map shows (its index in the step; `None`: every draw of the step).
    pub draw: Option<usize>,
}

impl Setting {
    /// The arguments of lesson `L`'s command line that make this setting: those that differ from
    /// the lesson's defaults.
    pub fn arguments<L: Lesson>(&self) -> Vec<String> {
        let mut arguments = Vec::new();
        for setting in self.knobs.changed().split_whitespace() {
            arguments.extend(["--set".to_string(), setting.to_string()]);
        }
        if self.camera != L::CAMERA {
            arguments.extend(["--camera".to_string(), self.camera.to_string()]);
        }
        if self.show != L::SHOWS {
            arguments.extend(["--show".to_string(), self.show.name().to_string()]);
        }
        if let Stop::After(number) = self.stop {
            arguments.extend(["--step".to_string(), number.to_string()]);
        }
        if let (Show::Tests, Some(draw)) = (self.show, self.draw) {
            arguments.extend(["--draw".to_string(), (draw + 1).to_string()]);
        }
        arguments
    }
}

impl BookShot {
    /// The list's line for this shot.
    pub fn line(&self) -> String {
        let mut words = vec![self.name.as_str(), self.lesson.as_str()];
        words.extend(self.arguments.iter().map(String::as_str));
        let line = words.join(" ");
        match &self.driver_dependent {
            Some(reason) => format!("{line}  {DRIVER_DEPENDENT}{reason}"),
            None => line,
        }
    }

    /// The reference picture.
    pub fn path(&self) -> PathBuf {
        images().join(format!("{}.png", self.name))
    }

    /// The arguments, parsed as the lesson's command line parses them.
    pub fn args(&self) -> Result<Args> {
        use clap::Parser;
        let words =
            std::iter::once(self.lesson.as_str()).chain(self.arguments.iter().map(|a| a.as_str()));
        Args::try_parse_from(words)
            .with_context(|| format!("the book's screenshot `{}` has bad arguments", self.name))
    }

    /// The shot's settings for lesson `L`, with `overrides` (`--set` values) applied after its own.
    pub fn setting<L: Lesson>(&self, overrides: &[String]) -> Result<Setting> {
        let args = self.args()?;
        let settings: Vec<&String> = args.settings.iter().chain(overrides).collect();
        Ok(Setting {
            knobs: Knobs::from_settings(L::KNOBS, &settings)?,
            camera: args.camera::<L>()?,
            show: args.show::<L>(),
            stop: args.step,
            draw: args.draw,
        })
    }
}

/// Reads the list from `dir`.
pub fn read(dir: &Path) -> Result<Vec<BookShot>> {
    let path = dir.join(LIST);
    let text = std::fs::read_to_string(&path).with_context(|| {
        format!(
            "cannot read the book's list of screenshots `{}`",
            path.display()
        )
    })?;
    text.lines()
        .filter(|line| !line.trim().is_empty() && !line.starts_with('#'))
        .map(|line| {
            let (line, driver_dependent) = match line.split_once(DRIVER_DEPENDENT) {
                Some((line, reason)) => (line, Some(reason.trim().to_string())),
                None => (line, None),
            };
            let mut words = line.split_whitespace().map(str::to_string);
            match (words.next(), words.next()) {
                (Some(name), Some(lesson)) => Ok(BookShot {
                    name,
                    lesson,
                    arguments: words.collect(),
                    driver_dependent,
                }),
                _ => bail!(
                    "{}: a line without a name and a lesson: `{line}`",
                    path.display()
                ),
            }
        })
        .collect()
}

/// The book's screenshots of lesson `L`.
pub fn of_lesson<L: Lesson>() -> Result<Vec<BookShot>> {
    let shots = read(&images())?;
    Ok(shots
        .into_iter()
        .filter(|shot| shot.lesson == L::NAME)
        .collect())
}

/// The list's text for these shots, with its header.
pub fn list_text(shots: &[BookShot]) -> String {
    let mut text = String::from(
        "# The book's screenshots: name, lesson, and the arguments of `cargo run -p <lesson> --` that\n\
         # make each. Written by `cargo screenshots` from tests/src/shots.rs; read by the window's\n\
         # panel (\"compare with the book\") and by `--check`. A picture marked driver-dependent is the\n\
         # GPU's own choice (z-fighting): they say so and do not compare it.\n",
    );
    for shot in shots {
        text += &shot.line();
        text.push('\n');
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_round_trip() {
        let shot = BookShot {
            name: "a-b".into(),
            lesson: "a".into(),
            arguments: vec![
                "--size".into(),
                "800x450".into(),
                "--set".into(),
                "k=v".into(),
            ],
            driver_dependent: None,
        };
        let fighting = BookShot {
            name: "a-c".into(),
            driver_dependent: Some("z-fighting".into()),
            ..shot.clone()
        };
        let dir = std::env::temp_dir().join(format!("book-shots-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let shots = [shot, fighting];
        std::fs::write(dir.join(LIST), list_text(&shots)).unwrap();
        assert_eq!(read(&dir).unwrap(), shots);
        std::fs::write(dir.join(LIST), "lonely\n").unwrap();
        assert!(read(&dir).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
