//! Image comparison with NVIDIA FLIP, the perceptual metric wgpu's own tests use.
//!
//! FLIP gives each pixel an error between 0 (no visible difference) and 1 (as different as can be),
//! modelling what a viewer at a given distance notices. Three numbers judge a comparison: the mean
//! error over the image (small overall drift), the share of pixels whose error exceeds [`VISIBLE`]
//! (a region that changed completely, which barely moves the mean), and the largest connected patch
//! of such pixels (one small thing that changed — a fringe, a shadow's image — which barely moves
//! the share either, where another driver's differences are specks scattered over the textures).

use std::path::Path;

use anyhow::{Context, Result, bail};
use image::{RgbImage, RgbaImage};

/// A pixel error above this is a difference anyone would see.
pub const VISIBLE: f32 = 0.25;

/// What a comparison found.
#[derive(Clone)]
pub struct Comparison {
    pub mean: f32,
    /// Share of pixels (0..1) with an error above [`VISIBLE`].
    pub visible_share: f32,
    /// The largest 8-connected patch of pixels with an error above [`VISIBLE`], in pixels.
    pub largest_patch: u32,
    /// Each pixel's error, coloured with FLIP's magma map (black: none, yellow: large).
    pub difference: RgbImage,
    /// Each pixel's error (0..1), row-major: where the differences lie, for placing the book's crops.
    pub errors: Vec<f32>,
}

/// How far an image may be from its reference and still pass.
#[derive(Debug, Clone, Copy)]
pub struct Threshold {
    pub mean: f32,
    pub visible_share: f32,
    pub largest_patch: u32,
}

/// How far a render may be from the book's picture and still be the same picture: the tests' limit
/// for every screenshot, and what `--check` and the window's "compare with the book" say.
///
/// Every wrong picture of the book must fail it (a test walks them all), and every right picture
/// must pass it on another GPU. The references were made with lavapipe, which renders each of them
/// bit-identically run to run. Measured on an NVIDIA H100 (Vulkan, driver 580), all 73 compared
/// pictures against the references: FLIP mean up to 0.020 (the textures' anisotropic filtering is
/// the driver's own), at most 0.056% of the pixels visibly different, and those in specks: the
/// largest patch 25 px (drawing-order), elsewhere at most 6. Measured on lavapipe, the wrong
/// pictures against their right ones: means from 0.0023, 0.33% to 51% of the pixels visibly
/// different, and the largest patch at least 1,016 px (render-to-texture at resolution 64; a
/// drawing-order fringe 1,164 px, a 30×30 square 900).
///
/// So the mean says little (15 of the 20 wrong pictures lie below the other driver's 0.020); the
/// share, 0.15%, sits between the other driver's 0.056% and the smallest wrong share, 0.33%; and the
/// patch, 160 px, sits between 25 and 900 (their geometric middle, 6× from each): a thing that
/// changed, however small its share of the picture, is one patch, where filtering differences are
/// scattered specks. The mean limit stays for drift over the whole picture.
pub const STRICT: Threshold = Threshold {
    mean: 0.03,
    visible_share: 0.0015,
    largest_patch: 160,
};

impl Comparison {
    pub fn passes(&self, threshold: Threshold) -> bool {
        self.mean <= threshold.mean
            && self.visible_share <= threshold.visible_share
            && self.largest_patch <= threshold.largest_patch
    }

    pub fn summary(&self) -> String {
        format!(
            "FLIP mean {:.5}, {:.3}% of pixels visibly different, the largest such patch {} px",
            self.mean,
            self.visible_share * 100.0,
            self.largest_patch,
        )
    }
}

/// Compares `test` with `reference` (alpha ignored: FLIP compares colours).
pub fn compare(reference: &RgbaImage, test: &RgbaImage) -> Result<Comparison> {
    if reference.dimensions() != test.dimensions() {
        bail!(
            "the images differ in size: {}x{} against {}x{}",
            reference.width(),
            reference.height(),
            test.width(),
            test.height()
        );
    }
    let (width, height) = reference.dimensions();
    let rgb = |image: &RgbaImage| {
        let data = image::DynamicImage::ImageRgba8(image.clone()).into_rgb8();
        nv_flip::FlipImageRgb8::with_data(width, height, &data)
    };
    let errors = nv_flip::flip(
        rgb(reference),
        rgb(test),
        nv_flip::DEFAULT_PIXELS_PER_DEGREE,
    );
    let values = errors.to_vec();
    let mask: Vec<bool> = values.iter().map(|&e| e > VISIBLE).collect();
    let visible = mask.iter().filter(|&&v| v).count();
    let pool = nv_flip::FlipPool::from_image(&errors);
    let difference = errors.apply_color_lut(&nv_flip::magma_lut());
    Ok(Comparison {
        mean: pool.mean(),
        visible_share: visible as f32 / values.len() as f32,
        largest_patch: largest_patch(&mask, width, height),
        difference: RgbImage::from_raw(width, height, difference.to_vec())
            .context("FLIP returned an image of the wrong size")?,
        errors: values,
    })
}

/// The size of the largest 8-connected patch of `true` in a `width`×`height` mask.
pub fn largest_patch(mask: &[bool], width: u32, height: u32) -> u32 {
    let (w, h) = (width as usize, height as usize);
    let mut seen = vec![false; mask.len()];
    let mut stack = Vec::new();
    let mut largest = 0;
    for start in 0..mask.len() {
        if !mask[start] || seen[start] {
            continue;
        }
        seen[start] = true;
        stack.push(start);
        let mut size = 0;
        while let Some(i) = stack.pop() {
            size += 1;
            let (x, y) = (i % w, i / w);
            for ny in y.saturating_sub(1)..(y + 2).min(h) {
                for nx in x.saturating_sub(1)..(x + 2).min(w) {
                    let n = ny * w + nx;
                    if mask[n] && !seen[n] {
                        seen[n] = true;
                        stack.push(n);
                    }
                }
            }
        }
        largest = largest.max(size);
    }
    largest
}

/// Reads a PNG for comparison.
pub fn load(path: &Path) -> Result<RgbaImage> {
    let image = image::open(path).with_context(|| format!("cannot read `{}`", path.display()))?;
    Ok(image.to_rgba8())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A `width`×`height` mask with the pixels of the rectangle (x, y, w, h) set.
    fn mask_with(width: u32, height: u32, (x0, y0, w, h): (u32, u32, u32, u32)) -> Vec<bool> {
        (0..width * height)
            .map(|i| {
                let (x, y) = (i % width, i / width);
                (x0..x0 + w).contains(&x) && (y0..y0 + h).contains(&y)
            })
            .collect()
    }

    /// A `width`×`height` black picture with the rectangle (x, y, w, h) white.
    fn picture(width: u32, height: u32, rect: (u32, u32, u32, u32)) -> RgbaImage {
        let mask = mask_with(width, height, rect);
        RgbaImage::from_fn(width, height, |x, y| {
            let v = if mask[(y * width + x) as usize] {
                255
            } else {
                0
            };
            image::Rgba([v, v, v, 255])
        })
    }

    #[test]
    fn the_same_picture_differs_nowhere() {
        let a = picture(64, 48, (10, 10, 8, 8));
        let same = compare(&a, &a).unwrap();
        assert_eq!(same.mean, 0.0);
        assert_eq!((same.visible_share, same.largest_patch), (0.0, 0));
        assert_eq!(same.errors.len(), 64 * 48);
        assert_eq!(same.difference.dimensions(), (64, 48));
        assert!(same.passes(STRICT));
    }

    #[test]
    fn a_square_that_changed_is_one_visible_patch_of_about_its_size() {
        let (a, b) = (
            picture(64, 48, (0, 0, 0, 0)),
            picture(64, 48, (20, 10, 10, 10)),
        );
        let changed = compare(&a, &b).unwrap();
        // FLIP filters spatially: the patch is the square's 100 pixels and a rim (measured: 244).
        assert!(
            (100..=300).contains(&changed.largest_patch),
            "{}",
            changed.largest_patch
        );
        let visible = changed.errors.iter().filter(|&&e| e > VISIBLE).count() as f32;
        assert_eq!(changed.visible_share, visible / (64.0 * 48.0));
        assert!(changed.visible_share > 0.02 && changed.mean > 0.0);
        assert!(!changed.passes(STRICT));
        // Black where nothing changed, bright inside the square (the magma map).
        assert_eq!(changed.difference.get_pixel(60, 44).0, [0, 0, 4]);
        assert!(changed.difference.get_pixel(25, 15).0[0] > 200);
        let summary = changed.summary();
        assert!(
            summary.contains(&format!("{} px", changed.largest_patch)),
            "{summary}"
        );
        assert!(
            summary.contains(&format!("{:.5}", changed.mean)),
            "{summary}"
        );
        assert!(
            summary.contains(&format!("{:.3}%", changed.visible_share * 100.0)),
            "{summary}"
        );
    }

    #[test]
    fn pictures_of_other_sizes_are_not_compared() {
        let error = compare(&picture(4, 4, (0, 0, 1, 1)), &picture(4, 5, (0, 0, 1, 1)));
        assert!(error.is_err());
        assert!(compare(&picture(4, 4, (0, 0, 1, 1)), &picture(5, 4, (0, 0, 1, 1))).is_err());
    }

    /// Each of the three figures alone decides, and a figure at its limit passes.
    #[test]
    fn each_figure_fails_alone_and_the_limit_itself_passes() {
        let at = Comparison {
            mean: STRICT.mean,
            visible_share: STRICT.visible_share,
            largest_patch: STRICT.largest_patch,
            difference: RgbImage::new(1, 1),
            errors: Vec::new(),
        };
        assert!(at.passes(STRICT));
        let over = |c: Comparison| !c.passes(STRICT);
        assert!(over(Comparison {
            mean: 0.031,
            ..at.clone()
        }));
        assert!(over(Comparison {
            visible_share: 0.0016,
            ..at.clone()
        }));
        assert!(over(Comparison {
            largest_patch: 161,
            ..at.clone()
        }));
    }

    /// A patch in the first rows and columns, whose neighbours lie below and right of it only.
    #[test]
    fn a_patch_in_the_corner_is_one_patch() {
        let mask = mask_with(8, 8, (0, 0, 2, 2));
        assert_eq!(largest_patch(&mask, 8, 8), 4);
        let mask = mask_with(8, 8, (6, 6, 2, 2));
        assert_eq!(largest_patch(&mask, 8, 8), 4);
    }

    #[test]
    fn a_png_is_read_for_comparison_and_a_missing_one_named() {
        let path = std::env::temp_dir().join(format!("flip-load-{}.png", std::process::id()));
        picture(6, 4, (1, 1, 2, 2)).save(&path).unwrap();
        let loaded = load(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(loaded, picture(6, 4, (1, 1, 2, 2)));
        let missing = load(&path).unwrap_err().to_string();
        assert!(missing.contains("cannot read"), "{missing}");
    }

    #[test]
    fn largest_patch_joins_neighbours_diagonals_included() {
        let mut mask = mask_with(20, 20, (2, 2, 3, 3)); // 9 pixels
        mask[5 * 20 + 5] = true; // touches (4, 4) diagonally: 10
        mask[10 * 20 + 10] = true; // alone
        assert_eq!(largest_patch(&mask, 20, 20), 10);
        assert_eq!(largest_patch(&vec![false; 400], 20, 20), 0);
    }
}
