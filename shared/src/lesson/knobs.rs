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

/// Every byte in decimal, `0` to `255`: the values of a stencil reference knob.
#[rustfmt::skip]
pub const BYTE_VALUES: &[&str] = &[
    "0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15",
    "16", "17", "18", "19", "20", "21", "22", "23", "24", "25", "26", "27", "28", "29", "30", "31",
    "32", "33", "34", "35", "36", "37", "38", "39", "40", "41", "42", "43", "44", "45", "46", "47",
    "48", "49", "50", "51", "52", "53", "54", "55", "56", "57", "58", "59", "60", "61", "62", "63",
    "64", "65", "66", "67", "68", "69", "70", "71", "72", "73", "74", "75", "76", "77", "78", "79",
    "80", "81", "82", "83", "84", "85", "86", "87", "88", "89", "90", "91", "92", "93", "94", "95",
    "96", "97", "98", "99", "100", "101", "102", "103", "104", "105", "106", "107", "108", "109", "110", "111",
    "112", "113", "114", "115", "116", "117", "118", "119", "120", "121", "122", "123", "124", "125", "126", "127",
    "128", "129", "130", "131", "132", "133", "134", "135", "136", "137", "138", "139", "140", "141", "142", "143",
    "144", "145", "146", "147", "148", "149", "150", "151", "152", "153", "154", "155", "156", "157", "158", "159",
    "160", "161", "162", "163", "164", "165", "166", "167", "168", "169", "170", "171", "172", "173", "174", "175",
    "176", "177", "178", "179", "180", "181", "182", "183", "184", "185", "186", "187", "188", "189", "190", "191",
    "192", "193", "194", "195", "196", "197", "198", "199", "200", "201", "202", "203", "204", "205", "206", "207",
    "208", "209", "210", "211", "212", "213", "214", "215", "216", "217", "218", "219", "220", "221", "222", "223",
    "224", "225", "226", "227", "228", "229", "230", "231", "232", "233", "234", "235", "236", "237", "238", "239",
    "240", "241", "242", "243", "244", "245", "246", "247", "248", "249", "250", "251", "252", "253", "254", "255",
];

/// Every byte in hexadecimal, `0x00` to `0xff`: the values of a stencil mask knob.
#[rustfmt::skip]
pub const MASK_VALUES: &[&str] = &[
    "0x00", "0x01", "0x02", "0x03", "0x04", "0x05", "0x06", "0x07", "0x08", "0x09", "0x0a", "0x0b", "0x0c", "0x0d", "0x0e", "0x0f",
    "0x10", "0x11", "0x12", "0x13", "0x14", "0x15", "0x16", "0x17", "0x18", "0x19", "0x1a", "0x1b", "0x1c", "0x1d", "0x1e", "0x1f",
    "0x20", "0x21", "0x22", "0x23", "0x24", "0x25", "0x26", "0x27", "0x28", "0x29", "0x2a", "0x2b", "0x2c", "0x2d", "0x2e", "0x2f",
    "0x30", "0x31", "0x32", "0x33", "0x34", "0x35", "0x36", "0x37", "0x38", "0x39", "0x3a", "0x3b", "0x3c", "0x3d", "0x3e", "0x3f",
    "0x40", "0x41", "0x42", "0x43", "0x44", "0x45", "0x46", "0x47", "0x48", "0x49", "0x4a", "0x4b", "0x4c", "0x4d", "0x4e", "0x4f",
    "0x50", "0x51", "0x52", "0x53", "0x54", "0x55", "0x56", "0x57", "0x58", "0x59", "0x5a", "0x5b", "0x5c", "0x5d", "0x5e", "0x5f",
    "0x60", "0x61", "0x62", "0x63", "0x64", "0x65", "0x66", "0x67", "0x68", "0x69", "0x6a", "0x6b", "0x6c", "0x6d", "0x6e", "0x6f",
    "0x70", "0x71", "0x72", "0x73", "0x74", "0x75", "0x76", "0x77", "0x78", "0x79", "0x7a", "0x7b", "0x7c", "0x7d", "0x7e", "0x7f",
    "0x80", "0x81", "0x82", "0x83", "0x84", "0x85", "0x86", "0x87", "0x88", "0x89", "0x8a", "0x8b", "0x8c", "0x8d", "0x8e", "0x8f",
    "0x90", "0x91", "0x92", "0x93", "0x94", "0x95", "0x96", "0x97", "0x98", "0x99", "0x9a", "0x9b", "0x9c", "0x9d", "0x9e", "0x9f",
    "0xa0", "0xa1", "0xa2", "0xa3", "0xa4", "0xa5", "0xa6", "0xa7", "0xa8", "0xa9", "0xaa", "0xab", "0xac", "0xad", "0xae", "0xaf",
    "0xb0", "0xb1", "0xb2", "0xb3", "0xb4", "0xb5", "0xb6", "0xb7", "0xb8", "0xb9", "0xba", "0xbb", "0xbc", "0xbd", "0xbe", "0xbf",
    "0xc0", "0xc1", "0xc2", "0xc3", "0xc4", "0xc5", "0xc6", "0xc7", "0xc8", "0xc9", "0xca", "0xcb", "0xcc", "0xcd", "0xce", "0xcf",
    "0xd0", "0xd1", "0xd2", "0xd3", "0xd4", "0xd5", "0xd6", "0xd7", "0xd8", "0xd9", "0xda", "0xdb", "0xdc", "0xdd", "0xde", "0xdf",
    "0xe0", "0xe1", "0xe2", "0xe3", "0xe4", "0xe5", "0xe6", "0xe7", "0xe8", "0xe9", "0xea", "0xeb", "0xec", "0xed", "0xee", "0xef",
    "0xf0", "0xf1", "0xf2", "0xf3", "0xf4", "0xf5", "0xf6", "0xf7", "0xf8", "0xf9", "0xfa", "0xfb", "0xfc", "0xfd", "0xfe", "0xff",
];

/// The byte a [`BYTE_VALUES`] or [`MASK_VALUES`] knob value stands for.
///
/// # Panics
/// On a value outside those lists: knob values are checked before a lesson sees them.
pub fn byte(value: &str) -> u8 {
    let parsed = match value.strip_prefix("0x") {
        Some(hex) => u8::from_str_radix(hex, 16),
        None => value.parse(),
    };
    parsed.unwrap_or_else(|_| panic!("not a byte: {value}"))
}

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
        let values = match knob.values {
            [first, .., last] if knob.values.len() > 12 => {
                format!("{first} to {last} ({} values)", knob.values.len())
            }
            values => values.join(", "),
        };
        out += &format!(
            "[{}] {}: {}\n    values: {values} (default {})\n",
            index + 1,
            knob.name,
            knob.meaning,
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
    fn a_knob_set_off_is_not_on() {
        let knobs = Knobs::from_settings(KNOBS, &["write=off"]).unwrap();
        assert!(!knobs.is_on("write"));
    }

    /// `--list-knobs`: each knob numbered by its key, its values listed, a long run of values
    /// (lesson 9's texture sizes) shortened to its ends and count; twelve are still listed.
    #[test]
    fn the_knob_table_lists_each_knob_and_shortens_long_runs() {
        let table = describe(KNOBS);
        assert_eq!(
            table.lines().collect::<Vec<_>>(),
            [
                "[1] depth: compare",
                "    values: never, less, equal, less-equal, greater, not-equal, greater-equal, \
                 always (default less)",
                "[2] write: write",
                "    values: on, off (default on)",
            ]
        );
        const TWELVE: &[&str] = &[
            "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12",
        ];
        const THIRTEEN: &[&str] = &[
            "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13",
        ];
        let with = |values| {
            describe(&[Knob {
                name: "n",
                values,
                default: "1",
                meaning: "a number",
            }])
        };
        assert!(with(TWELVE).contains("values: 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 (default 1)"));
        assert!(with(THIRTEEN).contains("values: 1 to 13 (13 values) (default 1)"));
        assert_eq!(describe(&[]), "This lesson has no knobs.\n");
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
    fn byte_tables_hold_every_byte() {
        for v in 0..=255u8 {
            assert_eq!(byte(BYTE_VALUES[v as usize]), v);
            assert_eq!(byte(MASK_VALUES[v as usize]), v);
        }
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
