//! The lights of the room: Luna's three directional lights, and the kinds of light a lesson may add
//! (point and spot lights).

use std::f32::consts::FRAC_1_SQRT_2;

use glam::{Mat4, Vec3};

use crate::math::shadow::LightSource;

/// A light, as Luna's `DirectionalLight`, `PointLight` and `SpotLight`.
#[derive(Debug, Clone, Copy)]
pub struct Light {
    /// The direction the light travels, or where it is.
    pub source: LightSource,
    /// A spot light's cone, around its axis.
    pub spot: Option<Spot>,
    pub ambient: Vec3,
    pub diffuse: Vec3,
    pub specular: Vec3,
}

/// A spot light's cone: light leaves along `axis`, fading out at the angle whose cosine is
/// `cos_cutoff`.
#[derive(Debug, Clone, Copy)]
pub struct Spot {
    pub axis: Vec3,
    pub cos_cutoff: f32,
}

// ANCHOR: light_reflected
impl Light {
    /// The light as the mirror world sees it: a position goes through the reflection as a point;
    /// a direction, and a spot's axis, as vectors (no translation).
    pub fn reflected(&self, reflection: Mat4) -> Light {
        Light {
            source: self.source.reflected(reflection),
            spot: self.spot.map(|spot| Spot {
                axis: reflection.transform_vector3(spot.axis),
                ..spot
            }),
            ..*self
        }
    }
}
// ANCHOR_END: light_reflected

/// Luna's three lights (a key light from the front right, a fill from the front left, a back light),
/// with z negated: his room lies on −z in a left-handed frame, ours on +z in a right-handed one.
pub const LIGHTS: [Light; 3] = [
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(0.577_35, -0.577_35, -0.577_35),
        },
        spot: None,
        ambient: Vec3::splat(0.2),
        diffuse: Vec3::splat(0.5),
        specular: Vec3::splat(0.5),
    },
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(-0.577_35, -0.577_35, -0.577_35),
        },
        spot: None,
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(0.2),
        specular: Vec3::splat(0.25),
    },
    Light {
        source: LightSource::Directional {
            direction: Vec3::new(0.0, -FRAC_1_SQRT_2, FRAC_1_SQRT_2),
        },
        spot: None,
        ambient: Vec3::ZERO,
        diffuse: Vec3::splat(0.2),
        specular: Vec3::ZERO,
    },
];
