//! Knobs: the settings a learner turns to see a lesson go wrong and right again.
//!
//! A knob is data — a name, its allowed values, a default and a one-line meaning — so the command line
//! (`--set name=value`, `--list-knobs`), the keyboard (key `1` cycles the first knob, `2` the second,
//! …; with Shift, backwards), the window title and the book all read the same list.

use anyhow::{Result, bail};

/// One setting of a lesson.
#[derive(Debug, PartialEq, Eq)]
pub struct Knob {
    /// The name used by `--set name=value`, e.g. `depth`.
    pub name: &'static str,
    /// Every allowed value, in the order the keyboard cycles them.
    pub values: &'static [&'static str],
    /// The value that gives the correct picture.
    pub default: &'static str,
    /// One line that says what the knob changes.
    pub meaning: &'static str,
}

/// The eight comparison functions of the depth and stencil tests, by the names the book uses.
pub const COMPARE_VALUES: &[&str] = &[
    "never",
    "less",
    "equal",
    "less-equal",
    "greater",
    "not-equal",
    "greater-equal",
    "always",
];

/// Values of a knob that switches something on or off.
pub const ON_OFF: &[&str] = &["on", "off"];

/// The chosen value of every knob of a lesson.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Knobs {
    knobs: &'static [Knob],
    chosen: Vec<usize>,
}

impl Knobs {
    /// Every knob at its default.
    pub fn defaults(knobs: &'static [Knob]) -> Self {
        let chosen = knobs
            .iter()
            .map(|knob| {
                knob.values
                    .iter()
                    .position(|value| *value == knob.default)
                    .unwrap_or(0)
            })
            .collect();
        Self { knobs, chosen }
    }

    /// The defaults, changed by `name=value` settings (as given to `--set`).
    pub fn from_settings<S: AsRef<str>>(knobs: &'static [Knob], settings: &[S]) -> Result<Self> {
        let mut this = Self::defaults(knobs);
        for setting in settings {
            this.apply(setting.as_ref())?;
        }
        Ok(this)
    }

    /// Applies one `name=value` setting.
    pub fn apply(&mut self, setting: &str) -> Result<()> {
        let Some((name, value)) = setting.split_once('=') else {
            bail!("--set expects NAME=VALUE, got `{setting}`");
        };
        let (name, value) = (name.trim(), value.trim());
        let Some(index) = self.knobs.iter().position(|knob| knob.name == name) else {
            let names: Vec<_> = self.knobs.iter().map(|knob| knob.name).collect();
            if names.is_empty() {
                bail!("unknown knob `{name}`: this lesson has no knobs");
            }
            bail!(
                "unknown knob `{name}`: this lesson's knobs are {}",
                names.join(", ")
            );
        };
        let knob = &self.knobs[index];
        let Some(position) = knob.values.iter().position(|v| *v == value) else {
            bail!(
                "knob `{name}` cannot be `{value}`: choose one of {}",
                knob.values.join(", ")
            );
        };
        self.chosen[index] = position;
        Ok(())
    }

    /// The value of the knob called `name`.
    ///
    /// # Panics
    /// If the lesson has no such knob: that is a bug in the lesson, not bad input.
    pub fn get(&self, name: &str) -> &'static str {
        let index = self
            .knobs
            .iter()
            .position(|knob| knob.name == name)
            .unwrap_or_else(|| panic!("the lesson asked for a knob it does not declare: {name}"));
        self.knobs[index].values[self.chosen[index]]
    }

    /// Whether the knob called `name` is `on`.
    pub fn is_on(&self, name: &str) -> bool {
        self.get(name) == "on"
    }

    /// Moves knob number `index` (0-based) one value forward, or back, wrapping around.
    /// Returns false when there is no such knob.
    pub fn cycle(&mut self, index: usize, forward: bool) -> bool {
        let Some(knob) = self.knobs.get(index) else {
            return false;
        };
        let count = knob.values.len();
        let step = if forward { 1 } else { count - 1 };
        self.chosen[index] = (self.chosen[index] + step) % count;
        true
    }

    /// The knobs with their values, as `name=value` pairs.
    pub fn pairs(&self) -> impl Iterator<Item = (&'static str, &'static str)> + '_ {
        self.knobs
            .iter()
            .zip(&self.chosen)
            .map(|(knob, &chosen)| (knob.name, knob.values[chosen]))
    }

    /// Only the knobs that differ from their default, as `name=value name=value`.
    pub fn changed(&self) -> String {
        self.pairs()
            .zip(self.knobs)
            .filter(|((_, value), knob)| *value != knob.default)
            .map(|((name, value), _)| format!("{name}={value}"))
            .collect::<Vec<_>>()
            .join(" ")
    }
}

/// The table `--list-knobs` prints: number (its key), name, values, default, meaning.
pub fn describe(knobs: &[Knob]) -> String {
    if knobs.is_empty() {
        return "This lesson has no knobs.\n".to_string();
    }
    let mut out = String::new();
    for (index, knob) in knobs.iter().enumerate() {
        out += &format!(
            "[{}] {}: {}\n    values: {} (default {})\n",
            index + 1,
            knob.name,
            knob.meaning,
            knob.values.join(", "),
            knob.default
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const KNOBS: &[Knob] = &[
        Knob {
            name: "depth",
            values: COMPARE_VALUES,
            default: "less",
            meaning: "compare",
        },
        Knob {
            name: "write",
            values: ON_OFF,
            default: "on",
            meaning: "write",
        },
    ];

    #[test]
    fn defaults_and_settings() {
        let knobs = Knobs::from_settings(KNOBS, &["depth=always"]).unwrap();
        assert_eq!(knobs.get("depth"), "always");
        assert!(knobs.is_on("write"));
        assert_eq!(knobs.changed(), "depth=always");
    }

    #[test]
    fn bad_settings_say_what_is_allowed() {
        let err = Knobs::from_settings(KNOBS, &["colour=red"]).unwrap_err();
        assert!(err.to_string().contains("depth, write"), "{err}");
        let err = Knobs::from_settings(KNOBS, &["depth=sometimes"]).unwrap_err();
        assert!(err.to_string().contains("never, less"), "{err}");
        assert!(Knobs::from_settings(KNOBS, &["depth"]).is_err());
    }

    #[test]
    fn cycling_wraps_both_ways() {
        let mut knobs = Knobs::defaults(KNOBS);
        assert!(knobs.cycle(1, true));
        assert_eq!(knobs.get("write"), "off");
        assert!(knobs.cycle(1, true));
        assert_eq!(knobs.get("write"), "on");
        assert!(knobs.cycle(0, false));
        assert_eq!(knobs.get("depth"), "never");
        assert!(!knobs.cycle(2, true));
    }
}
