//! Independent expectations: where things land on screen, computed on the CPU from the camera and the
//! room's dimensions alone — never from a render.

use glam::{Mat4, Vec3, Vec4Swizzles};
use workbook::room::camera::Camera;
use workbook::room::mesh::MeshData;
use workbook::room::scene::{
    CRATE_CENTRE, CRATE_SIZE, FLOOR_DEPTH, MIRROR_MAX, MIRROR_MIN, WALL_HALF_WIDTH, WALL_HEIGHT,
    WALL_THICKNESS, skull_world,
};

/// A camera looking at a target of a given size in pixels.
#[derive(Debug, Clone, Copy)]
pub struct View {
    pub camera: Camera,
    pub width: u32,
    pub height: u32,
}

impl View {
    pub const fn new(camera: Camera, width: u32, height: u32) -> Self {
        Self {
            camera,
            width,
            height,
        }
    }

    pub fn view_projection(&self) -> Mat4 {
        self.camera
            .view_projection(self.width as f32 / self.height as f32)
    }

    /// The ray from the eye through the centre of pixel (x, y): origin on the near plane, unit direction.
    pub fn ray(&self, x: u32, y: u32) -> (Vec3, Vec3) {
        self.ray_at(x as f32 + 0.5, y as f32 + 0.5)
    }

    /// The ray from the eye through a point of the picture, in pixels from its top left corner.
    pub fn ray_at(&self, x: f32, y: f32) -> (Vec3, Vec3) {
        let inverse = self.view_projection().inverse();
        let ndc_x = x / self.width as f32 * 2.0 - 1.0;
        let ndc_y = 1.0 - y / self.height as f32 * 2.0;
        let unproject = |z: f32| {
            let p = inverse * glam::Vec4::new(ndc_x, ndc_y, z, 1.0);
            p.xyz() / p.w
        };
        let (near, far) = (unproject(0.0), unproject(1.0));
        (near, (far - near).normalize())
    }

    /// Where wgpu's depth range puts a world point: clip z / clip w, 0 at the near plane, 1 at the far.
    pub fn depth_of(&self, point: Vec3) -> f32 {
        let clip = self.view_projection() * point.extend(1.0);
        clip.z / clip.w
    }

    /// The pixel a world point lands in.
    pub fn pixel_of(&self, point: Vec3) -> (u32, u32) {
        let clip = self.view_projection() * point.extend(1.0);
        let ndc = clip.xyz() / clip.w;
        (
            ((ndc.x + 1.0) / 2.0 * self.width as f32) as u32,
            ((1.0 - ndc.y) / 2.0 * self.height as f32) as u32,
        )
    }

    /// Every pixel, in rows.
    pub fn pixels(&self) -> impl Iterator<Item = (u32, u32)> + use<> {
        let (w, h) = (self.width, self.height);
        (0..h).flat_map(move |y| (0..w).map(move |x| (x, y)))
    }

    /// Whether `classify` gives pixel (x, y) the same answer as its four neighbours: pixels on an edge
    /// may go either way under the rasteriser's rules, so tests skip them.
    pub fn inside_region<T: PartialEq>(
        &self,
        x: u32,
        y: u32,
        classify: impl Fn(u32, u32) -> T,
    ) -> bool {
        let here = classify(x, y);
        [(0i32, 1i32), (1, 0), (0, -1), (-1, 0)]
            .iter()
            .all(|&(dx, dy)| {
                let (nx, ny) = (x as i32 + dx, y as i32 + dy);
                let outside =
                    nx < 0 || ny < 0 || nx >= self.width as i32 || ny >= self.height as i32;
                outside || classify(nx as u32, ny as u32) == here
            })
    }
}

/// Where the ray meets the plane z = 0 inside the rectangle `min`..`max` (x and y), if it does.
pub fn hit_z0_rect(origin: Vec3, direction: Vec3, min: Vec3, max: Vec3) -> Option<f32> {
    let t = -origin.z / direction.z;
    let p = origin + direction * t;
    let inside = (min.x..=max.x).contains(&p.x) && (min.y..=max.y).contains(&p.y);
    (t > 0.0 && inside).then_some(t)
}

/// Where the ray meets the plane y = 0 inside x in `x_range` and z in `z_range`, if it does.
pub fn hit_y0_rect(
    origin: Vec3,
    direction: Vec3,
    x_range: std::ops::RangeInclusive<f32>,
    z_range: std::ops::RangeInclusive<f32>,
) -> Option<f32> {
    let t = -origin.y / direction.y;
    let p = origin + direction * t;
    (t > 0.0 && x_range.contains(&p.x) && z_range.contains(&p.z)).then_some(t)
}

/// Where the ray enters an axis-aligned box, if it does (the slab test).
pub fn hit_box(origin: Vec3, direction: Vec3, min: Vec3, max: Vec3) -> Option<f32> {
    let inverse = direction.recip();
    let (a, b) = ((min - origin) * inverse, (max - origin) * inverse);
    let (near, far) = (a.min(b).max_element(), a.max(b).min_element());
    (near <= far && far > 0.0).then_some(near.max(0.0))
}

/// Whether the ray passes within `radius` of `centre`.
pub fn passes_near(origin: Vec3, direction: Vec3, centre: Vec3, radius: f32) -> bool {
    let along = (centre - origin).dot(direction);
    (origin + direction * along).distance(centre) < radius
}

/// Where a ray meets a triangle (Möller–Trumbore): the distance along it, for a hit in front of
/// the origin. Both faces count.
pub fn hit_triangle(origin: Vec3, direction: Vec3, [a, b, c]: [Vec3; 3]) -> Option<f32> {
    let (ab, ac) = (b - a, c - a);
    let p = direction.cross(ac);
    let determinant = ab.dot(p);
    if determinant.abs() < 1e-12 {
        return None;
    }
    let inverse = 1.0 / determinant;
    let t_vec = origin - a;
    let u = t_vec.dot(p) * inverse;
    let q = t_vec.cross(ab);
    let v = direction.dot(q) * inverse;
    let t = ac.dot(q) * inverse;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some(t)
}

/// A triangle mesh in the world, ready for rays: a bounding-volume hierarchy over its triangles
/// (each node a box; leaves of a few triangles), so that a ray tests tens of triangles, not all.
pub struct Mesh {
    pub triangles: Vec<[Vec3; 3]>,
    /// (box min, box max, children or leaf): a leaf holds a range of `triangles`.
    nodes: Vec<(Vec3, Vec3, Node)>,
}

enum Node {
    Inner(usize, usize),
    Leaf(usize, usize),
}

impl Mesh {
    /// The mesh of `data` placed by `world`.
    pub fn new(data: &workbook::room::mesh::MeshData, world: Mat4) -> Self {
        let point = |i: u32| world.transform_point3(Vec3::from(data.vertices[i as usize].position));
        let triangles = (data.indices.chunks_exact(3))
            .map(|t| [point(t[0]), point(t[1]), point(t[2])])
            .collect();
        let mut mesh = Self {
            triangles,
            nodes: Vec::new(),
        };
        let count = mesh.triangles.len();
        mesh.build(0, count);
        mesh
    }

    fn build(&mut self, start: usize, end: usize) -> usize {
        let corners = self.triangles[start..end].iter().flatten();
        let (min, max) = corners.fold((Vec3::MAX, Vec3::MIN), |(lo, hi), p| {
            (lo.min(*p), hi.max(*p))
        });
        let index = self.nodes.len();
        self.nodes.push((min, max, Node::Leaf(start, end)));
        if end - start > 8 {
            let axis = (max - min).max_position();
            let centre = |t: &[Vec3; 3]| (t[0] + t[1] + t[2])[axis];
            self.triangles[start..end].sort_by(|a, b| centre(a).total_cmp(&centre(b)));
            let middle = (start + end) / 2;
            let left = self.build(start, middle);
            let right = self.build(middle, end);
            self.nodes[index].2 = Node::Inner(left, right);
        }
        index
    }

    /// How many triangles the ray crosses (in front of its origin): odd where the origin lies
    /// inside a closed mesh.
    pub fn crossings(&self, origin: Vec3, direction: Vec3) -> usize {
        let mut count = 0;
        let mut stack = vec![0];
        while let Some(node) = stack.pop() {
            let (min, max, ref kind) = self.nodes[node];
            if hit_box(origin, direction, min, max).is_none() {
                continue;
            }
            match *kind {
                Node::Inner(left, right) => stack.extend([left, right]),
                Node::Leaf(start, end) => {
                    let triangles = self.triangles[start..end].iter();
                    count += triangles
                        .filter(|t| hit_triangle(origin, direction, **t).is_some())
                        .count();
                }
            }
        }
        count
    }

    /// The nearest hit along the ray, closer than `limit`: its distance and its triangle.
    pub fn hit(&self, origin: Vec3, direction: Vec3, limit: f32) -> Option<(f32, [Vec3; 3])> {
        self.nearest(origin, direction, limit, false)
    }

    /// [`Mesh::hit`] among the triangles the ray meets from their front (counter-clockwise as it
    /// sees them): what a draw that culls back faces shows.
    pub fn hit_front(&self, origin: Vec3, direction: Vec3) -> Option<(f32, [Vec3; 3])> {
        self.nearest(origin, direction, f32::MAX, true)
    }

    fn nearest(
        &self,
        origin: Vec3,
        direction: Vec3,
        limit: f32,
        front_only: bool,
    ) -> Option<(f32, [Vec3; 3])> {
        let facing =
            |[a, b, c]: &[Vec3; 3]| !front_only || (b - a).cross(c - a).dot(direction) < 0.0;
        let mut best: Option<(f32, [Vec3; 3])> = None;
        let mut stack = vec![0];
        while let Some(node) = stack.pop() {
            let (min, max, ref kind) = self.nodes[node];
            let nearest = best.map_or(limit, |(t, _)| t);
            match hit_box(origin, direction, min, max) {
                Some(t) if t < nearest => {}
                _ => continue,
            }
            match *kind {
                Node::Inner(left, right) => stack.extend([left, right]),
                Node::Leaf(start, end) => {
                    for triangle in self.triangles[start..end].iter().filter(|t| facing(t)) {
                        if let Some(t) = hit_triangle(origin, direction, *triangle)
                            && t < best.map_or(limit, |(b, _)| b)
                        {
                            best = Some((t, *triangle));
                        }
                    }
                }
            }
        }
        best
    }
}

/// What a ray from the eye meets first in the room.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Surface {
    Floor,
    Wall,
    Mirror,
    Crate,
    Skull,
}

/// A visible point: the surface, where it is, and its outward normal.
pub struct Seen {
    pub surface: Surface,
    pub point: Vec3,
    pub normal: Vec3,
}

/// The room as rays see it: floor, wall, mirror, crate and skull, where the lessons draw them, each
/// seen from its front (the lessons cull back faces).
pub struct RoomRays {
    pub skull: Mesh,
}

impl Default for RoomRays {
    fn default() -> Self {
        Self::new()
    }
}

impl RoomRays {
    /// The room, its skull read from the workbook's assets.
    pub fn new() -> Self {
        let assets = workbook::room::scene::default_assets();
        let skull = MeshData::load_obj(&assets.join("skull.obj")).expect("the skull's mesh");
        Self {
            skull: Mesh::new(&skull, skull_world()),
        }
    }

    /// The first surface the ray meets, seen from its front (the lesson culls back faces).
    pub fn see(&self, origin: Vec3, direction: Vec3) -> Option<Seen> {
        let (w, h, t) = (WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS);
        let (a, b) = (MIRROR_MIN, MIRROR_MAX);
        let mut hits: Vec<(f32, Surface, Vec3)> = Vec::new();
        if direction.y < 0.0
            && let Some(d) = hit_y0_rect(origin, direction, -w..=w, 0.0..=FLOOR_DEPTH)
        {
            hits.push((d, Surface::Floor, Vec3::Y));
        }
        if direction.z < 0.0
            && let Some(d) = hit_z0_rect(origin, direction, a, b)
        {
            hits.push((d, Surface::Mirror, Vec3::Z));
        }
        let blocks = [
            (Vec3::new(-w, 0.0, -t), Vec3::new(a.x, b.y, 0.0)),
            (Vec3::new(b.x, 0.0, -t), Vec3::new(w, b.y, 0.0)),
            (Vec3::new(-w, b.y, -t), Vec3::new(w, h, 0.0)),
        ];
        let half = Vec3::splat(CRATE_SIZE / 2.0);
        let boxes = (blocks.iter().map(|&(min, max)| (min, max, Surface::Wall))).chain([(
            CRATE_CENTRE - half,
            CRATE_CENTRE + half,
            Surface::Crate,
        )]);
        for (min, max, surface) in boxes {
            if let Some(d) = hit_box(origin, direction, min, max) {
                hits.push((d, surface, box_normal(origin + direction * d, min, max)));
            }
        }
        if let Some((d, [p, q, r])) = self.skull.hit_front(origin, direction) {
            hits.push((d, Surface::Skull, (q - p).cross(r - p).normalize()));
        }
        let (d, surface, normal) = hits.into_iter().min_by(|x, y| x.0.total_cmp(&y.0))?;
        Some(Seen {
            surface,
            point: origin + direction * d,
            normal,
        })
    }
}

/// The normal of the box face a point lies on.
fn box_normal(point: Vec3, min: Vec3, max: Vec3) -> Vec3 {
    let faces = [
        ((point.x - min.x).abs(), -Vec3::X),
        ((point.x - max.x).abs(), Vec3::X),
        ((point.y - min.y).abs(), -Vec3::Y),
        ((point.y - max.y).abs(), Vec3::Y),
        ((point.z - min.z).abs(), -Vec3::Z),
        ((point.z - max.z).abs(), Vec3::Z),
    ];
    faces
        .into_iter()
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap()
        .1
}
