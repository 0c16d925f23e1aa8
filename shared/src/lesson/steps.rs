//! Seeing the frame being built: which step to stop after, which buffer to show, and the names the
//! film's files take. The steps themselves are the lesson's: see [`crate::Frame::step`].

use anyhow::{Result, bail};

/// Which buffer a screenshot or the window shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Show {
    /// The colour target: the picture.
    Color,
    /// The depth buffer, linearised to grey: black at the near plane, white at the far plane.
    Depth,
    /// The stencil buffer in false colour (0 dark, 1 white, 2 amber, 3 blue, ...).
    Stencil,
    /// The depth buffer's raw values as grey (almost all near white: see lesson 1).
    RawDepth,
    /// The depth complexity: how many fragments every draw of the frame brought to each pixel,
    /// counted by replaying the draws with a stencil that counts, painted as heat with its scale.
    Complexity,
    /// A step's test map: its draw's fragments (`--draw N`; every draw of the step without it)
    /// painted by their fate — passed both tests, failed the depth test, failed the stencil test,
    /// culled — over the picture as the step found it, dimmed.
    Tests,
}

impl Show {
    /// The three buffers a frame has.
    pub const BUFFERS: [Show; 3] = [Show::Color, Show::Depth, Show::Stencil];

    /// Everything a frame can be seen as, in the order `Tab` cycles them: the buffers, then the
    /// maps made by replaying its draws.
    pub const VIEWS: [Show; 5] = [
        Show::Color,
        Show::Depth,
        Show::Stencil,
        Show::Complexity,
        Show::Tests,
    ];

    /// What `--film` writes for every step: the buffers and the complexity (a test map is one
    /// draw's, asked for by its number).
    pub const FILM: [Show; 4] = [Show::Color, Show::Depth, Show::Stencil, Show::Complexity];

    /// The name `--show` takes.
    pub fn name(self) -> &'static str {
        match self {
            Show::Color => "color",
            Show::Depth => "depth",
            Show::Stencil => "stencil",
            Show::RawDepth => "raw-depth",
            Show::Complexity => "complexity",
            Show::Tests => "tests",
        }
    }

    /// Whether it is a map made by replaying the frame's draws (not a buffer the frame fills).
    pub fn is_map(self) -> bool {
        matches!(self, Show::Complexity | Show::Tests)
    }

    /// The next view (`Tab` in the window).
    pub fn next(self) -> Show {
        match self {
            Show::Color => Show::Depth,
            Show::Depth => Show::Stencil,
            Show::Stencil => Show::Complexity,
            Show::Complexity => Show::Tests,
            Show::Tests | Show::RawDepth => Show::Color,
        }
    }
}

/// Where the frame stops: after step `n` (1-based), or after its last step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Stop {
    #[default]
    Last,
    After(usize),
}

impl Stop {
    /// Parses `--step`: a step number from 1, or `last`.
    pub fn parse(text: &str) -> Result<Stop, String> {
        match text.trim() {
            "last" => Ok(Stop::Last),
            number => match number.parse::<usize>() {
                Ok(0) => Err("steps count from 1 (see --list-steps)".into()),
                Ok(n) => Ok(Stop::After(n)),
                Err(_) => Err("expected a step number from 1, or `last`".into()),
            },
        }
    }

    /// How many steps to record.
    pub fn count(self) -> usize {
        match self {
            Stop::Last => usize::MAX,
            Stop::After(n) => n,
        }
    }

    /// The step number (1-based) the frame stops after, in a frame of these steps; fails on a step
    /// past the end.
    pub fn resolve(self, steps: &[&str]) -> Result<usize> {
        match self {
            Stop::Last => Ok(steps.len()),
            Stop::After(n) if n <= steps.len() => Ok(n),
            Stop::After(n) => bail!(
                "there is no step {n}: this frame has {} steps (see --list-steps)",
                steps.len()
            ),
        }
    }
}

/// The numbered list `--list-steps` prints: `1. clear`, one step a line.
pub fn describe(steps: &[&str]) -> String {
    steps
        .iter()
        .enumerate()
        .map(|(i, name)| format!("{}. {name}\n", i + 1))
        .collect()
}

/// The file `--film` writes for step `number` (1-based) and a buffer:
/// `03-mark-the-mirror-stencil.png`.
pub fn film_file(number: usize, name: &str, show: Show) -> String {
    format!("{number:02}-{}-{}.png", slug(name), show.name())
}

/// A step's name as a file name: lower case, words joined by `-`, only letters and digits.
pub fn slug(name: &str) -> String {
    name.replace('\'', "")
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|word| !word.is_empty())
        .map(str::to_ascii_lowercase)
        .collect::<Vec<_>>()
        .join("-")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_parse_and_resolve() {
        assert_eq!(Stop::parse("last"), Ok(Stop::Last));
        assert_eq!(Stop::parse("2"), Ok(Stop::After(2)));
        assert!(Stop::parse("0").unwrap_err().contains("from 1"));
        assert!(Stop::parse("two").is_err());
        let steps = ["clear", "draw the room", "mark the mirror"];
        assert_eq!(Stop::Last.resolve(&steps).unwrap(), 3);
        assert_eq!(Stop::After(3).resolve(&steps).unwrap(), 3);
        let past = Stop::After(4).resolve(&steps).unwrap_err().to_string();
        assert!(past.contains("has 3 steps"), "{past}");
        assert_eq!(Stop::After(2).count(), 2);
        assert_eq!(Stop::Last.count(), usize::MAX, "every step, however many");
    }

    #[test]
    fn film_files_are_numbered_slugs() {
        assert_eq!(
            film_file(3, "mark the mirror", Show::Stencil),
            "03-mark-the-mirror-stencil.png"
        );
        assert_eq!(slug("draw the mirror's world"), "draw-the-mirrors-world");
        assert_eq!(describe(&["clear", "draw"]), "1. clear\n2. draw\n");
    }
}
