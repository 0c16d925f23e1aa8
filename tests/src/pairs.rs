//! Right-and-wrong pairs for the book: from a lesson's right and wrong screenshots, find where they
//! differ, and compose an enlarged side-by-side crop of that place and the FLIP difference image with
//! the crop outlined, so the reader sees both where to look and what changed.
//!
//! The crop is placed from FLIP's per-pixel errors ([`crate::flip::Comparison::errors`]) rather than
//! by hand, so it follows the pictures when a lesson's scene or camera changes — the errors between
//! the book's two committed pictures, so that it lies in the same place on every machine.

use std::sync::OnceLock;

use anyhow::{Context, Result};
use image::imageops::{self, FilterType};
use image::{Rgba, RgbaImage};

use crate::flip::{self, VISIBLE};
use crate::shots::{PAIRS, Pair, SIZE, Shot};

/// The share of the visibly different pixels the crop aims to hold: high enough that the crop shows
/// the difference, low enough that a few stray pixels (texture shimmer) far away are left out.
pub const COVERAGE: f32 = 0.9;

/// Trims tried on each axis, tightest first: the box between the `t` and `1 - t` quantiles of the
/// visibly different pixels' coordinates. Beyond 5% a single blob's trimmed box already falls well
/// below [`COVERAGE`]; 0 (the full extent) always reaches it, so one of them is always taken.
const TRIMS: [f32; 6] = [0.05, 0.04, 0.03, 0.02, 0.01, 0.0];

/// The least margin around the differences, in pixels: enough that an edge that changed is not on
/// the crop's border, where the reader would miss it.
const MIN_MARGIN: f32 = 8.0;

/// The margin as a share of the box's size: a large difference gets proportionally more context.
const MARGIN_SHARE: f32 = 0.1;

/// The smallest crop, as a share of the image's width: smaller crops are enlarged so much that the
/// reader loses the context (which object, which edge) the difference sits in.
const MIN_WIDTH_SHARE: f32 = 1.0 / 6.0;

/// Pixels between the two panels of [`zoom`]: enough to read as two pictures, not one.
pub const GAP: u32 = 8;

/// The page's colour, for the strip between the panels: it reads as page, not as picture.
const PAGE: Rgba<u8> = Rgba([255, 255, 255, 255]);

/// The outline's colour on the difference image: cyan is absent from magma (black, purple, orange,
/// yellow), so it stands out on small and large errors alike.
const OUTLINE: Rgba<u8> = Rgba([0, 255, 255, 255]);

/// The outline's width in pixels: 1 px vanishes once the book scales the image down.
const OUTLINE_WIDTH: u32 = 2;

/// A rectangle in pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Rect {
    pub x: u32,
    pub y: u32,
    pub width: u32,
    pub height: u32,
}

impl Rect {
    pub fn contains(&self, x: u32, y: u32) -> bool {
        x >= self.x && x - self.x < self.width && y >= self.y && y - self.y < self.height
    }

    /// The same rectangle in an image `factor` times larger (a render of the same view at a higher
    /// resolution).
    pub fn scaled(&self, factor: u32) -> Rect {
        Rect {
            x: self.x * factor,
            y: self.y * factor,
            width: self.width * factor,
            height: self.height * factor,
        }
    }
}

/// The coordinates of the pixels whose error is visible.
fn visible(errors: &[f32], width: u32) -> impl Iterator<Item = (u32, u32)> + '_ {
    errors
        .iter()
        .enumerate()
        .filter(|(_, e)| **e > VISIBLE)
        .map(move |(i, _)| (i as u32 % width, i as u32 / width))
}

/// Where the crop goes: the smallest box (in practice: found from trimmed quantiles of the visibly
/// different pixels, then padded by a margin, grown to the image's aspect ratio and to a minimum size
/// of 1/6 of the image width, and moved inside the image) that holds at least [`COVERAGE`] of the
/// pixels whose FLIP error exceeds [`VISIBLE`]. If no pixel differs visibly, returns `None`.
///
/// Trimming the quantiles keeps a few stray pixels far away from blowing the box up to the whole
/// image; where the differences genuinely span the image, only the wider boxes reach the coverage, and
/// the crop grows to match (up to the whole image).
pub fn crop_box(errors: &[f32], width: u32, height: u32) -> Option<Rect> {
    assert_eq!(
        errors.len(),
        width as usize * height as usize,
        "one error per pixel"
    );
    let points: Vec<(u32, u32)> = visible(errors, width).collect();
    if points.is_empty() {
        return None;
    }
    let mut xs: Vec<u32> = points.iter().map(|p| p.0).collect();
    let mut ys: Vec<u32> = points.iter().map(|p| p.1).collect();
    xs.sort_unstable();
    ys.sort_unstable();
    // The `t` quantile rounded outwards, so that the box between two quantiles only ever grows as
    // the trim shrinks.
    let low = |sorted: &[u32], t: f32| sorted[(t * (sorted.len() - 1) as f32).floor() as usize];
    let high =
        |sorted: &[u32], t: f32| sorted[((1.0 - t) * (sorted.len() - 1) as f32).ceil() as usize];
    let core = TRIMS
        .iter()
        .map(|&t| {
            let (x0, x1) = (low(&xs, t), high(&xs, t));
            let (y0, y1) = (low(&ys, t), high(&ys, t));
            Rect {
                x: x0,
                y: y0,
                width: x1 - x0 + 1,
                height: y1 - y0 + 1,
            }
        })
        .find(|rect| share(&points, *rect) >= COVERAGE)
        .expect("the untrimmed box holds every point");

    // Sizes in floating point from here on; rounded once at the end.
    let (image_w, image_h) = (width as f32, height as f32);
    let aspect = image_w / image_h;
    let centre_x = core.x as f32 + core.width as f32 / 2.0;
    let centre_y = core.y as f32 + core.height as f32 / 2.0;
    let pad = |size: f32| size + 2.0 * (size * MARGIN_SHARE).max(MIN_MARGIN);
    let w = pad(core.width as f32).min(image_w);
    let h = pad(core.height as f32).min(image_h);
    // Grown to the image's aspect ratio, so that the pair and the full pictures share a shape on the
    // page; the height follows from the width below. Neither side outgrows the image, as the padded
    // height already fits.
    let w = w.max(h * aspect).max(image_w * MIN_WIDTH_SHARE);

    let crop_w = (w.round() as u32).clamp(1, width);
    // The height from the rounded width, so that the aspect ratio holds to the pixel.
    let crop_h = ((crop_w as f32 / aspect).round() as u32).clamp(1, height);
    // Centred on the differences, shifted inside the image where it would stick out.
    let place = |centre: f32, size: u32, limit: u32| {
        ((centre - size as f32 / 2.0).round().max(0.0) as u32).min(limit - size)
    };
    Some(Rect {
        x: place(centre_x, crop_w, width),
        y: place(centre_y, crop_h, height),
        width: crop_w,
        height: crop_h,
    })
}

/// Share of `points` inside `rect`; all of none (1) when there are none.
fn share(points: &[(u32, u32)], rect: Rect) -> f32 {
    if points.is_empty() {
        return 1.0;
    }
    let inside = points.iter().filter(|(x, y)| rect.contains(*x, *y)).count();
    inside as f32 / points.len() as f32
}

/// Share (0..=1) of the visibly different pixels that lie inside `rect` (1 when there are none: the
/// crop misses nothing).
pub fn coverage(errors: &[f32], width: u32, rect: Rect) -> f32 {
    let points: Vec<(u32, u32)> = visible(errors, width).collect();
    share(&points, rect)
}

/// The enlarged crop for the book: the right picture's crop on the left, the wrong picture's on the
/// right, separated by a [`GAP`]-pixel strip of the page's colour, each resized to `panel_width`
/// pixels wide keeping the aspect ratio. `right` and `wrong` may be larger renders of the same view
/// (`scale` times the size `rect` was computed at): the crop is `rect.scaled(scale)`.
pub fn zoom(
    right: &RgbaImage,
    wrong: &RgbaImage,
    rect: Rect,
    scale: u32,
    panel_width: u32,
) -> RgbaImage {
    assert_eq!(
        right.dimensions(),
        wrong.dimensions(),
        "the right and wrong pictures show the same view"
    );
    let crop = rect.scaled(scale);
    assert!(
        crop.x + crop.width <= right.width() && crop.y + crop.height <= right.height(),
        "the crop {crop:?} lies inside the {}x{} pictures",
        right.width(),
        right.height()
    );
    let panel_height = ((panel_width as u64 * crop.height as u64 + crop.width as u64 / 2)
        / crop.width as u64) as u32;
    let panel_height = panel_height.max(1);
    // Lanczos3 in general: it keeps edges sharp without the blocks of nearest-neighbour. But where
    // the enlargement is an exact integer of 3 or more, nearest-neighbour shows each rendered pixel
    // as a crisp square, which is the point of a zoom on aliasing, z-fighting speckle or a stencil's
    // edge; Lanczos would blur those pixels and ring around them.
    let filter = if panel_width.is_multiple_of(crop.width) && panel_width / crop.width >= 3 {
        FilterType::Nearest
    } else {
        FilterType::Lanczos3
    };
    let panel = |image: &RgbaImage| {
        let view = imageops::crop_imm(image, crop.x, crop.y, crop.width, crop.height).to_image();
        imageops::resize(&view, panel_width, panel_height, filter)
    };
    let mut canvas = RgbaImage::from_pixel(2 * panel_width + GAP, panel_height, PAGE);
    imageops::replace(&mut canvas, &panel(right), 0, 0);
    imageops::replace(&mut canvas, &panel(wrong), (panel_width + GAP) as i64, 0);
    canvas
}

/// The FLIP difference image (as [`crate::flip::Comparison::difference`]) with the crop's outline
/// drawn on it, [`OUTLINE_WIDTH`] pixels wide just inside `rect` (so that it shows even when the crop
/// is the whole image), as RGBA. No text: the book's caption says what the outline is.
pub fn outlined(difference: &image::RgbImage, rect: Rect) -> RgbaImage {
    let mut image = image::DynamicImage::ImageRgb8(difference.clone()).into_rgba8();
    let inner = Rect {
        x: rect.x + OUTLINE_WIDTH,
        y: rect.y + OUTLINE_WIDTH,
        width: rect.width.saturating_sub(2 * OUTLINE_WIDTH),
        height: rect.height.saturating_sub(2 * OUTLINE_WIDTH),
    };
    let right = (rect.x + rect.width).min(image.width());
    let bottom = (rect.y + rect.height).min(image.height());
    for y in rect.y..bottom {
        for x in rect.x..right {
            if !inner.contains(x, y) {
                image.put_pixel(x, y, OUTLINE);
            }
        }
    }
    image
}

/// The zoom's crops come from renders this many times the book's size, so that the enlargement
/// shows detail the renderer drew rather than blown-up pixels.
pub const ZOOM_SCALE: u32 = 2;

/// The width of each panel of a zoom: two of them and the gap make about the book's width.
pub const PANEL_WIDTH: u32 = 400;

/// What `cargo screenshots` makes of a pair.
pub struct PairImages {
    /// Where the crop lies in the book-size pictures, and the share of visibly different pixels it
    /// holds.
    pub rect: Rect,
    pub coverage: f32,
    /// The right and the wrong picture's crops, enlarged, side by side.
    pub zoom: RgbaImage,
    /// The FLIP difference image of the book-size pictures with the crop outlined.
    pub difference: RgbaImage,
}

impl Pair {
    /// The file names (without `.png`) of the pair's images in `book/src/images/`.
    pub fn zoom_name(&self) -> String {
        format!("{}-zoom", self.wrong)
    }
    pub fn difference_name(&self) -> String {
        format!("{}-flip", self.wrong)
    }

    /// The pair as the book has it: its two committed pictures compared. The crop is placed from
    /// this alone, so it is the same on every machine (FLIP runs on the CPU); a driver's own
    /// choices — texture filtering, z-fighting — never move it.
    pub fn in_the_book(&self) -> Result<flip::Comparison> {
        let (wrong, right) = (Shot::named(self.wrong)?, Shot::named(self.right)?);
        flip::compare(&flip::load(&right.path())?, &flip::load(&wrong.path())?)
    }

    /// The pair as this machine renders it, compared (once per process: several tests ask).
    pub fn here(&self) -> Result<&'static flip::Comparison> {
        static HERE: OnceLock<Vec<Result<flip::Comparison, String>>> = OnceLock::new();
        let all = HERE.get_or_init(|| {
            let compare = |pair: &Pair| {
                let (wrong, right) = (Shot::named(pair.wrong)?, Shot::named(pair.right)?);
                flip::compare(&right.render()?, &wrong.render()?)
            };
            PAIRS
                .iter()
                .map(|pair| compare(pair).map_err(|e| format!("{e:#}")))
                .collect()
        });
        let index = PAIRS
            .iter()
            .position(|pair| (pair.wrong, pair.right) == (self.wrong, self.right))
            .context("a pair of the catalogue")?;
        all[index].as_ref().map_err(|e| anyhow::anyhow!("{e}"))
    }

    /// Places the crop where the book's two pictures differ, and makes the images: the zoom from
    /// renders at [`ZOOM_SCALE`] times the size, the difference image from the book's pictures.
    pub fn make(&self) -> Result<PairImages> {
        let (wrong, right) = (Shot::named(self.wrong)?, Shot::named(self.right)?);
        let comparison = self.in_the_book()?;
        let rect = crop_box(&comparison.errors, SIZE.0, SIZE.1)
            .with_context(|| format!("{} does not differ from {}", self.wrong, self.right))?;
        let large = (SIZE.0 * ZOOM_SCALE, SIZE.1 * ZOOM_SCALE);
        let (right_large, wrong_large) = (right.render_at(large)?, wrong.render_at(large)?);
        Ok(PairImages {
            rect,
            coverage: coverage(&comparison.errors, SIZE.0, rect),
            zoom: zoom(&right_large, &wrong_large, rect, ZOOM_SCALE, PANEL_WIDTH),
            difference: outlined(&comparison.difference, rect),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const W: u32 = 320;
    const H: u32 = 240;

    /// An error map with no differences.
    fn blank() -> Vec<f32> {
        vec![0.0; (W * H) as usize]
    }

    /// Marks the pixels of `rect` as clearly different.
    fn blob(errors: &mut [f32], rect: Rect) {
        for y in rect.y..rect.y + rect.height {
            for x in rect.x..rect.x + rect.width {
                errors[(y * W + x) as usize] = 0.8;
            }
        }
    }

    fn rect(x: u32, y: u32, width: u32, height: u32) -> Rect {
        Rect {
            x,
            y,
            width,
            height,
        }
    }

    /// What every crop must satisfy: inside the image, in its aspect ratio to the pixel.
    fn check_shape(crop: Rect) {
        assert!(crop.width >= 1 && crop.height >= 1, "{crop:?}");
        assert!(crop.x + crop.width <= W, "{crop:?} sticks out");
        assert!(crop.y + crop.height <= H, "{crop:?} sticks out");
        let expected_height = crop.width as f32 * H as f32 / W as f32;
        assert!(
            (crop.height as f32 - expected_height).abs() <= 1.0,
            "{crop:?} is not {W}:{H}"
        );
    }

    fn holds(crop: Rect, inner: Rect) -> bool {
        crop.contains(inner.x, inner.y)
            && crop.contains(inner.x + inner.width - 1, inner.y + inner.height - 1)
    }

    #[test]
    fn a_blob_gets_a_small_box_around_it() {
        let mut errors = blank();
        let spot = rect(200, 60, 30, 20);
        blob(&mut errors, spot);
        let crop = crop_box(&errors, W, H).unwrap();
        check_shape(crop);
        assert!(coverage(&errors, W, crop) >= 0.8);
        assert!(holds(crop, spot), "{crop:?} misses {spot:?}");
        assert!(crop.width * crop.height * 4 < W * H, "{crop:?} is too big");
    }

    #[test]
    fn far_outliers_do_not_blow_the_box_up() {
        let mut errors = blank();
        let spot = rect(100, 100, 40, 40);
        blob(&mut errors, spot);
        for (x, y) in [(0, 0), (319, 0), (0, 239), (319, 239), (5, 120)] {
            errors[(y * W + x) as usize] = 0.5;
        }
        let crop = crop_box(&errors, W, H).unwrap();
        check_shape(crop);
        assert!(coverage(&errors, W, crop) >= 0.8);
        assert!(holds(crop, spot), "{crop:?} misses {spot:?}");
        assert!(crop.width * crop.height * 4 < W * H, "{crop:?} is too big");
    }

    #[test]
    fn two_blobs_are_both_held() {
        let mut errors = blank();
        let (left, right) = (rect(40, 50, 20, 20), rect(240, 150, 20, 20));
        blob(&mut errors, left);
        blob(&mut errors, right);
        let crop = crop_box(&errors, W, H).unwrap();
        check_shape(crop);
        assert!(coverage(&errors, W, crop) >= 0.8);
        assert!(crop.contains(50, 60) && crop.contains(250, 160), "{crop:?}");
    }

    #[test]
    fn differences_everywhere_give_the_whole_image() {
        let errors = vec![0.6; (W * H) as usize];
        let crop = crop_box(&errors, W, H).unwrap();
        check_shape(crop);
        assert!(coverage(&errors, W, crop) >= 0.8);
        assert!(crop.width >= W - 2 && crop.height >= H - 2, "{crop:?}");
    }

    #[test]
    fn no_differences_give_no_box() {
        let mut errors = blank();
        // Below the visible threshold: no crop.
        errors.iter_mut().for_each(|e| *e = VISIBLE * 0.9);
        assert_eq!(crop_box(&errors, W, H), None);
    }

    #[test]
    fn boxes_stay_inside_in_the_image_shape() {
        // Blobs at each edge and corner, small and large, including ones larger than the image's
        // height, which must be shifted and clamped inside.
        let spots = [
            rect(0, 0, 3, 3),
            rect(317, 237, 3, 3),
            rect(0, 100, 10, 140),
            rect(300, 0, 20, 240),
            rect(0, 230, 320, 10),
            rect(150, 0, 5, 5),
            rect(10, 10, 300, 30),
        ];
        for spot in spots {
            let mut errors = blank();
            blob(&mut errors, spot);
            let crop = crop_box(&errors, W, H).unwrap();
            check_shape(crop);
            assert!(coverage(&errors, W, crop) >= 0.8, "{spot:?} -> {crop:?}");
            // The minimum size: a sixth of the image's width.
            assert!(crop.width + 1 >= W / 6, "{spot:?} -> {crop:?}");
        }
    }

    #[test]
    fn rect_contains_and_scales() {
        let r = rect(10, 20, 5, 4);
        assert!(r.contains(10, 20) && r.contains(14, 23));
        assert!(!r.contains(15, 20) && !r.contains(10, 24) && !r.contains(9, 20));
        assert_eq!(r.scaled(2), rect(20, 40, 10, 8));
    }

    #[test]
    fn zoom_puts_right_left_and_wrong_right() {
        // Both pictures are grey, each with a coloured square where the crop goes; rendered at twice
        // the size the crop was computed at.
        let scale = 2;
        let crop = rect(40, 30, 40, 30);
        let picture = |colour: [u8; 4]| {
            let mut image = RgbaImage::from_pixel(W * scale, H * scale, Rgba([128, 128, 128, 255]));
            let inside = crop.scaled(scale);
            for y in inside.y..inside.y + inside.height {
                for x in inside.x..inside.x + inside.width {
                    image.put_pixel(x, y, Rgba(colour));
                }
            }
            image
        };
        let (green, red) = ([0, 200, 0, 255], [200, 0, 0, 255]);
        let panel_width = 200;
        let pair = zoom(&picture(green), &picture(red), crop, scale, panel_width);
        assert_eq!(pair.width(), 2 * panel_width + GAP);
        assert_eq!(pair.height(), 150, "40x30 at 200 wide");
        let middle = pair.height() / 2;
        assert_eq!(pair.get_pixel(panel_width / 2, middle).0, green);
        assert_eq!(pair.get_pixel(panel_width + GAP / 2, middle), &PAGE);
        assert_eq!(
            pair.get_pixel(panel_width + GAP + panel_width / 2, middle)
                .0,
            red
        );
    }

    #[test]
    fn outlined_draws_only_the_outline() {
        let difference = image::RgbImage::from_pixel(W, H, image::Rgb([20, 10, 40]));
        let frame = rect(50, 40, 60, 45);
        let image = outlined(&difference, frame);
        assert_eq!(image.dimensions(), (W, H));
        let plain = Rgba([20, 10, 40, 255]);
        // Both pixels of the outline's width, on every side.
        for (x, y) in [
            (50, 60),
            (51, 60),
            (109, 60),
            (108, 60),
            (80, 40),
            (80, 41),
            (80, 84),
            (80, 83),
        ] {
            assert_eq!(image.get_pixel(x, y), &OUTLINE, "({x}, {y})");
        }
        // Inside and outside the outline, the difference image is untouched.
        for (x, y) in [
            (52, 60),
            (107, 60),
            (80, 42),
            (80, 82),
            (80, 62),
            (49, 60),
            (110, 60),
            (0, 0),
        ] {
            assert_eq!(image.get_pixel(x, y), &plain, "({x}, {y})");
        }
        // A crop of the whole image is still outlined, on its edge.
        let whole = outlined(&difference, rect(0, 0, W, H));
        assert_eq!(whole.get_pixel(0, 100), &OUTLINE);
        assert_eq!(whole.get_pixel(W - 1, H - 1), &OUTLINE);
        assert_eq!(whole.get_pixel(W / 2, H / 2), &plain);
    }
}
