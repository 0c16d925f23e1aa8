//! Lesson 10, by oracles: the shadow darkens each of its pixels exactly once, to half the light
//! (measured in linear light), and more than once without NO_DOUBLE_BLEND; its outline is the
//! skull's silhouette cast on the floor, found by casting rays on the CPU; the lights of the mirror
//! world are the real ones reflected; the mirror's mark and the shadow's bit share the stencil.

use glam::Vec3;
use image::RgbaImage;
use workbook::app::headless::{Capture, Still};
use workbook::gpu::{linear_to_srgb, srgb_to_linear};
use workbook::math::shadow::LightSource;
use workbook::room::mesh::MeshData;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, SKULL_CENTRE, SKULL_SIZE, default_assets, mirror_reflection,
    skull_world,
};
use workbook::{Lesson, Stop};
use workbook_tests::geometry::{View, hit_box, hit_y0_rect, passes_near};
use workbook_tests::shots;

use lessons::planar_shadow::{PlanarShadow, key_light};

const SIZE: (u32, u32) = (320, 180);

fn render(settings: &[&str], stop: Option<&str>) -> Capture {
    let stop = stop.map_or(Stop::Last, |step| {
        shots::after_step("planar-shadow", settings, step).unwrap()
    });
    shots::render("planar-shadow", settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        request.stop = stop;
    })
    .unwrap()
}

/// For each pixel the shadow step changed: how dark it became, as a share of its light before, in
/// linear light — and whether that is half, to one 8-bit step.
fn darkening(before: &RgbaImage, after: &RgbaImage) -> (usize, usize, usize) {
    let (mut changed, mut halved, mut darker) = (0, 0, 0);
    for (x, y, pixel) in after.enumerate_pixels() {
        let old = before.get_pixel(x, y);
        if pixel == old {
            continue;
        }
        changed += 1;
        let half = |c: usize| linear_to_srgb(0.5 * srgb_to_linear(old.0[c]));
        if (0..3).all(|c| pixel.0[c].abs_diff(half(c)) <= 1) {
            halved += 1;
        } else if (0..3).all(|c| pixel.0[c] + 1 < half(c)) {
            darker += 1;
        }
    }
    (changed, halved, darker)
}

#[test]
fn the_shadow_darkens_each_pixel_exactly_once() {
    let before = render(&[], Some("draw the glass")).color;
    let after = render(&[], None).color;
    let (changed, halved, _) = darkening(&before, &after);
    assert!(changed > 500, "the shadow changed only {changed} pixels");
    assert_eq!(
        halved, changed,
        "{changed} pixels changed, {halved} to half their light"
    );

    let settings = ["no-double-blend=off"];
    let before = render(&settings, Some("draw the glass")).color;
    let after = render(&settings, None).color;
    let (changed, _, darker) = darkening(&before, &after);
    assert!(
        darker > changed / 10,
        "without NO_DOUBLE_BLEND only {darker} of {changed} pixels darkened more than once"
    );
}

/// The shadow's outline by ray casting: a floor point is in shadow when the ray from it towards the
/// light meets the skull's mesh. Pixels where the floor is hidden, or on the outline's edge, are not
/// judged.
#[test]
fn the_outline_is_the_silhouette_cast_by_the_light() {
    let mesh = MeshData::load_obj(&default_assets().join("skull.obj")).unwrap();
    let world = skull_world();
    let triangles: Vec<[Vec3; 3]> = mesh
        .indices
        .chunks(3)
        .map(|t| {
            let corner =
                |i: u32| world.transform_point3(Vec3::from(mesh.vertices[i as usize].position));
            [corner(t[0]), corner(t[1]), corner(t[2])]
        })
        .collect();
    let light = key_light("directional", "floor");
    let LightSource::Directional { direction } = light.source else {
        unreachable!()
    };
    let view = View::new(PlanarShadow::CAMERA, SIZE.0, SIZE.1);
    let before = render(&[], Some("draw the glass")).color;
    let after = render(&[], None).color;
    let in_shadow = |x: u32, y: u32| -> Option<bool> {
        let (origin, ray) = view.ray(x, y);
        let w = workbook::room::scene::WALL_HALF_WIDTH;
        let t = hit_y0_rect(
            origin,
            ray,
            -w..=w,
            0.0..=workbook::room::scene::FLOOR_DEPTH,
        )?;
        let half = Vec3::splat(CRATE_SIZE / 2.0);
        let crate_hit = hit_box(origin, ray, CRATE_CENTRE - half, CRATE_CENTRE + half);
        if crate_hit.is_some_and(|c| c < t) || passes_near(origin, ray, SKULL_CENTRE, SKULL_SIZE) {
            return None;
        }
        let floor = origin + ray * t;
        let to_light = -direction.normalize();
        if !passes_near(floor, to_light, SKULL_CENTRE, SKULL_SIZE) {
            return Some(false);
        }
        Some(triangles.iter().any(|tri| ray_hits(floor, to_light, tri)))
    };
    let (mut agree, mut judged) = (0, 0);
    for y in 1..SIZE.1 - 1 {
        for x in 1..SIZE.0 - 1 {
            let Some(expected) = in_shadow(x, y) else {
                continue;
            };
            // Only pixels whose four neighbours agree: the outline's own pixels are half covered.
            let neighbours = [(x - 1, y), (x + 1, y), (x, y - 1), (x, y + 1)];
            if neighbours
                .iter()
                .any(|&(a, b)| in_shadow(a, b) != Some(expected))
            {
                continue;
            }
            let shaded = after.get_pixel(x, y) != before.get_pixel(x, y);
            judged += 1;
            if shaded == expected {
                agree += 1;
            }
        }
    }
    assert!(judged > 5000, "only {judged} floor pixels judged");
    assert_eq!(
        agree,
        judged,
        "{} of {judged} pixels disagree",
        judged - agree
    );
}

/// Möller–Trumbore: does the ray from `origin` along `direction` meet the triangle?
fn ray_hits(origin: Vec3, direction: Vec3, [a, b, c]: &[Vec3; 3]) -> bool {
    let (e1, e2) = (*b - *a, *c - *a);
    let p = direction.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-9 {
        return false;
    }
    let s = origin - *a;
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = direction.dot(q) / det;
    let t = e2.dot(q) / det;
    (0.0..=1.0).contains(&u) && v >= 0.0 && u + v <= 1.0 && t > 1e-4
}

#[test]
fn the_mirror_world_is_lit_by_the_lights_reflected() {
    let r = mirror_reflection();
    for name in ["directional", "point", "spot"] {
        for surface in ["floor", "wall"] {
            let light = key_light(name, surface);
            let mirrored = light.reflected(r);
            match (light.source, mirrored.source) {
                (LightSource::Point { position: p }, LightSource::Point { position: q }) => {
                    assert!(q.abs_diff_eq(r.transform_point3(p), 1e-5), "{name}")
                }
                (
                    LightSource::Directional { direction: d },
                    LightSource::Directional { direction: e },
                ) => {
                    assert!(e.abs_diff_eq(r.transform_vector3(d), 1e-6), "{name}")
                }
                _ => panic!("{name}: a reflected light changed its kind"),
            }
            if let (Some(spot), Some(image)) = (light.spot, mirrored.spot) {
                assert!(image.axis.abs_diff_eq(r.transform_vector3(spot.axis), 1e-6));
                assert_eq!(image.cos_cutoff, spot.cos_cutoff);
            }
            assert_eq!(light.spot.is_some(), name == "spot");
        }
    }
}

/// The stencil after the reflected shadow: the mark in bit 0 everywhere in the mirror, bit 1 set
/// where the shadow is; the glass reads bit 0 only, so it covers the whole mirror — with the whole
/// value read (masks=off) it leaves a hole where the shadow is.
#[test]
fn the_mark_and_the_shadow_share_the_stencil_through_masks() {
    let capture = render(&[], Some("draw the reflected shadow"));
    let values = capture.stencil.unwrap();
    let count = |v: u8| values.iter().filter(|&&s| s == v).count();
    assert!(
        count(1) > 1000,
        "mirror pixels without the shadow: {}",
        count(1)
    );
    assert!(
        count(3) > 100,
        "mirror pixels with the shadow: {}",
        count(3)
    );
    assert_eq!(count(2), 0, "the shadow's bit outside the mark");
    let with = render(&[], None).color;
    let without = render(&["masks=off"], None).color;
    let holes = values
        .iter()
        .enumerate()
        .filter(|&(i, &v)| {
            let (x, y) = (i as u32 % SIZE.0, i as u32 / SIZE.0);
            v == 3 && with.get_pixel(x, y) != without.get_pixel(x, y)
        })
        .count();
    assert_eq!(
        holes,
        count(3),
        "masks=off changes exactly the pixels holding 3"
    );
}

/// Where two surfaces lie at one depth, which wins a pixel is the rasteriser's rounding: the
/// z-fighting picture (`lift=none`) is every driver's own, so everywhere it is judged by what it
/// teaches, and on the driver that drew the book (where it is deterministic) against the book's
/// picture too.
///
/// What it teaches, at the book's size: the unlifted shadow is *speckled*: of the pixels the lifted
/// shadow darkens, some are lost to the floor (they show the floor as it was before the shadow
/// step) and some are kept (they show the shadow); and nothing outside the shadows changes.
/// Measured (share of the lifted shadow's pixels lost to the floor, and kept): lavapipe (Mesa
/// 22.3) 89.1% and 10.9%, an NVIDIA H200 (Vulkan, driver 580) 20.0% and 80.0%, none neither. The limits: at least 5% lost (a lift of 0.2 mm already
/// loses 0.3%), at least 0.5% kept (a shadow sunk under the floor, or not drawn, keeps none: that
/// is not z-fighting), at most 5% neither.
#[test]
fn without_a_lift_the_shadow_fights_the_floor() {
    let book_size = |request: &mut workbook::app::headless::Request| {
        (request.width, request.height) = shots::SIZE;
    };
    let film = shots::film("planar-shadow", &[], book_size).unwrap();
    let fighting = shots::render("planar-shadow", &["lift=none"], book_size)
        .unwrap()
        .color;
    let adapter = workbook::gpu::Gpu::shared_headless(None, false)
        .unwrap()
        .adapter
        .get_info();
    let Fight {
        in_shadow,
        kept,
        lost,
        neither,
        elsewhere,
    } = fight(&film, &fighting);
    let share = |n: usize| n as f32 / in_shadow as f32;
    println!(
        "z-fighting on {}: {in_shadow} shadow pixels, {:.1}% of them lost to the floor, {:.1}% \
         kept, {neither} neither; {elsewhere} pixels visibly different outside the shadows",
        adapter.name,
        share(lost) * 100.0,
        share(kept) * 100.0
    );
    assert!(
        in_shadow > 5000,
        "the lifted shadow covers {in_shadow} pixels"
    );
    assert!(
        share(lost) >= 0.05,
        "without a lift the shadow still wins {:.1}% of its pixels: no z-fighting to see",
        share(kept) * 100.0
    );
    assert!(
        share(kept) >= 0.005,
        "without a lift the shadow is gone ({:.2}% of it kept): sunk or not drawn, not fighting",
        share(kept) * 100.0
    );
    assert!(
        share(neither) <= 0.05,
        "{neither} of the shadow's pixels are neither shadow nor floor without the lift"
    );
    let pixels = (shots::SIZE.0 * shots::SIZE.1) as f32;
    assert!(
        elsewhere as f32 <= 0.0015 * pixels,
        "{elsewhere} pixels outside the shadows changed"
    );
    if shots::drew_the_book(&adapter) {
        let shot = shots::Shot::named("planar-shadow-z-fighting").unwrap();
        shots::check_image(shot.name, &fighting, shot.threshold).unwrap();
        println!("z-fighting: the book's driver, and the book's picture");
    }
}

/// The unlifted shadow's picture against the lifted one's film, in pixels.
struct Fight {
    /// The pixels the lifted shadow darkens.
    in_shadow: usize,
    /// Of those, the pixels the unlifted shadow darkens too, and those it loses to the floor (they
    /// show the floor as it was before the shadow step), and those that are neither.
    kept: usize,
    lost: usize,
    neither: usize,
    /// The pixels visibly different (FLIP) away from both shadows.
    elsewhere: usize,
}

/// Each pixel of the lifted shadow, in the picture without the lift: the shadow's (kept), the
/// floor's as it was before the shadow step (lost), or neither. Both pictures are this driver's,
/// drawn by the same draws: a pixel is one or the other exactly. Away from the shadows (whose
/// outlines move by a pixel or so, 1 cm lower) nothing may change.
fn fight(film: &[Still], fighting: &RgbaImage) -> Fight {
    let at = |step: &str| film.iter().position(|still| still.step == step).unwrap();
    let changed_by = |step: &str| -> Vec<bool> {
        let (before, after) = (&film[at(step) - 1].color, &film[at(step)].color);
        let pairs = before.pixels().zip(after.pixels());
        pairs.map(|(a, b)| a != b).collect()
    };
    let shadow = changed_by("draw the shadow");
    let floor = &film[at("draw the shadow") - 1].color;
    let lifted = &film.last().unwrap().color;
    let reflected = changed_by("draw the reflected shadow");
    let both: Vec<bool> = reflected.iter().zip(&shadow).map(|(a, b)| a | b).collect();
    let near_shadows = grown(&both, shots::SIZE, 2);
    let comparison = workbook_tests::flip::compare(lifted, fighting).unwrap();
    let visible = |i: usize| comparison.errors[i] > workbook_tests::flip::VISIBLE;
    let pixel = |image: &RgbaImage, i: usize| image.as_raw()[4 * i..4 * i + 4].to_vec();
    let count = |keep: &dyn Fn(usize) -> bool| (0..shadow.len()).filter(|&i| keep(i)).count();
    let in_shadow = count(&|i| shadow[i]);
    let kept = count(&|i| shadow[i] && pixel(fighting, i) == pixel(lifted, i));
    let lost = count(&|i| shadow[i] && pixel(fighting, i) == pixel(floor, i));
    Fight {
        in_shadow,
        kept,
        lost,
        neither: in_shadow - kept - lost,
        elsewhere: count(&|i| !near_shadows[i] && visible(i)),
    }
}

/// `mask` grown by `by` pixels in every direction (a square neighbourhood).
fn grown(mask: &[bool], (width, height): (u32, u32), by: i64) -> Vec<bool> {
    let (w, h) = (width as i64, height as i64);
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            (-by..=by).any(|dy| {
                (-by..=by).any(|dx| {
                    let (nx, ny) = (x + dx, y + dy);
                    (0..w).contains(&nx) && (0..h).contains(&ny) && mask[(ny * w + nx) as usize]
                })
            })
        })
        .collect()
}
