//! What the room is made of: the surfaces' materials (Luna's `Material`s, Blinn-Phong).

use glam::Vec3;

/// A surface's response to light, as Luna's `Material`.
#[derive(Debug, Clone, Copy)]
pub struct Material {
    pub ambient: Vec3,
    pub diffuse: Vec3,
    /// Opacity used when the material is blended (the mirror's is 0.5).
    pub alpha: f32,
    pub specular: Vec3,
    pub shininess: f32,
    /// Texels whose alpha is below this are thrown away (0: none are); the wire fence's holes.
    pub alpha_cutoff: f32,
}

/// Luna's room and skull material: half ambient, full diffuse, a dull highlight.
pub const ROOM_MATERIAL: Material = Material {
    ambient: Vec3::splat(0.5),
    diffuse: Vec3::ONE,
    alpha: 1.0,
    specular: Vec3::splat(0.4),
    shininess: 16.0,
    alpha_cutoff: 0.0,
};
pub const SKULL_MATERIAL: Material = Material {
    ambient: Vec3::splat(0.5),
    diffuse: Vec3::ONE,
    alpha: 1.0,
    specular: Vec3::splat(0.4),
    shininess: 24.0,
    alpha_cutoff: 0.0,
};
pub const MIRROR_MATERIAL: Material = Material {
    alpha: 0.5,
    ..ROOM_MATERIAL
};
/// Lesson 8's polished stone: 60% of what is seen in it is the stone's own colour, 40% the
/// reflection — SPE's constant alpha of 0.4 for the reflection, the other way round.
pub const FLOOR_MIRROR_MATERIAL: Material = Material {
    alpha: 0.6,
    ambient: Vec3::splat(0.2),
    diffuse: Vec3::new(0.35, 0.38, 0.42),
    ..ROOM_MATERIAL
};
/// A planar shadow: black, at 50%.
pub const SHADOW_MATERIAL: Material = Material {
    ambient: Vec3::ZERO,
    diffuse: Vec3::ZERO,
    alpha: 0.5,
    specular: Vec3::ZERO,
    shininess: 1.0,
    alpha_cutoff: 0.0,
};
/// Water lets half the light through.
pub const WATER_MATERIAL: Material = Material {
    alpha: 0.5,
    specular: Vec3::splat(0.8),
    shininess: 64.0,
    ..ROOM_MATERIAL
};
/// The wire fence: opaque wires, holes cut where the texture's alpha is below 0.1, the soft edges
/// in between blended.
pub const FENCE_MATERIAL: Material = Material {
    alpha_cutoff: 0.1,
    ..ROOM_MATERIAL
};
