//! The wall mirror's plane and the mirror world it shows: the reflection in it, the world matrix of
//! an object's mirror image, and the lights as the mirror world sees them.

use glam::{Mat4, Vec3};

use super::lights::{LIGHTS, Light};
use crate::math::reflect::{Plane, reflection};

/// The plane of the mirror: z = 0, facing the room (+z).
pub fn mirror_plane() -> Plane {
    Plane::new(Vec3::Z, 0.0)
}

/// The reflection in the mirror's plane.
pub fn mirror_reflection() -> Mat4 {
    reflection(mirror_plane())
}

// ANCHOR: reflected_world
/// The world matrix of an object's mirror image: first its own world matrix, then the reflection.
/// (Column vectors: R * world. DirectXMath's row vectors write it world * R.)
pub fn reflected_world(world: Mat4) -> Mat4 {
    mirror_reflection() * world
}
// ANCHOR_END: reflected_world

// ANCHOR: reflected_lights
/// The lights as the mirror world sees them: each one reflected too ([`Light::reflected`]). Without
/// this the mirror image would be lit from the wrong side (a key light from the front right would
/// light the image's front right, which faces away from the light).
pub fn reflected_lights() -> [Light; 3] {
    LIGHTS.map(|light| light.reflected(mirror_reflection()))
}
// ANCHOR_END: reflected_lights
