//! Lesson 15, against the plane and the solids' shapes: the cap's pixels lie on the plane (their
//! depth, unprojected), and the count (the stencil after "count the inside") is not 0 exactly where
//! the ray meets the plane inside a solid — point-in-mesh by the parity of a ray's crossings of
//! the skull's triangles, on the CPU. Each wrong count disagrees: parity where two solids overlap,
//! and a mesh with a hole.

use glam::{Mat4, Vec3, Vec4Swizzles};
use lessons::capping::{Capping, crate_through, cut_plane};
use workbook::math::reflect::Plane;
use workbook::room::mesh::MeshData;
use workbook::room::scene::{CRATE_SIZE, skull_world};
use workbook::{Lesson, Show, Stop};
use workbook_tests::geometry::{Mesh, View};
use workbook_tests::shots;

/// The size the counts and depths are read at.
pub(crate) const SIZE: (u32, u32) = (320, 180);

fn skull_shape() -> MeshData {
    MeshData::load_obj(&workbook::room::scene::default_assets().join("skull.obj"))
        .expect("the skull's mesh")
}

/// The frame stopped after step `stop`, its stencil and depth read back.
fn render(settings: &[&str], stop: usize) -> workbook::app::headless::Capture {
    shots::render(Capping::NAME, settings, |request| {
        (request.width, request.height) = SIZE;
        request.read_stencil = true;
        request.read_depth = true;
        request.stop = Stop::After(stop);
        request.show = Show::Color;
    })
    .unwrap()
}

/// The solids as rays see them: the skull — whole, even where the lesson draws it with a hole: the
/// hole is the mesh's fault, not the solid's — and the second crate if it goes through.
pub(crate) struct Solids {
    skull: Mesh,
    crate_inverse: Option<Mat4>,
}

impl Solids {
    pub(crate) fn new(settings: &[&str]) -> Self {
        Self::with_skull(&skull_shape(), settings)
    }

    /// The solids with another shape where the skull is (placed as the skull is).
    pub(crate) fn with_skull(shape: &MeshData, settings: &[&str]) -> Self {
        Self {
            skull: Mesh::new(shape, skull_world()),
            crate_inverse: settings
                .contains(&"crate=through")
                .then(|| crate_through().inverse()),
        }
    }

    /// Whether the skull contains `point`: by the parity of a ray's crossings of its triangles (in
    /// a direction no triangle lies along).
    pub(crate) fn in_skull(&self, point: Vec3) -> bool {
        let direction = Vec3::new(0.31, 0.83, 0.47).normalize();
        self.skull.crossings(point, direction) % 2 == 1
    }

    /// Whether the second crate, if it goes through, contains `point`: by its box.
    pub(crate) fn in_crate(&self, point: Vec3) -> bool {
        let half = CRATE_SIZE / 2.0;
        self.crate_inverse.is_some_and(|inverse| {
            let local = inverse.transform_point3(point);
            local.abs().max_element() < half
        })
    }

    /// How many of the solids contain `point`.
    pub(crate) fn containing(&self, point: Vec3) -> u32 {
        self.in_skull(point) as u32 + self.in_crate(point) as u32
    }
}

/// Where the ray through a point of the picture meets the plane, if in front of the eye.
fn on_plane(view: &View, plane: Plane, x: f32, y: f32) -> Option<Vec3> {
    let (origin, direction) = view.ray_at(x, y);
    let along = direction.dot(plane.normal);
    let t = -(plane.normal.dot(origin) + plane.d) / along;
    (along.abs() > 1e-6 && t > 0.0).then(|| origin + direction * t)
}

/// At the pixels judged — those whose four corners' rays meet the plane where `oracle` says what
/// it says at the centre's — how many `counts` (the stencil, row by row at `SIZE`) disagree with
/// the oracle, as `agree` tells: (judged, disagreeing).
pub(crate) fn judge_on_plane<T: PartialEq + Copy>(
    counts: &[u8],
    oracle: impl Fn(Vec3) -> T,
    agree: impl Fn(u8, T) -> bool,
) -> (usize, usize) {
    let view = View::new(Capping::CAMERA, SIZE.0, SIZE.1);
    let plane = cut_plane(0.0);
    let at = |x: f32, y: f32| on_plane(&view, plane, x, y).map(&oracle);
    let (mut judged, mut wrong) = (0, 0);
    for y in 0..SIZE.1 {
        for x in 0..SIZE.0 {
            let (fx, fy) = (x as f32, y as f32);
            let Some(centre) = at(fx + 0.5, fy + 0.5) else {
                continue;
            };
            let corners = [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)];
            if corners
                .iter()
                .any(|&(dx, dy)| at(fx + dx, fy + dy) != Some(centre))
            {
                continue;
            }
            judged += 1;
            if !agree(counts[(y * SIZE.0 + x) as usize], centre) {
                wrong += 1;
            }
        }
    }
    (judged, wrong)
}

/// The pixels judged, and at how many the count disagrees with "inside a solid" (not 0 where the
/// point lies in one solid at least).
fn disagreements(settings: &[&str]) -> (usize, usize) {
    let solids = Solids::new(settings);
    let counts = render(settings, 4).stencil.unwrap();
    let inside = |count: u8, solids: u32| (count != 0) == (solids > 0);
    let (judged, wrong) = judge_on_plane(&counts, |p| solids.containing(p), inside);
    eprintln!("{settings:?}: {wrong} of {judged} judged pixels disagree");
    (judged, wrong)
}

#[test]
fn the_count_is_not_zero_exactly_where_the_plane_is_inside_a_solid() {
    for settings in [&[][..], &["crate=through"]] {
        let (judged, wrong) = disagreements(settings);
        assert!(judged > 30_000, "{settings:?}: only {judged} pixels judged");
        assert_eq!(
            wrong, 0,
            "{settings:?}: {wrong} of {judged} pixels disagree"
        );
    }
}

#[test]
fn each_wrong_count_disagrees_with_the_solids() {
    for settings in [&["crate=through", "count=invert"][..], &["mesh=holed"]] {
        let (judged, wrong) = disagreements(settings);
        assert!(
            wrong > 100,
            "{settings:?}: only {wrong} of {judged} pixels disagree"
        );
    }
}

/// Every pixel the cap drew (its depth changed by "draw the cap") lies on the plane.
#[test]
fn the_caps_pixels_lie_on_the_plane() {
    let before = render(&[], 4).depth.unwrap();
    let after = render(&[], 5).depth.unwrap();
    let view = View::new(Capping::CAMERA, SIZE.0, SIZE.1);
    let inverse = view.view_projection().inverse();
    let plane = cut_plane(0.0);
    let mut drawn = 0;
    for (index, (a, b)) in before.iter().zip(&after).enumerate() {
        if a == b {
            continue;
        }
        drawn += 1;
        let (x, y) = (index as u32 % SIZE.0, index as u32 / SIZE.0);
        let ndc = Vec3::new(
            (x as f32 + 0.5) / SIZE.0 as f32 * 2.0 - 1.0,
            1.0 - (y as f32 + 0.5) / SIZE.1 as f32 * 2.0,
            *b,
        );
        let world = inverse * ndc.extend(1.0);
        let point = world.xyz() / world.w;
        let distance = plane.normal.dot(point) + plane.d;
        assert!(
            distance.abs() < 0.005,
            "pixel ({x}, {y}) lies {distance} m off the plane"
        );
    }
    assert!(drawn > 1_000, "the cap drew only {drawn} pixels");
}
