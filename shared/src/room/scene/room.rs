//! The room itself: where everything stands, the sky it is seen against, its meshes and textures,
//! and the objects made of them.

use glam::{Mat4, Vec2, Vec3};

use super::drawables::{Drawable, DrawableMaker};
use super::materials::{
    FENCE_MATERIAL, FLOOR_MIRROR_MATERIAL, MIRROR_MATERIAL, ROOM_MATERIAL, SKULL_MATERIAL,
    WATER_MATERIAL,
};
use crate::room::assets::{Assets, TEXTURE_FILES};
use crate::room::mesh::MeshData;
use crate::room::texture;

/// Where the mirror is: the plane z = 0, x in -2.5..2.5, y in 0..4.
pub const MIRROR_MIN: Vec3 = Vec3::new(-2.5, 0.0, 0.0);
pub const MIRROR_MAX: Vec3 = Vec3::new(2.5, 4.0, 0.0);
/// The wall around it: x in -6..6, y in 0..5.
pub const WALL_HALF_WIDTH: f32 = 6.0;
pub const WALL_HEIGHT: f32 = 5.0;
/// The wall is a solid block behind the mirror's plane, this thick.
pub const WALL_THICKNESS: f32 = 0.25;
/// The floor runs from the wall to z = 12.
pub const FLOOR_DEPTH: f32 = 12.0;
/// The crate: a cube standing on the floor, in front of the mirror's lower right corner.
pub const CRATE_SIZE: f32 = 1.4;
pub const CRATE_CENTRE: Vec3 = Vec3::new(2.2, CRATE_SIZE / 2.0, 1.6);
/// The wire-fence crate, to the left in front of the mirror.
pub const FENCE_SIZE: f32 = 1.6;
pub const FENCE_CENTRE: Vec3 = Vec3::new(-3.4, FENCE_SIZE / 2.0, 2.4);
/// The water: a shallow pool on the floor that runs up to the mirror, its surface 25 cm above the
/// tiles, so the mirror's lowest strip is seen through it.
pub const WATER_MIN: Vec3 = Vec3::new(-1.5, 0.25, 0.0);
pub const WATER_MAX: Vec3 = Vec3::new(1.2, 0.25, 2.8);
/// The skull: where its bounding box's centre goes, how tall it is, how far it is turned.
pub const SKULL_CENTRE: Vec3 = Vec3::new(-0.5, 1.5, 2.5);
pub const SKULL_SIZE: f32 = 1.7;
pub const SKULL_YAW_DEGREES: f32 = 50.0;
/// The floor mirror of lesson 8: a slab of polished stone set into the floor (the plane y = 0),
/// x in -4..4, z in 0.3..5.3 — the crate stands on it, the skull floats above it.
pub const FLOOR_MIRROR_MIN: Vec3 = Vec3::new(-4.0, 0.0, 0.3);
pub const FLOOR_MIRROR_MAX: Vec3 = Vec3::new(4.0, 0.0, 5.3);
/// The sky, what every frame is cleared to: a dark slate (Luna clears to a light steel blue). Dark,
/// so that a mirror with nothing reflected in it yet reads as dark glass, and what is missing from a
/// reflection shows as a dark gap.
pub const CLEAR_SRGB: [u8; 3] = [36, 42, 56];

/// The room's textures on the GPU, and a white one for the skull.
pub(super) struct RoomTextures {
    checker: wgpu::TextureView,
    bricks: wgpu::TextureView,
    ice: wgpu::TextureView,
    crate_image: wgpu::TextureView,
    fence_image: wgpu::TextureView,
    water_image: wgpu::TextureView,
    white: wgpu::TextureView,
}

impl RoomTextures {
    /// Uploads the pictures of `assets`, and makes the white one.
    pub(super) fn upload(device: &wgpu::Device, queue: &wgpu::Queue, assets: &Assets) -> Self {
        // Each picture uploaded once (the floor and the floor mirror share theirs).
        let [checker, bricks, ice, crate_image, fence_image, water_image] =
            std::array::from_fn(|i| {
                let name = TEXTURE_FILES[i].trim_end_matches(".png");
                texture::upload(
                    device,
                    queue,
                    &format!("{name} texture"),
                    &assets.textures[i],
                )
            });
        let white =
            texture::Mipmapped::new(image::RgbaImage::from_pixel(1, 1, image::Rgba([255; 4])));
        let white = texture::upload(device, queue, "white texture", &white);
        Self {
            checker,
            bricks,
            ice,
            crate_image,
            fence_image,
            water_image,
            white,
        }
    }
}

/// The room's objects, as [`Scene`](super::Scene) holds them.
pub(super) struct RoomObjects {
    pub(super) floor: Drawable,
    pub(super) wall: Drawable,
    pub(super) mirror: Drawable,
    pub(super) crate_box: Drawable,
    pub(super) skull: Drawable,
    pub(super) fence_box: Drawable,
    pub(super) water: Drawable,
    pub(super) floor_mirror: Drawable,
    pub(super) floor_around_mirror: Drawable,
}

impl RoomObjects {
    /// Every object of the room, the skull made of `skull_mesh`.
    pub(super) fn new(
        maker: &DrawableMaker,
        textures: &RoomTextures,
        skull_mesh: &MeshData,
    ) -> Self {
        let t = textures;
        let object = |name, mesh: &MeshData, world, material, view: &wgpu::TextureView| {
            maker.drawable(name, mesh, world, material, view, Vec2::ONE)
        };
        // Most meshes are modelled where they stand; the crates are moved into place, and the skull
        // turned and scaled too (`skull_world`).
        let (here, at) = (Mat4::IDENTITY, Mat4::from_translation);
        Self {
            floor: object("floor", &floor_mesh(), here, ROOM_MATERIAL, &t.checker),
            wall: object("wall", &wall_mesh(), here, ROOM_MATERIAL, &t.bricks),
            mirror: object("mirror", &mirror_mesh(), here, MIRROR_MATERIAL, &t.ice),
            crate_box: object(
                "crate",
                &MeshData::cuboid(Vec3::splat(CRATE_SIZE)),
                at(CRATE_CENTRE),
                ROOM_MATERIAL,
                &t.crate_image,
            ),
            skull: object("skull", skull_mesh, skull_world(), SKULL_MATERIAL, &t.white),
            fence_box: object(
                "wire-fence crate",
                &MeshData::cuboid(Vec3::splat(FENCE_SIZE)),
                at(FENCE_CENTRE),
                FENCE_MATERIAL,
                &t.fence_image,
            ),
            water: object("water", &water_mesh(), here, WATER_MATERIAL, &t.water_image),
            floor_mirror: object(
                "floor mirror",
                &floor_mirror_mesh(),
                here,
                FLOOR_MIRROR_MATERIAL,
                &t.ice,
            ),
            floor_around_mirror: object(
                "floor around the mirror",
                &floor_around_mirror_mesh(),
                here,
                ROOM_MATERIAL,
                &t.checker,
            ),
        }
    }
}

/// Where the skull stands: turned towards the camera's side, so the mirror shows its other side.
pub fn skull_world() -> Mat4 {
    Mat4::from_translation(SKULL_CENTRE)
        * Mat4::from_rotation_y(SKULL_YAW_DEGREES.to_radians())
        * Mat4::from_scale(Vec3::splat(SKULL_SIZE))
}

/// The floor: one 4 m checker tile repeated.
fn floor_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let width = 2.0 * WALL_HALF_WIDTH;
    mesh.add_quad(
        Vec3::new(-WALL_HALF_WIDTH, 0.0, FLOOR_DEPTH),
        Vec3::X * width,
        -Vec3::Z * FLOOR_DEPTH,
        Vec2::new(width, FLOOR_DEPTH) / 4.0,
    );
    mesh
}

/// The wall: three solid blocks around the mirror's opening, WALL_THICKNESS deep behind the plane
/// z = 0, so it has a back a camera behind it can see. Bricks are laid by position, so the courses
/// line up across the blocks.
fn wall_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let (w, h, t) = (WALL_HALF_WIDTH, WALL_HEIGHT, WALL_THICKNESS);
    let (a, b) = (MIRROR_MIN, MIRROR_MAX);
    // (left, bottom) and (right, top) of each block's face.
    for (min, max) in [
        (Vec2::new(-w, 0.0), Vec2::new(a.x, b.y)),
        (Vec2::new(b.x, 0.0), Vec2::new(w, b.y)),
        (Vec2::new(-w, b.y), Vec2::new(w, h)),
    ] {
        let size = (max - min).extend(t);
        let centre = ((min + max) / 2.0).extend(-t / 2.0);
        mesh.append(MeshData::cuboid(size).translated(centre));
    }
    // One brick texture per 2 m, projected along each face's normal.
    for vertex in &mut mesh.vertices {
        let [x, y, z] = vertex.position;
        let n = Vec3::from(vertex.normal).abs();
        vertex.uv = if n.z > 0.5 {
            [x / 2.0, -y / 2.0]
        } else if n.x > 0.5 {
            [z / 2.0, -y / 2.0]
        } else {
            [x / 2.0, z / 2.0]
        };
    }
    mesh
}

/// Lesson 8's stone mirror: one slab of the floor, facing up.
fn floor_mirror_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let size = FLOOR_MIRROR_MAX - FLOOR_MIRROR_MIN;
    let near_left = Vec3::new(FLOOR_MIRROR_MIN.x, 0.0, FLOOR_MIRROR_MAX.z);
    mesh.add_quad(
        near_left,
        Vec3::X * size.x,
        -Vec3::Z * size.z,
        Vec2::new(2.0, 1.25),
    );
    mesh
}

/// The floor with a hole where lesson 8's stone mirror lies (no two surfaces in one plane, so no
/// z-fighting): four strips around it, the checker tiles laid by position so they line up.
fn floor_around_mirror_mesh() -> MeshData {
    let (w, depth) = (WALL_HALF_WIDTH, FLOOR_DEPTH);
    let (a, b) = (FLOOR_MIRROR_MIN, FLOOR_MIRROR_MAX);
    let mut mesh = MeshData::default();
    // (x0, z0) to (x1, z1) of each strip: behind, in front of, left of and right of the slab.
    for (x0, z0, x1, z1) in [
        (-w, 0.0, w, a.z),
        (-w, b.z, w, depth),
        (-w, a.z, a.x, b.z),
        (b.x, a.z, w, b.z),
    ] {
        mesh.add_quad(
            Vec3::new(x0, 0.0, z1),
            Vec3::X * (x1 - x0),
            -Vec3::Z * (z1 - z0),
            Vec2::new(x1 - x0, z1 - z0) / 4.0,
        );
    }
    // One 4 m tile, by position, as the whole floor lays it.
    for vertex in &mut mesh.vertices {
        let [x, _, z] = vertex.position;
        vertex.uv = [(x + w) / 4.0, z / 4.0];
    }
    mesh
}

/// Lesson 7's water: one quad at the surface's height, the texture once per 2 m.
fn water_mesh() -> MeshData {
    let water_size = WATER_MAX - WATER_MIN;
    let mut water_mesh = MeshData::default();
    water_mesh.add_quad(
        Vec3::new(WATER_MIN.x, WATER_MIN.y, WATER_MAX.z),
        Vec3::X * water_size.x,
        -Vec3::Z * water_size.z,
        Vec2::new(water_size.x, water_size.z) / 2.0,
    );
    water_mesh
}

fn mirror_mesh() -> MeshData {
    let mut mesh = MeshData::default();
    let size = MIRROR_MAX - MIRROR_MIN;
    mesh.add_quad(MIRROR_MIN, Vec3::X * size.x, Vec3::Y * size.y, Vec2::ONE);
    mesh
}
