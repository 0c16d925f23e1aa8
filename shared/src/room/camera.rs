//! The orbit camera: it circles a point of the room, given by yaw, pitch and distance.
//!
//! A pose is written `YAW,PITCH,DISTANCE` (degrees, degrees, metres), as `--camera` takes it and the
//! window title shows it, so a teacher can hand a class the exact view on the board.

use anyhow::{Result, bail};
use glam::{Mat4, Vec3};

/// The point the camera circles: the middle of the mirror's lower half.
pub const TARGET: Vec3 = Vec3::new(0.0, 1.6, 0.0);
/// Near and far planes of the projection, in metres.
pub const NEAR: f32 = 0.5;
pub const FAR: f32 = 50.0;
/// Vertical field of view, in degrees.
pub const FOV_Y_DEGREES: f32 = 45.0;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Camera {
    /// Degrees around the vertical axis; 0 looks straight at the mirror, positive moves the camera right.
    pub yaw: f32,
    /// Degrees above the horizon.
    pub pitch: f32,
    /// Metres from the target.
    pub distance: f32,
}

/// The pose of the book's screenshots: a little to the right and above, the crate hiding the
/// mirror's lower right corner, the skull in front of the mirror.
pub const BOOK_POSE: Camera = Camera {
    yaw: 22.0,
    pitch: 14.0,
    distance: 11.0,
};

/// Behind the wall, looking back through the mirror's frame: the view that shows a reflection the
/// stencil test did not confine.
pub const BEHIND_THE_WALL: Camera = Camera {
    yaw: 140.0,
    pitch: 12.0,
    distance: 10.0,
};

/// High above the floor, looking down at it.
pub const FROM_ABOVE: Camera = Camera {
    yaw: 15.0,
    pitch: 60.0,
    distance: 12.0,
};

/// The poses the book uses, by name (the window's panel offers them).
pub const POSES: &[(&str, Camera)] = &[
    ("front", BOOK_POSE),
    ("behind the wall", BEHIND_THE_WALL),
    ("from above", FROM_ABOVE),
];

impl Default for Camera {
    fn default() -> Self {
        BOOK_POSE
    }
}

impl Camera {
    pub const MIN_DISTANCE: f32 = 2.0;
    pub const MAX_DISTANCE: f32 = 30.0;
    pub const MAX_PITCH: f32 = 89.0;

    /// Parses `YAW,PITCH,DISTANCE`.
    pub fn parse(text: &str) -> Result<Self> {
        let numbers: Vec<f32> = text
            .split(',')
            .map(|part| part.trim().parse::<f32>())
            .collect::<Result<_, _>>()
            .map_err(|_| {
                anyhow::anyhow!(
                    "--camera expects YAW,PITCH,DISTANCE in numbers, e.g. 22,14,11; got `{text}`"
                )
            })?;
        let [yaw, pitch, distance] = numbers[..] else {
            bail!("--camera expects three numbers YAW,PITCH,DISTANCE, e.g. 22,14,11; got `{text}`");
        };
        if !yaw.is_finite() || !(-Self::MAX_PITCH..=Self::MAX_PITCH).contains(&pitch) {
            bail!("--camera: pitch must lie in -89..=89 degrees and yaw be a number; got `{text}`");
        }
        if !(Self::MIN_DISTANCE..=Self::MAX_DISTANCE).contains(&distance) {
            bail!("--camera: distance must lie in 2..=30 metres; got `{text}`");
        }
        Ok(Self {
            yaw,
            pitch,
            distance,
        })
    }

    /// Where the camera is.
    pub fn eye(&self) -> Vec3 {
        let (yaw, pitch) = (self.yaw.to_radians(), self.pitch.to_radians());
        let direction = Vec3::new(
            yaw.sin() * pitch.cos(),
            pitch.sin(),
            yaw.cos() * pitch.cos(),
        );
        TARGET + direction * self.distance
    }

    /// World to view space (right-handed, looking down −z).
    pub fn view(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye(), TARGET, Vec3::Y)
    }

    // ANCHOR: projection
    /// View to clip space with wgpu's depth range: the near plane maps to 0, the far plane to 1.
    pub fn projection(aspect: f32) -> Mat4 {
        glam::camera::rh::proj::directx::perspective(FOV_Y_DEGREES.to_radians(), aspect, NEAR, FAR)
    }
    // ANCHOR_END: projection

    // ANCHOR: infinity
    /// [`Camera::projection`] with the far plane moved to infinity: points at any distance map
    /// to depths below 1, and a point at infinity (w = 0) maps to exactly 1, which still lies
    /// inside the clip volume (0 ≤ z ≤ w). A shadow volume extruded to infinity needs it.
    pub fn projection_to_infinity(aspect: f32) -> Mat4 {
        glam::camera::rh::proj::directx::perspective_infinite(
            FOV_Y_DEGREES.to_radians(),
            aspect,
            NEAR,
        )
    }
    // ANCHOR_END: infinity

    /// World to clip space.
    pub fn view_projection(&self, aspect: f32) -> Mat4 {
        Self::projection(aspect) * self.view()
    }

    /// Dragging by (dx, dy) pixels turns the camera around the target.
    pub fn orbit(&mut self, dx: f32, dy: f32) {
        self.yaw = (self.yaw - dx * 0.3).rem_euclid(360.0);
        if self.yaw > 180.0 {
            self.yaw -= 360.0;
        }
        self.pitch = (self.pitch + dy * 0.3).clamp(-Self::MAX_PITCH, Self::MAX_PITCH);
    }

    /// The wheel moves the camera nearer (positive steps) or farther.
    pub fn zoom(&mut self, steps: f32) {
        self.distance =
            (self.distance * 0.9f32.powf(steps)).clamp(Self::MIN_DISTANCE, Self::MAX_DISTANCE);
    }
}

/// What a frame is seen through: where the eye is, the world-to-view matrix and the projection.
/// Usually the orbit camera's ([`Camera::view_at`]); a render-to-texture mirror sees the room through a
/// reflected one ([`View::reflected`]), and an oblique projection swaps the near plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    pub eye: Vec3,
    pub view: Mat4,
    pub projection: Mat4,
}

impl Camera {
    /// The orbit camera's view of a target with this aspect ratio (width / height).
    pub fn view_at(&self, aspect: f32) -> View {
        View {
            eye: self.eye(),
            view: self.view(),
            projection: Self::projection(aspect),
        }
    }
}

impl View {
    /// A camera at `eye` looking at `target`, `up` pointing up on the screen.
    pub fn look_at(eye: Vec3, target: Vec3, up: Vec3, projection: Mat4) -> Self {
        Self {
            eye,
            view: glam::camera::rh::view::look_at_mat4(eye, target, up),
            projection,
        }
    }

    /// World to clip space.
    pub fn view_projection(&self) -> Mat4 {
        self.projection * self.view
    }

    /// The aspect ratio (width / height) the projection was made for.
    pub fn aspect(&self) -> f32 {
        self.projection.y_axis.y / self.projection.x_axis.x
    }

    /// The same eye seeing the world reflected by `reflection`: view · R. Its determinant is −1, so
    /// it turns every triangle's winding around (draw with the front face flipped).
    pub fn reflected(&self, reflection: Mat4) -> Self {
        Self {
            eye: reflection.transform_point3(self.eye),
            view: self.view * reflection,
            projection: self.projection,
        }
    }
}

impl std::fmt::Display for Camera {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:.0},{:.0},{:.1}", self.yaw, self.pitch, self.distance)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pose_round_trips_through_text() {
        let camera = Camera::parse("30,-10,8.5").unwrap();
        assert_eq!(Camera::parse(&camera.to_string()).unwrap(), camera);
        assert!(Camera::parse("1,2").is_err());
        assert!(Camera::parse("1,95,5").is_err());
        assert!(Camera::parse("a,b,c").is_err());
    }

    #[test]
    fn a_view_knows_its_aspect_and_a_reflected_view_mirrors_the_eye() {
        let view = BOOK_POSE.view_at(16.0 / 9.0);
        assert!((view.aspect() - 16.0 / 9.0).abs() < 1e-5);
        let floor = Mat4::from_scale(Vec3::new(1.0, -1.0, 1.0));
        let mirrored = view.reflected(floor);
        assert!(
            mirrored
                .eye
                .abs_diff_eq(view.eye * Vec3::new(1.0, -1.0, 1.0), 1e-5)
        );
        // A point seen through the reflected view lands where its mirror image does in the real one.
        let p = Vec3::new(0.3, 1.2, 2.0);
        let a = mirrored.view_projection().project_point3(p);
        let b = view
            .view_projection()
            .project_point3(floor.transform_point3(p));
        assert!(a.abs_diff_eq(b, 1e-5));
    }

    #[test]
    fn yaw_zero_looks_straight_at_the_mirror() {
        let camera = Camera {
            yaw: 0.0,
            pitch: 0.0,
            distance: 10.0,
        };
        assert!(camera.eye().abs_diff_eq(TARGET + Vec3::Z * 10.0, 1e-5));
        // The target lands in the middle of the screen, at a depth between 0 and 1.
        let clip = camera.view_projection(1.0) * TARGET.extend(1.0);
        let ndc = clip.truncate() / clip.w;
        assert!(ndc.x.abs() < 1e-5 && ndc.y.abs() < 1e-5);
        assert!(ndc.z > 0.0 && ndc.z < 1.0);
    }
}
