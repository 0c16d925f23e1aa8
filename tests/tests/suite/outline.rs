//! Lesson 12, by distances measured in the picture: the band around the skull (the pixels that hold
//! 2 in the stencil buffer read back) is amber all round up to one distance and nowhere past
//! another, the same for its image in the mirror (value 3); and each of the four stencil values is
//! where another lesson's picture puts it (lesson 3's mark, lesson 4's image).

use lessons::outline;
use workbook::app::headless::{self, Capture, Request};
use workbook::room::camera::Camera;
use workbook::{Lesson, Show, Stop};
use workbook_tests::shots;

/// The outline is 5/720 of the height: 3.75 pixels here.
pub const SIZE: (u32, u32) = (960, 540);

/// Every pixel outside the shape this near it is in the band. Measured on lavapipe: every pixel
/// nearer than 4.0 is; this leaves a pixel for the rasteriser's rounding. The scaled copy
/// (grow=scale) leaves a gap 2.2 pixels from the cheek, an outline of 3/720 one at 2.5.
pub const INSIDE_THE_BAND: f32 = 3.0;

/// No pixel farther than this from the shape is in the band. Measured on lavapipe: the farthest is
/// 4.5 (the width, 3.75, and the normals' slant across the silhouette); this leaves a pixel. The
/// scaled copy's band reaches 8.1 at the crown.
pub const PAST_THE_BAND: f32 = 5.5;

/// The outline's colour, `fs_outline`'s (1, 0.45, 0) in sRGB.
pub const AMBER: [u8; 3] = [0xff, 0xb3, 0x00];

/// The lesson's frame at [`SIZE`], its stencil read back, from the book's pose or `camera`.
pub fn render(settings: &[&str], camera: Option<&str>) -> Capture {
    render_as::<outline::Outline>(settings, camera)
}

/// [`render`] for lesson `L` (an exercise's solution).
pub fn render_as<L: Lesson>(settings: &[&str], camera: Option<&str>) -> Capture {
    let mut request = Request::new::<L>(settings).unwrap();
    (request.width, request.height) = SIZE;
    request.read_stencil = true;
    if let Some(camera) = camera {
        request.camera = Camera::parse(camera).unwrap();
    }
    headless::render::<L>(&request).unwrap()
}

/// A picture of [`SIZE`] as one flag per pixel, rows top to bottom.
pub struct Mask(pub Vec<bool>);

impl Mask {
    pub fn of(capture: &Capture, holds: impl Fn(u8) -> bool) -> Mask {
        Mask(
            capture
                .stencil
                .as_ref()
                .unwrap()
                .iter()
                .map(|&v| holds(v))
                .collect(),
        )
    }

    pub fn count(&self) -> usize {
        self.0.iter().filter(|&&on| on).count()
    }

    /// The pixels not in the mask that the picture's border reaches without crossing it: outside
    /// the shape, its holes left out.
    pub fn exterior(&self) -> Mask {
        let (w, h) = (SIZE.0 as usize, SIZE.1 as usize);
        let mut outside = vec![false; w * h];
        let mut todo: Vec<usize> = (0..w * h)
            .filter(|&i| i % w == 0 || i % w == w - 1 || i / w == 0 || i / w == h - 1)
            .collect();
        while let Some(i) = todo.pop() {
            if outside[i] || self.0[i] {
                continue;
            }
            outside[i] = true;
            let (x, y) = (i % w, i / w);
            if x > 0 {
                todo.push(i - 1);
            }
            if x + 1 < w {
                todo.push(i + 1);
            }
            if y > 0 {
                todo.push(i - w);
            }
            if y + 1 < h {
                todo.push(i + w);
            }
        }
        Mask(outside)
    }

    /// Each pixel's distance to the nearest pixel of the mask (centre to centre), up to `reach`;
    /// `f32::INFINITY` beyond it.
    pub fn distances(&self, reach: i32) -> Vec<f32> {
        let (w, h) = (SIZE.0 as i32, SIZE.1 as i32);
        let mut distance = vec![f32::INFINITY; self.0.len()];
        let on =
            |x: i32, y: i32| x >= 0 && y >= 0 && x < w && y < h && self.0[(y * w + x) as usize];
        for y in 0..h {
            for x in 0..w {
                // Only the shape's edge can be nearest to a pixel outside it.
                let edge =
                    on(x, y) && !(on(x - 1, y) && on(x + 1, y) && on(x, y - 1) && on(x, y + 1));
                if !edge {
                    continue;
                }
                for dy in -reach..=reach {
                    for dx in -reach..=reach {
                        let (px, py) = (x + dx, y + dy);
                        if px < 0 || py < 0 || px >= w || py >= h {
                            continue;
                        }
                        let d = ((dx * dx + dy * dy) as f32).sqrt();
                        let slot = &mut distance[(py * w + px) as usize];
                        *slot = slot.min(d);
                    }
                }
            }
        }
        distance
    }
}

pub fn rgb(capture: &Capture, i: usize) -> [u8; 3] {
    let [r, g, b, _] = capture.color.as_raw()[i * 4..i * 4 + 4] else {
        unreachable!()
    };
    [r, g, b]
}

pub fn is_amber(c: [u8; 3]) -> bool {
    c.iter().zip(AMBER).all(|(&a, b)| a.abs_diff(b) <= 3)
}

/// The pixels that break the band around `shape` in `band` (which pixels are the band's): in it but
/// inside the shape or past [`PAST_THE_BAND`], or outside the shape, this near it, and not in it.
pub fn band_faults(shape: &Mask, band: impl Fn(usize) -> bool, near: f32) -> Vec<String> {
    let exterior = shape.exterior();
    let distance = shape.distances(12);
    let mut faults = Vec::new();
    for (i, &d) in distance.iter().enumerate() {
        let (x, y) = (i as u32 % SIZE.0, i as u32 / SIZE.0);
        let fault = match (shape.0[i], band(i)) {
            (true, true) => Some("on the shape".to_string()),
            (false, true) if d > PAST_THE_BAND => Some(format!("{d:.1} px from the shape")),
            (false, false) if exterior.0[i] && d <= near => {
                Some(format!("{d:.1} px away, not in it"))
            }
            _ => None,
        };
        if let Some(fault) = fault {
            faults.push(format!("({x}, {y}): {fault}"));
        }
    }
    faults
}

fn assert_no_faults(what: &str, faults: &[String]) {
    assert!(
        faults.is_empty(),
        "{what}: {} pixels break the band, e.g. {:?}",
        faults.len(),
        &faults[..faults.len().min(8)]
    );
}

/// From the book's pose, and from behind the crate, where the crate hides the jaw: the selection
/// marks the skull's hidden pixels too, and the band goes round them over the crate. Both ways,
/// the grown copy and the mask's edge on the screen, by the same measure.
#[test]
fn the_band_goes_round_the_skull_at_one_width() {
    for way in ["way=stencil", "way=screen-space"] {
        for camera in [None, Some(shots::BEHIND_THE_CRATE)] {
            let capture = render(&[way], camera);
            let skull = Mask::of(&capture, |v| v == 2);
            assert!(
                skull.count() > 5_000,
                "the skull holds 2 at {} pixels",
                skull.count()
            );
            let band = |i| is_amber(rgb(&capture, i));
            let faults = band_faults(&skull, band, INSIDE_THE_BAND);
            assert_no_faults(
                &format!("the skull's band, {way}, camera {camera:?}"),
                &faults,
            );
        }
    }
}

/// The same band around the skull's image (value 3), seen through the glass: the pixels where the
/// picture differs from the one without the image's outline.
#[test]
fn the_image_in_the_mirror_has_the_same_band() {
    for way in ["way=stencil", "way=screen-space"] {
        image_band(way);
    }
}

fn image_band(way: &str) {
    let capture = render(&[way], None);
    let unoutlined = render(&[way, "reflected-outline=off"], None);
    let stencil = capture.stencil.as_ref().unwrap();
    let image = Mask::of(&capture, |v| v == 3);
    assert!(
        image.count() > 2_000,
        "the image holds 3 at {} pixels",
        image.count()
    );
    let (exterior, distance) = (image.exterior(), image.distances(12));
    let mut faults = Vec::new();
    for (i, &d) in distance.iter().enumerate() {
        let band = rgb(&capture, i) != rgb(&unoutlined, i);
        // The skull's own band is drawn last, over the mirror too: there both pictures are amber.
        let covered = is_amber(rgb(&capture, i));
        let fault = match (band, stencil[i]) {
            (true, 1) if d > PAST_THE_BAND => Some(format!("{d:.1} px from the image")),
            (true, 1) => None,
            (true, value) => Some(format!("in the band, but the stencil holds {value}")),
            (false, 1) if exterior.0[i] && d <= INSIDE_THE_BAND && !covered => {
                Some(format!("{d:.1} px from the image, not in the band"))
            }
            (false, _) => None,
        };
        if let Some(fault) = fault {
            faults.push(format!(
                "({}, {}): {fault}",
                i as u32 % SIZE.0,
                i as u32 / SIZE.0
            ));
        }
    }
    assert_no_faults(&format!("the image's band, {way}"), &faults);
}

/// The four values, each where the colours say: bit 0 is lesson 3's mark (another lesson), 2 where
/// step 3 drew the skull's colour, 3 where step 5 drew the image's.
#[test]
fn each_stencil_value_is_where_its_recipe_puts_it() {
    let capture = render(&[], None);
    let stencil = capture.stencil.as_ref().unwrap();
    let mark = render_as::<lessons::mark_mirror::MarkMirror>(&[], None);
    let [room, skull, marked, imaged] = [2, 3, 4, 5].map(step_colour);
    let drew = |before: &image::RgbaImage, after: &image::RgbaImage, i: usize| {
        before.as_raw()[i * 4..i * 4 + 3] != after.as_raw()[i * 4..i * 4 + 3]
    };
    let mut faults = Vec::new();
    for (i, &value) in stencil.iter().enumerate() {
        let mark_bit = mark.stencil.as_ref().unwrap()[i] == 1;
        let (on_skull, reflected) = (drew(&room, &skull, i), drew(&marked, &imaged, i));
        let expected = match (on_skull, mark_bit, reflected) {
            (true, _, _) => 2,
            (false, true, true) => 3,
            (false, true, false) => 1,
            (false, false, _) => 0,
        };
        if value != expected {
            faults.push(format!(
                "({}, {}): {value}, not {expected}",
                i as u32 % SIZE.0,
                i as u32 / SIZE.0
            ));
        }
    }
    assert!(
        faults.is_empty(),
        "{} pixels: {:?}",
        faults.len(),
        &faults[..faults.len().min(8)]
    );
}

fn step_colour(step: usize) -> image::RgbaImage {
    shots::render("outline", &[], |request| {
        (request.width, request.height) = SIZE;
        request.stop = Stop::After(step);
        request.show = Show::Color;
    })
    .unwrap()
    .color
}
