//! Clip planes, and the oblique near plane that cuts the reflected world at the mirror.
//!
//! A mirror world lies behind the mirror's plane, and whatever of it comes out in front of the glass
//! (the reflection of an object that crosses the plane) must not show. A clip plane cuts it away;
//! Lengyel's trick costs nothing instead: it moves the projection's near plane onto the mirror, so
//! the clipping every triangle goes through anyway does the cut.
//!
//! Depth here is wgpu's (and D3D's, and Vulkan's): a point survives clipping when 0 ≤ z_c ≤ w_c.

use glam::{Mat4, Vec4};

use super::reflect::Plane;

// ANCHOR: plane
impl Plane {
    /// (n, d) as one 4-vector, so that plane · (p, 1) = n·p + d.
    pub fn as_vec4(&self) -> Vec4 {
        self.normal.extend(self.d)
    }

    /// The plane with the other side in front.
    pub fn flipped(&self) -> Plane {
        Plane {
            normal: -self.normal,
            d: -self.d,
        }
    }

    /// The plane carried by the transform `m` (points p go to m p): (m⁻¹)ᵀ (n, d), renormalised.
    /// This is why glClipPlane takes the plane through the inverse transpose of the model-view.
    ///
    /// For any point p, ((m⁻¹)ᵀ P)·(m p) = P·(m⁻¹ m p) = P·p: points on the plane land on the new
    /// plane, and every point keeps the side it was on (renormalising divides by a positive length).
    pub fn transformed(&self, m: Mat4) -> Plane {
        let carried = m.inverse().transpose() * self.as_vec4();
        Plane::new(carried.truncate(), carried.w)
    }
}
// ANCHOR_END: plane

// ANCHOR: oblique
/// A projection whose near plane is `plane` (given in VIEW space, the kept side in front, the camera behind it:
/// plane.signed_distance(origin) < 0) and whose far plane is tilted to pass through the far corner of the original frustum
/// that lies opposite (Lengyel, "Oblique View Frustum Depth Projection and Clipping", 2005), derived for clip-space depth
/// z_c ∈ [0, w_c] (wgpu, D3D, Vulkan): the third row becomes a·C with a = (M₄·Q)/(C·Q), Q = M⁻¹ (sgn C′x, sgn C′y, 1, 1),
/// C′ = M⁻ᵀ C.
///
/// Why: the near plane is where z_c = 0, so a third row a·C makes it the plane C (a > 0 keeps its
/// front). The far plane is where z_c = w_c, i.e. (a·C − M₄)·v = 0; choosing a so that it passes
/// through Q, the corner of the far face lying farthest in front of C, keeps the whole visible part of
/// the old frustum inside the new one. The x, y and w rows stay, so the picture does not move.
pub fn oblique_projection(projection: Mat4, plane: Plane) -> Mat4 {
    debug_assert!(
        plane.d < 0.0,
        "the camera (the view-space origin) must lie behind the near plane"
    );
    let c = plane.as_vec4();
    let inverse = projection.inverse();
    // The plane in clip space: C·v = C·(M⁻¹ M v) = (M⁻ᵀ C)·(M v).
    let c_clip = inverse.transpose() * c;
    // The far face is NDC z = 1 for both depth conventions; its corner farthest in front of the plane
    // is where x and y take the signs of the plane's clip-space normal.
    let corner = Vec4::new(c_clip.x.signum(), c_clip.y.signum(), 1.0, 1.0);
    let q = inverse * corner;
    let w_row = projection.row(3);
    let a = w_row.dot(q) / c.dot(q);
    // With z_c ∈ [−w_c, w_c] (OpenGL) the near plane is z_c = −w_c, so the row would be 2a·C − M₄
    // instead: near at (z_c + w_c) = 2a·C·v = 0, far at (z_c − w_c) = 2(a·C − M₄)·v = 0 through Q.
    let depth_row = a * c;
    // glam stores columns: replace the third row by working on the transpose.
    let mut rows = projection.transpose();
    rows.z_axis = depth_row;
    rows.transpose()
}
// ANCHOR_END: oblique

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::reflect::numbers::Numbers;
    use crate::math::reflect::reflection;
    use glam::{Quat, Vec3};

    /// Random cases per property test.
    const CASES: usize = 300;
    /// Tolerance on NDC depth, as the brief of the property asks.
    const DEPTH_EPS: f32 = 1e-4;

    /// A random D3D-style, right-handed perspective: fov 30–90°, aspect 0.5–2, near 0.1–1, far 20–100.
    fn random_projection(numbers: &mut Numbers) -> (Mat4, f32, f32) {
        let fov = numbers.between(30.0, 90.0).to_radians();
        let aspect = numbers.between(0.5, 2.0);
        let near = numbers.between(0.1, 1.0);
        let far = numbers.between(20.0, 100.0);
        let projection = glam::camera::rh::proj::directx::perspective(fov, aspect, near, far);
        (projection, near, far)
    }

    /// The view-space point on the ray through NDC (x, y) at `distance` in front of the camera.
    fn view_point(projection: Mat4, x: f32, y: f32, distance: f32) -> Vec3 {
        // NDC z = 0 is the near plane for this depth convention.
        let on_near = projection.inverse().project_point3(Vec3::new(x, y, 0.0));
        on_near * (distance / -on_near.z)
    }

    /// A view-space plane through a random point inside the frustum, the camera behind it.
    fn random_plane(numbers: &mut Numbers, projection: Mat4, near: f32, far: f32) -> Plane {
        loop {
            // Within 90 % of the x/y bounds and the nearer half of the depth range: the plane cuts
            // the frustum well inside it.
            let (x, y) = (numbers.next() * 0.9, numbers.next() * 0.9);
            let inside = view_point(projection, x, y, numbers.between(near, far * 0.5));
            let normal = numbers.unit();
            // Face away from the camera, so that the camera is behind the plane.
            let normal = if normal.dot(inside) < 0.0 {
                -normal
            } else {
                normal
            };
            let plane = Plane::through(inside, normal);
            // At least 5 cm between camera and plane: nearer, the plane nearly contains the eye.
            if plane.d < -0.05 {
                return plane;
            }
        }
    }

    /// NDC depth z_c / w_c of a view-space point.
    fn depth(projection: Mat4, v: Vec3) -> f32 {
        let clip = projection * v.extend(1.0);
        clip.z / clip.w
    }

    /// Where the ray through NDC (x, y) meets the plane, as a multiple of its point at distance 1.
    fn hit(projection: Mat4, plane: Plane, x: f32, y: f32) -> Option<Vec3> {
        let ray = view_point(projection, x, y, 1.0);
        let t = -plane.d / plane.normal.dot(ray);
        (t > 0.0).then_some(ray * t)
    }

    #[test]
    fn a_plane_parallel_to_the_near_plane_gives_an_ordinary_perspective() {
        // The plane z = −k facing away from the camera: −z − k = 0, i.e. normal (0, 0, −1), d = −k.
        let (fov, aspect, near, far, k) = (1.0, 1.5, 0.5, 50.0, 3.0);
        let projection = glam::camera::rh::proj::directx::perspective(fov, aspect, near, far);
        let oblique = oblique_projection(projection, Plane::new(-Vec3::Z, -k));
        let expected = glam::camera::rh::proj::directx::perspective(fov, aspect, k, far);
        assert!(
            oblique.abs_diff_eq(expected, 1e-5),
            "{oblique} vs {expected}"
        );
        // And the original near plane gives back the original projection.
        let same = oblique_projection(projection, Plane::new(-Vec3::Z, -near));
        assert!(same.abs_diff_eq(projection, 1e-5));
    }

    #[test]
    fn points_on_the_plane_get_depth_zero() {
        let mut numbers = Numbers(0x0b11_90e5);
        let mut checked = 0;
        for _ in 0..CASES {
            let (projection, near, far) = random_projection(&mut numbers);
            let plane = random_plane(&mut numbers, projection, near, far);
            let oblique = oblique_projection(projection, plane);
            for _ in 0..8 {
                let (x, y) = (numbers.next(), numbers.next());
                let Some(on) = hit(projection, plane, x, y) else {
                    continue;
                };
                // Only points inside the original frustum.
                if !(near..=far).contains(&-on.z) {
                    continue;
                }
                let z = depth(oblique, on);
                assert!(z.abs() < DEPTH_EPS, "depth {z} at {on} on {plane:?}");
                checked += 1;
            }
        }
        assert!(checked >= 200, "only {checked} points checked");
    }

    #[test]
    fn points_in_front_of_the_plane_keep_a_depth_in_range() {
        let mut numbers = Numbers(0xf00d_cafe);
        let mut checked = 0;
        for _ in 0..CASES {
            let (projection, near, far) = random_projection(&mut numbers);
            let plane = random_plane(&mut numbers, projection, near, far);
            let oblique = oblique_projection(projection, plane);
            // The eight corners of the frustum, then random points inside it.
            let corners = [-1.0, 1.0]
                .into_iter()
                .flat_map(|x| [-1.0, 1.0].map(|y| (x, y)))
                .flat_map(|(x, y)| [near, far].map(|distance| (x, y, distance)));
            let random = (0..8).map(|_| {
                let (x, y) = (numbers.next(), numbers.next());
                (x, y, numbers.between(near, far))
            });
            for (x, y, distance) in corners.chain(random.collect::<Vec<_>>()) {
                let v = view_point(projection, x, y, distance);
                if plane.signed_distance(v) <= 0.0 {
                    continue;
                }
                let z = depth(oblique, v);
                assert!(
                    (-DEPTH_EPS..=1.0 + DEPTH_EPS).contains(&z),
                    "depth {z} at {v} in front of {plane:?}"
                );
                checked += 1;
            }
        }
        assert!(checked >= 200, "only {checked} points checked");
    }

    #[test]
    fn points_between_the_camera_and_the_plane_are_clipped() {
        let mut numbers = Numbers(0x5eed_1e55);
        let mut checked = 0;
        for _ in 0..CASES {
            let (projection, near, far) = random_projection(&mut numbers);
            let plane = random_plane(&mut numbers, projection, near, far);
            let oblique = oblique_projection(projection, plane);
            for _ in 0..8 {
                let (x, y) = (numbers.next(), numbers.next());
                let Some(on) = hit(projection, plane, x, y) else {
                    continue;
                };
                // From 5 % to 95 % of the way from the camera to the plane (nearer than `near` too).
                let behind = on * numbers.between(0.05, 0.95);
                let z = depth(oblique, behind);
                assert!(z < 0.0, "depth {z} at {behind} behind {plane:?}");
                checked += 1;
            }
        }
        assert!(checked >= 200, "only {checked} points checked");
    }

    #[test]
    fn only_the_depth_row_changes() {
        let mut numbers = Numbers(0x00ab_5e17);
        for _ in 0..CASES {
            let (projection, near, far) = random_projection(&mut numbers);
            let plane = random_plane(&mut numbers, projection, near, far);
            let oblique = oblique_projection(projection, plane);
            // Copied, not recomputed: exactly equal.
            for row in [0, 1, 3] {
                assert_eq!(oblique.row(row), projection.row(row));
            }
            // The new depth row is a positive multiple of the plane.
            let depth_row = oblique.row(2);
            let a = depth_row.length() / plane.as_vec4().length();
            assert!(depth_row.abs_diff_eq(a * plane.as_vec4(), 1e-4 * a));
        }
    }

    /// A random affine map: a non-uniform scale, a rotation, a translation, sometimes a mirror.
    fn random_affine(numbers: &mut Numbers) -> Mat4 {
        let scale = Vec3::new(
            numbers.between(0.3, 3.0),
            numbers.between(0.3, 3.0),
            numbers.between(0.3, 3.0),
        );
        let rotation = Quat::from_axis_angle(numbers.unit(), numbers.next() * std::f32::consts::PI);
        let m = Mat4::from_scale_rotation_translation(scale, rotation, numbers.vec3(10.0));
        // One case in four through a mirror too: it turns space inside out, yet sides are kept.
        if numbers.next() > 0.5 {
            reflection(numbers.plane()) * m
        } else {
            m
        }
    }

    #[test]
    fn transformed_planes_carry_their_points_and_sides() {
        let mut numbers = Numbers(0x7a2f_0e11);
        for _ in 0..CASES {
            let plane = numbers.plane();
            let m = random_affine(&mut numbers);
            let moved = plane.transformed(m);
            assert!((moved.normal.length() - 1.0).abs() < 1e-5);
            for _ in 0..4 {
                let p = numbers.vec3(10.0);
                let on = p - plane.signed_distance(p) * plane.normal;
                let carried = m.transform_point3(on);
                // Relative to the size of the carried point: f32 keeps about 7 digits.
                let tolerance = 1e-5 * carried.length().max(1.0);
                assert!(moved.signed_distance(carried).abs() < tolerance);
                // Points clearly off the plane stay on their side.
                let side = plane.signed_distance(p);
                if side.abs() > 1e-2 {
                    let after = moved.signed_distance(m.transform_point3(p));
                    assert_eq!(after.signum(), side.signum(), "{p} on {plane:?} by {m}");
                }
            }
        }
    }

    #[test]
    fn flipping_and_the_four_vector() {
        let mut numbers = Numbers(0xf11b_0d1e);
        for _ in 0..CASES {
            let plane = numbers.plane();
            assert_eq!(plane.flipped().flipped(), plane);
            let p = numbers.vec3(10.0);
            assert!((plane.as_vec4().dot(p.extend(1.0)) - plane.signed_distance(p)).abs() < 1e-5);
            assert_eq!(
                plane.flipped().signed_distance(p),
                -plane.signed_distance(p)
            );
        }
    }
}
