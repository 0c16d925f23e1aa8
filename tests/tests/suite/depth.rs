//! The depth buffer read back and checked against an independent expectation: the room's floor and
//! wall are planes, so the depth they leave at a pixel follows from the camera alone — cast the ray
//! through the pixel, intersect the plane, project the point.

use glam::{Mat4, Vec3, Vec4Swizzles};
use workbook::camera::Camera;
use workbook::headless::Capture;
use workbook::scene::{
    CRATE_CENTRE, CRATE_SIZE, FLOOR_DEPTH, SKULL_CENTRE, SKULL_SIZE, WALL_HALF_WIDTH, WALL_HEIGHT,
};
use workbook_tests::shots;

const W: u32 = 320;
const H: u32 = 180;

fn render(settings: &[&str]) -> Capture {
    shots::render("depth-test", settings, |request| {
        (request.width, request.height) = (W, H);
        request.read_depth = true;
    })
    .unwrap()
}

fn view_projection() -> Mat4 {
    Camera::default().view_projection(W as f32 / H as f32)
}

/// The ray from the eye through the centre of pixel (x, y).
fn ray(x: u32, y: u32) -> (Vec3, Vec3) {
    let inverse = view_projection().inverse();
    let ndc_x = (x as f32 + 0.5) / W as f32 * 2.0 - 1.0;
    let ndc_y = 1.0 - (y as f32 + 0.5) / H as f32 * 2.0;
    let unproject = |z: f32| {
        let p = inverse * glam::Vec4::new(ndc_x, ndc_y, z, 1.0);
        p.xyz() / p.w
    };
    let (near, far) = (unproject(0.0), unproject(1.0));
    (near, (far - near).normalize())
}

/// The nearest point where the ray meets the floor (y = 0) or the wall-and-mirror (z = 0), if any.
fn room_hit(origin: Vec3, direction: Vec3) -> Option<Vec3> {
    let mut hits = Vec::new();
    let t_floor = -origin.y / direction.y;
    let p = origin + direction * t_floor;
    if t_floor > 0.0 && p.x.abs() <= WALL_HALF_WIDTH && (0.0..=FLOOR_DEPTH).contains(&p.z) {
        hits.push((t_floor, p));
    }
    let t_wall = -origin.z / direction.z;
    let p = origin + direction * t_wall;
    if t_wall > 0.0 && p.x.abs() <= WALL_HALF_WIDTH && (0.0..=WALL_HEIGHT).contains(&p.y) {
        hits.push((t_wall, p));
    }
    hits.into_iter()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, p)| p)
}

/// Whether the ray passes near the skull or the crate (generously: their bounding spheres).
fn near_an_object(origin: Vec3, direction: Vec3) -> bool {
    let spheres = [
        (SKULL_CENTRE, SKULL_SIZE * 0.9),
        (CRATE_CENTRE, CRATE_SIZE * 0.9),
    ];
    spheres.iter().any(|&(centre, radius)| {
        let along = (centre - origin).dot(direction);
        (origin + direction * along).distance(centre) < radius
    })
}

/// Where wgpu's depth range puts a world point: clip z / clip w, 0 at the near plane, 1 at the far.
fn depth_of(point: Vec3) -> f32 {
    let clip = view_projection() * point.extend(1.0);
    clip.z / clip.w
}

/// Skips pixels whose neighbours see something else: an edge may go either way.
fn inside_region(x: u32, y: u32, hit: &dyn Fn(u32, u32) -> Option<Vec3>) -> bool {
    let here = hit(x, y).is_some();
    [(0i32, 1i32), (1, 0), (0, -1), (-1, 0)]
        .iter()
        .all(|&(dx, dy)| {
            let (nx, ny) = (x as i32 + dx, y as i32 + dy);
            nx < 0
                || ny < 0
                || nx >= W as i32
                || ny >= H as i32
                || hit(nx as u32, ny as u32).is_some() == here
        })
}

#[test]
fn the_room_leaves_the_depth_its_planes_predict() {
    let capture = render(&[]);
    let hit = |x: u32, y: u32| {
        let (origin, direction) = ray(x, y);
        if near_an_object(origin, direction) {
            return None;
        }
        room_hit(origin, direction)
    };
    let (mut checked, mut sky) = (0, 0);
    for y in (0..H).step_by(3) {
        for x in (0..W).step_by(3) {
            let (origin, direction) = ray(x, y);
            if near_an_object(origin, direction) || !inside_region(x, y, &hit) {
                continue;
            }
            let stored = capture.depth_at(x, y).unwrap();
            match room_hit(origin, direction) {
                Some(point) => {
                    let expected = depth_of(point);
                    assert!(
                        (stored - expected).abs() < 2e-5,
                        "pixel ({x}, {y}) sees {point:?}: expected depth {expected}, stored {stored}"
                    );
                    checked += 1;
                }
                None => {
                    assert_eq!(
                        stored, 1.0,
                        "pixel ({x}, {y}) sees the sky: depth stays cleared"
                    );
                    sky += 1;
                }
            }
        }
    }
    assert!(checked > 3000, "only {checked} room pixels checked");
    assert!(sky > 100, "only {sky} sky pixels checked");
}

/// The pixel at the middle of the skull.
fn skull_pixel() -> (u32, u32) {
    let clip = view_projection() * SKULL_CENTRE.extend(1.0);
    let ndc = clip.xyz() / clip.w;
    (
        ((ndc.x + 1.0) / 2.0 * W as f32) as u32,
        ((1.0 - ndc.y) / 2.0 * H as f32) as u32,
    )
}

#[test]
fn the_skull_is_nearer_than_the_wall_behind_it() {
    let (x, y) = skull_pixel();
    let behind = depth_of(room_hit(ray(x, y).0, ray(x, y).1).unwrap());
    let stored = render(&[]).depth_at(x, y).unwrap();
    assert!(
        stored < behind - 1e-4,
        "skull {stored}, room behind it {behind}"
    );
}

/// The classic wrong picture: with depth=always the last object drawn wins, so where the skull was
/// drawn first, the room drawn after it holds the pixel — at exactly the room's depth.
#[test]
fn with_depth_always_the_room_is_drawn_over_the_skull() {
    let (x, y) = skull_pixel();
    let behind = depth_of(room_hit(ray(x, y).0, ray(x, y).1).unwrap());
    let stored = render(&["depth=always"]).depth_at(x, y).unwrap();
    assert!(
        (stored - behind).abs() < 2e-5,
        "stored {stored}, room {behind}"
    );
    let painter = render(&["depth=always", "order=far-first"])
        .depth_at(x, y)
        .unwrap();
    assert!(
        painter < behind - 1e-4,
        "the painter's order draws the skull last"
    );
}
