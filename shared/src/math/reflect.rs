//! Planar reflection: the matrix that mirrors the world in a plane.
//!
//! glam uses column vectors: a point is transformed as `R * p`, and "first the world matrix, then the
//! reflection" is `R * world`. DirectXMath uses row vectors and writes the same thing `world * R`.

use glam::{Mat3, Mat4, Vec3};

/// A plane: the points p with `normal · p + d = 0`, the normal of unit length.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    pub normal: Vec3,
    pub d: f32,
}

impl Plane {
    /// The plane `normal · p + d = 0`; `normal` is normalised (and `d` with it).
    pub fn new(normal: Vec3, d: f32) -> Self {
        let length = normal.length();
        Self {
            normal: normal / length,
            d: d / length,
        }
    }

    /// The plane through `point` facing `normal`.
    pub fn through(point: Vec3, normal: Vec3) -> Self {
        let normal = normal.normalize();
        Self {
            normal,
            d: -normal.dot(point),
        }
    }

    /// How far `p` lies in front of the plane (negative: behind it).
    pub fn signed_distance(&self, p: Vec3) -> f32 {
        self.normal.dot(p) + self.d
    }
}

// ANCHOR: reflection
/// The reflection in `plane`: p' = p − 2 (n·p + d) n.
///
/// Its upper 3×3 part is I − 2 n nᵀ, its translation −2 d n; its determinant is −1.
pub fn reflection(plane: Plane) -> Mat4 {
    let Plane { normal: n, d } = plane;
    let linear = Mat3::IDENTITY - 2.0 * Mat3::from_cols(n * n.x, n * n.y, n * n.z);
    let translation = -2.0 * d * n;
    Mat4::from_cols(
        linear.x_axis.extend(0.0),
        linear.y_axis.extend(0.0),
        linear.z_axis.extend(0.0),
        translation.extend(1.0),
    )
}
// ANCHOR_END: reflection

/// The matrix that carries normals for a world matrix: the inverse transpose of its 3×3 part.
pub fn normal_matrix(world: Mat4) -> Mat4 {
    Mat4::from_mat3(Mat3::from_mat4(world).inverse().transpose())
}

/// A small deterministic generator for the property tests of all of `math` (no dependency needed).
#[cfg(test)]
pub(crate) mod numbers {
    use super::Plane;
    use glam::Vec3;

    /// Xorshift64: the same seed gives the same cases on every machine.
    pub(crate) struct Numbers(pub(crate) u64);

    impl Numbers {
        /// A number in −1..1.
        pub(crate) fn next(&mut self) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            // The top 24 bits: exactly as many as an f32 mantissa holds.
            (self.0 >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0
        }

        /// A number in `low..high`.
        pub(crate) fn between(&mut self, low: f32, high: f32) -> f32 {
            low + (self.next() + 1.0) * 0.5 * (high - low)
        }

        /// A vector in the cube −scale..scale.
        pub(crate) fn vec3(&mut self, scale: f32) -> Vec3 {
            Vec3::new(self.next(), self.next(), self.next()) * scale
        }

        /// A direction of unit length (never near zero before normalising).
        pub(crate) fn unit(&mut self) -> Vec3 {
            loop {
                let v = self.vec3(1.0);
                // Inside the unit ball and not tiny: uniform over directions, safe to normalise.
                if (0.01..=1.0).contains(&v.length_squared()) {
                    return v.normalize();
                }
            }
        }

        /// A plane at most 5 from the origin, in any direction.
        pub(crate) fn plane(&mut self) -> Plane {
            // The offset keeps the normal away from zero.
            let normal = self.vec3(1.0) + Vec3::splat(1e-3);
            Plane::new(normal, self.next() * 5.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::numbers::Numbers;
    use super::*;

    const EPS: f32 = 1e-4;

    #[test]
    fn the_mirror_wall_flips_z() {
        let r = reflection(Plane::new(Vec3::Z, 0.0));
        assert!(r.abs_diff_eq(Mat4::from_scale(Vec3::new(1.0, 1.0, -1.0)), EPS));
        assert!(
            r.transform_point3(Vec3::new(1.0, 2.0, 3.0))
                .abs_diff_eq(Vec3::new(1.0, 2.0, -3.0), EPS)
        );
    }

    #[test]
    fn an_offset_plane_mirrors_across_itself() {
        // The plane x = 2, i.e. (1, 0, 0)·p − 2 = 0.
        let r = reflection(Plane::new(Vec3::X, -2.0));
        assert!(
            r.transform_point3(Vec3::new(3.0, 5.0, 0.0))
                .abs_diff_eq(Vec3::new(1.0, 5.0, 0.0), EPS)
        );
        assert!(
            r.transform_point3(Vec3::ZERO)
                .abs_diff_eq(Vec3::new(4.0, 0.0, 0.0), EPS)
        );
    }

    #[test]
    fn a_tilted_plane_swaps_axes() {
        // The plane x = y through the origin swaps x and y.
        let r = reflection(Plane::new(Vec3::new(1.0, -1.0, 0.0), 0.0));
        assert!(
            r.transform_point3(Vec3::new(1.0, 0.0, 0.0))
                .abs_diff_eq(Vec3::new(0.0, 1.0, 0.0), EPS)
        );
        // A 45° plane through (0, 1, 0) facing (0, 1, 1)/√2: the point (0, 2, 0) goes to (0, 1, -1).
        let r = reflection(Plane::through(Vec3::Y, Vec3::new(0.0, 1.0, 1.0)));
        assert!(
            r.transform_point3(Vec3::new(0.0, 2.0, 0.0))
                .abs_diff_eq(Vec3::new(0.0, 1.0, -1.0), EPS)
        );
    }

    #[test]
    fn properties_hold_for_many_planes() {
        let mut numbers = Numbers(0x9e37_79b9_7f4a_7c15);
        for _ in 0..500 {
            let plane = numbers.plane();
            let r = reflection(plane);
            // Reflecting twice gives back the original.
            assert!((r * r).abs_diff_eq(Mat4::IDENTITY, EPS));
            // It turns space inside out: determinant −1.
            assert!((r.determinant() + 1.0).abs() < EPS);
            // A point on the plane stays where it is.
            let p = numbers.vec3(10.0);
            let on = p - plane.signed_distance(p) * plane.normal;
            assert!(r.transform_point3(on).abs_diff_eq(on, EPS * 10.0));
            // A point off the plane lands as far behind it as it was in front, on the same normal.
            let q = r.transform_point3(p);
            assert!((plane.signed_distance(q) + plane.signed_distance(p)).abs() < EPS * 10.0);
            assert!((q - p).cross(plane.normal).length() < EPS * 10.0);
            // Normals: the inverse transpose of a reflection is the reflection itself, so the
            // plane's own normal comes out reversed and tangents are untouched.
            let normals = normal_matrix(r);
            assert!(normals.abs_diff_eq(Mat4::from_mat3(Mat3::from_mat4(r)), EPS));
            let flipped = normals.transform_vector3(plane.normal);
            assert!(flipped.abs_diff_eq(-plane.normal, EPS));
            let tangent = plane.normal.any_orthonormal_vector();
            assert!(normals.transform_vector3(tangent).abs_diff_eq(tangent, EPS));
        }
    }

    /// DirectXMath's `XMMatrixReflect` as its documentation writes it: row vectors, so the translation
    /// sits in the last *row*.
    fn xm_matrix_reflect(plane: Plane) -> [[f32; 4]; 4] {
        let (a, b, c, d) = (plane.normal.x, plane.normal.y, plane.normal.z, plane.d);
        [
            [1.0 - 2.0 * a * a, -2.0 * a * b, -2.0 * a * c, 0.0],
            [-2.0 * a * b, 1.0 - 2.0 * b * b, -2.0 * b * c, 0.0],
            [-2.0 * a * c, -2.0 * b * c, 1.0 - 2.0 * c * c, 0.0],
            [-2.0 * a * d, -2.0 * b * d, -2.0 * c * d, 1.0],
        ]
    }

    #[test]
    fn directx_rows_are_glam_columns() {
        let mut numbers = Numbers(42);
        for _ in 0..100 {
            let plane = numbers.plane();
            // The same sixteen numbers: D3D reads them as rows (`p * M`), glam as columns (`M * p`).
            let from_d3d = Mat4::from_cols_array_2d(&xm_matrix_reflect(plane));
            assert!(from_d3d.abs_diff_eq(reflection(plane), EPS));
        }
    }
}
