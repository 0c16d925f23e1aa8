//! The book's pixel stories: one pixel of a lesson's frame told step by step and draw by draw
//! (`--pixel`), beside the lesson's picture with that pixel marked. `cargo screenshots` writes the
//! text and the picture; the tests tell each story again and compare.

use std::path::PathBuf;

use anyhow::{Context, Result};
use image::{Rgba, RgbaImage};
use workbook::app::headless::PngSize;
use workbook::lesson::story::Story;

use crate::shots;

/// One story the book tells.
pub struct BookStory {
    /// The files' name: `images/stories/<name>.{png,txt}`.
    pub name: &'static str,
    pub lesson: &'static str,
    pub settings: &'static [&'static str],
    /// The pixel, at [`SIZE`].
    pub pixel: (u32, u32),
}

/// The size of the pictures and of the frames the stories are told in.
pub const SIZE: (u32, u32) = (640, 360);

/// Every story the book tells, in the book's order.
pub const STORIES: &[BookStory] = &[
    BookStory {
        name: "stencil-basics-masked",
        lesson: "stencil-basics",
        settings: &["reference=3", "read-mask=0x01"],
        pixel: (220, 150),
    },
    BookStory {
        name: "mark-mirror-on-the-mirror",
        lesson: "mark-mirror",
        settings: &[],
        pixel: (320, 120),
    },
    BookStory {
        name: "mark-mirror-behind-the-crate",
        lesson: "mark-mirror",
        settings: &[],
        pixel: (400, 222),
    },
    BookStory {
        name: "transparent-mirror-blend",
        lesson: "transparent-mirror",
        settings: &[],
        pixel: (335, 160),
    },
    BookStory {
        name: "planar-shadow-no-double-blend",
        lesson: "planar-shadow",
        settings: &[],
        pixel: (340, 260),
    },
    BookStory {
        name: "two-mirrors-three-deep",
        lesson: "two-mirrors",
        settings: &[],
        pixel: (420, 110),
    },
    BookStory {
        name: "outline-in-the-mirror",
        lesson: "outline",
        settings: &[],
        pixel: (340, 150),
    },
    BookStory {
        name: "depth-complexity-through-the-water",
        lesson: "depth-complexity",
        settings: &[],
        pixel: (300, 250),
    },
    BookStory {
        name: "shadow-volume-beside-the-crates-shadow",
        lesson: "shadow-volume",
        settings: &[],
        pixel: (560, 300),
    },
    BookStory {
        name: "capping-on-the-cap",
        lesson: "capping",
        settings: &[],
        pixel: (215, 250),
    },
    BookStory {
        name: "portal-in-room-2",
        lesson: "portal",
        settings: &[],
        pixel: (270, 120),
    },
];

impl BookStory {
    /// `images/stories/<name>.txt`: the story as `--pixel` prints it.
    pub fn text_path(&self) -> PathBuf {
        crate::images()
            .join("stories")
            .join(format!("{}.txt", self.name))
    }

    /// The picture's name among the book's images: `stories/<name>` (`.png`).
    pub fn image_name(&self) -> String {
        format!("stories/{}", self.name)
    }

    /// The command that tells the story.
    pub fn command(&self) -> String {
        let mut command = format!(
            "cargo run -p {} -- --size {}x{}",
            self.lesson, SIZE.0, SIZE.1
        );
        for setting in self.settings {
            command += &format!(" --set {setting}");
        }
        command + &format!(" --pixel {},{}", self.pixel.0, self.pixel.1)
    }

    /// The story and the lesson's picture (its own buffer, as the screenshots show it) with the
    /// pixel marked.
    pub fn tell(&self) -> Result<(Story, RgbaImage)> {
        let adjust =
            |request: &mut workbook::app::headless::Request| (request.width, request.height) = SIZE;
        let (mut stories, _) = shots::stories(self.lesson, self.settings, &[self.pixel], adjust)?;
        let capture = shots::render(self.lesson, self.settings, adjust)?;
        let mut picture = capture.color;
        mark(&mut picture, self.pixel);
        Ok((stories.remove(0), picture))
    }

    /// Tells the story and writes its text and picture.
    pub fn write(&self) -> Result<Vec<PathBuf>> {
        let (story, picture) = self.tell()?;
        let text = self.text_path();
        std::fs::create_dir_all(text.parent().unwrap())?;
        std::fs::write(&text, story.text())
            .with_context(|| format!("cannot write {}", text.display()))?;
        let png = crate::images().join(format!("{}.png", self.image_name()));
        workbook::app::headless::save_png_as(&picture, &png, PngSize::Small)?;
        Ok(vec![text, png])
    }
}

/// Marks `pixel` with a cross: four arms in yellow with a dark outline, leaving the pixel itself
/// and its neighbours as they are.
pub fn mark(picture: &mut RgbaImage, (x, y): (u32, u32)) {
    let (width, height) = picture.dimensions();
    let mut paint = |dx: i32, dy: i32, colour: [u8; 4]| {
        let (px, py) = (x as i32 + dx, y as i32 + dy);
        if px >= 0 && py >= 0 && (px as u32) < width && (py as u32) < height {
            picture.put_pixel(px as u32, py as u32, Rgba(colour));
        }
    };
    for distance in 3..=10 {
        for (sx, sy) in [(1, 0), (-1, 0), (0, 1), (0, -1)] {
            let (dx, dy) = (sx * distance, sy * distance);
            // The outline beside each arm, then the arm.
            paint(dx + sy, dy + sx, [0, 0, 0, 255]);
            paint(dx - sy, dy - sx, [0, 0, 0, 255]);
            paint(dx, dy, [255, 220, 0, 255]);
        }
    }
}

/// The story's text with its measured numbers (colours, depths) left out: what must not change
/// from one GPU to another is which steps and draws reach the pixel and what each test decides.
pub fn skeleton(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '#' && chars.peek().is_some_and(|c| c.is_ascii_hexdigit()) {
            while chars
                .peek()
                .is_some_and(|c| c.is_ascii_hexdigit() || *c == '/')
            {
                chars.next();
            }
            out.push_str("#colour");
        } else if c.is_ascii_digit() && chars.peek() == Some(&'.') {
            chars.next();
            while chars.peek().is_some_and(|c| c.is_ascii_digit()) {
                chars.next();
            }
            out.push_str("depth");
        } else {
            out.push(c);
        }
    }
    out
}
