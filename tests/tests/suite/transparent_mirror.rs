//! Lesson 6: at mirror pixels the picture is a·mirror + (1 − a)·reflection, computed from two separate
//! renders of the layers: the reflection without any glass (lesson 5's picture) and the glass alone,
//! opaque (`blend=off`).
//!
//! The colour target is `Rgba8UnormSrgb`, so the GPU blends in *linear* light: it decodes the stored
//! sRGB value, mixes, and encodes the result. The test does the same with the layers' bytes and
//! allows one step of 8-bit rounding; it also checks that mixing the sRGB bytes directly would be
//! visibly wrong, so the test really tells the two spaces apart.

use workbook::app::headless::Capture;
use workbook::gpu::{linear_to_srgb, srgb_to_linear};
use workbook_tests::shots;

const W: u32 = 320;
const H: u32 = 180;

fn render(lesson: &str, settings: &[&str]) -> Capture {
    shots::render(lesson, settings, |request| {
        (request.width, request.height) = (W, H);
        request.read_stencil = true;
    })
    .unwrap()
}

/// Pixels well inside the mark (the pixel and its 8 neighbours hold 1): the reflection's mirror pixels.
fn mirror_pixels(capture: &Capture) -> Vec<(u32, u32)> {
    let marked = |x: u32, y: u32| capture.stencil_at(x, y) == Some(1);
    (1..H - 1)
        .flat_map(|y| (1..W - 1).map(move |x| (x, y)))
        .filter(|&(x, y)| (0..3).all(|dy| (0..3).all(|dx| marked(x + dx - 1, y + dy - 1))))
        .collect()
}

#[test]
fn the_mirror_is_blended_over_the_reflection_in_linear_light() {
    let reflection = render("winding-fix", &[]);
    let glass = render("transparent-mirror", &["blend=off"]);
    let pixels = mirror_pixels(&reflection);
    assert!(pixels.len() > 3000, "only {} mirror pixels", pixels.len());

    for alpha in [0.25f32, 0.5, 0.75] {
        let setting = format!("mirror-alpha={alpha}");
        let blended = render("transparent-mirror", &[setting.as_str()]);
        let (mut worst, mut naive_off) = (0u8, 0usize);
        for &(x, y) in &pixels {
            let r = reflection.color.get_pixel(x, y).0;
            let g = glass.color.get_pixel(x, y).0;
            let got = blended.color.get_pixel(x, y).0;
            for c in 0..3 {
                let linear = alpha * srgb_to_linear(g[c]) + (1.0 - alpha) * srgb_to_linear(r[c]);
                worst = worst.max(linear_to_srgb(linear).abs_diff(got[c]));
                // Mixing the encoded bytes instead, as if the blend happened in sRGB space.
                let naive = (alpha * g[c] as f32 + (1.0 - alpha) * r[c] as f32).round() as u8;
                naive_off += usize::from(naive.abs_diff(got[c]) > 2);
            }
        }
        assert!(
            worst <= 1,
            "mirror-alpha={alpha}: a pixel is {worst} steps from a·mirror + (1 − a)·reflection"
        );
        assert!(
            naive_off > pixels.len() / 4,
            "mirror-alpha={alpha}: blending the sRGB bytes would pass too ({naive_off} misses): the \
             test cannot tell the spaces apart"
        );
    }
}

#[test]
fn an_opaque_mirror_hides_the_reflection() {
    let reflection = render("winding-fix", &[]);
    let glass = render("transparent-mirror", &["blend=off"]);
    let alpha_one = render("transparent-mirror", &["mirror-alpha=1"]);
    let alpha_zero = render("transparent-mirror", &["mirror-alpha=0"]);
    for (x, y) in mirror_pixels(&reflection) {
        assert_eq!(glass.color.get_pixel(x, y), alpha_one.color.get_pixel(x, y));
        assert_eq!(
            reflection.color.get_pixel(x, y),
            alpha_zero.color.get_pixel(x, y)
        );
    }
}
