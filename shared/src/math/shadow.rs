//! Planar shadows: the matrix that flattens the world onto a plane along the light's rays
//! (Luna's `XMMatrixShadow`, written for glam's column vectors).

use glam::{Mat4, Vec3, Vec4};

use super::reflect::Plane;

// ANCHOR: light
/// Where light comes from: a direction it travels (directional) or a position (point/spot light).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LightSource {
    Directional { direction: Vec3 },
    Point { position: Vec3 },
}

impl LightSource {
    /// The light as XMMatrixShadow's 4-vector L: (−direction, 0) — pointing TO the light — or (position, 1).
    ///
    /// A directional light is a point light infinitely far away: w = 0 makes L a point at infinity.
    pub fn as_vec4(&self) -> Vec4 {
        match *self {
            LightSource::Directional { direction } => (-direction).extend(0.0),
            LightSource::Point { position } => position.extend(1.0),
        }
    }

    /// The same light seen in a mirror: a position goes through `reflection` as a point, a direction as a vector.
    pub fn reflected(&self, reflection: Mat4) -> LightSource {
        match *self {
            LightSource::Directional { direction } => LightSource::Directional {
                direction: reflection.transform_vector3(direction),
            },
            LightSource::Point { position } => LightSource::Point {
                position: reflection.transform_point3(position),
            },
        }
    }
}
// ANCHOR_END: light

// ANCHOR: shadow
/// The matrix that flattens the world onto `plane` as seen from `light`: S = (P·L) I − L Pᵀ, with P = plane.as_vec4(),
/// L = light.as_vec4() (glam: column vectors, so DirectXMath's row-vector matrix transposed). Its results are homogeneous:
/// divide by w (`Mat4::project_point3` does).
///
/// Why: S p = (P·L) p − (P·p) L is a mix of p and the light, so it lies on the light's ray through p;
/// and P·(S p) = (P·L)(P·p) − (P·p)(P·L) = 0, so it lies on the plane.
///
/// The signs matter on the GPU even though −S projects to the same points: with the light in front of
/// the plane, w = P·L − L_w (P·p) > 0 for every point nearer the plane than the light, and clipping
/// keeps only w > 0. Hence L points *to* the light.
pub fn shadow_matrix(plane: Plane, light: LightSource) -> Mat4 {
    let p = plane.as_vec4();
    let l = light.as_vec4();
    // The outer product L Pᵀ: its column j is L scaled by P's j-th number.
    let outer = Mat4::from_cols(l * p.x, l * p.y, l * p.z, l * p.w);
    Mat4::from_diagonal(Vec4::splat(p.dot(l))) - outer
}
// ANCHOR_END: shadow

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::reflect::numbers::Numbers;
    use crate::math::reflect::reflection;

    /// Random cases per property test.
    const CASES: usize = 300;
    /// Relative tolerance: f32 keeps about 7 digits, and the division by w costs some.
    const EPS: f32 = 1e-3;

    fn point_light(numbers: &mut Numbers) -> LightSource {
        LightSource::Point {
            position: numbers.vec3(10.0),
        }
    }

    fn directional_light(numbers: &mut Numbers) -> LightSource {
        LightSource::Directional {
            direction: numbers.unit(),
        }
    }

    /// The homogeneous w that `shadow_matrix` gives `p`: P·L − L_w (P·p). Near zero the shadow
    /// runs off to infinity (the point is level with a point light, or the sun grazes the plane).
    fn shadow_w(plane: Plane, light: LightSource, p: Vec3) -> f32 {
        (shadow_matrix(plane, light) * p.extend(1.0)).w
    }

    /// Cases far enough from those infinities for f32: the shadow at most ~100 times farther out.
    fn well_posed(plane: Plane, light: LightSource, p: Vec3) -> bool {
        let l = light.as_vec4();
        plane.as_vec4().dot(l).abs() > 0.2 && shadow_w(plane, light, p).abs() > 0.2
    }

    #[test]
    fn points_on_the_plane_stay_put() {
        let mut numbers = Numbers(0x5ad0_0001);
        let mut checked = 0;
        for i in 0..CASES {
            let plane = numbers.plane();
            let light = if i % 2 == 0 {
                point_light(&mut numbers)
            } else {
                directional_light(&mut numbers)
            };
            let p = numbers.vec3(10.0);
            let on = p - plane.signed_distance(p) * plane.normal;
            if !well_posed(plane, light, on) {
                continue;
            }
            let s = shadow_matrix(plane, light).project_point3(on);
            assert!(
                s.abs_diff_eq(on, EPS * on.length().max(1.0)),
                "{on} went to {s}"
            );
            checked += 1;
        }
        assert!(checked >= 200, "only {checked} cases checked");
    }

    #[test]
    fn every_shadow_lies_on_the_plane() {
        let mut numbers = Numbers(0x5ad0_0002);
        let mut checked = 0;
        for i in 0..CASES {
            let plane = numbers.plane();
            let light = if i % 2 == 0 {
                point_light(&mut numbers)
            } else {
                directional_light(&mut numbers)
            };
            let p = numbers.vec3(10.0);
            if !well_posed(plane, light, p) {
                continue;
            }
            let s = shadow_matrix(plane, light).project_point3(p);
            let distance = plane.signed_distance(s);
            assert!(
                distance.abs() < EPS * s.length().max(1.0),
                "{s} is {distance} off"
            );
            checked += 1;
        }
        assert!(checked >= 200, "only {checked} cases checked");
    }

    #[test]
    fn a_point_light_casts_along_its_rays() {
        let mut numbers = Numbers(0x5ad0_0003);
        let (mut checked, mut beyond) = (0, 0);
        for _ in 0..CASES {
            let plane = numbers.plane();
            let light = point_light(&mut numbers);
            let LightSource::Point { position } = light else {
                unreachable!()
            };
            let p = numbers.vec3(10.0);
            if !well_posed(plane, light, p) || (p - position).length() < 0.5 {
                continue;
            }
            let s = shadow_matrix(plane, light).project_point3(p);
            // On the line through the light and p: the two directions from the light are parallel.
            let (to_p, to_s) = (p - position, s - position);
            let sine = to_p.cross(to_s).length() / (to_p.length() * to_s.length());
            assert!(sine < EPS, "{s} is off the ray from {position} through {p}");
            checked += 1;
            // When p lies between the light and the plane, its shadow lies beyond p, away from the light.
            let (light_side, p_side) = (plane.signed_distance(position), plane.signed_distance(p));
            if light_side * p_side > 0.0 && p_side.abs() < light_side.abs() {
                assert!((s - p).dot(to_p) > 0.0);
                assert!(to_s.length() >= to_p.length());
                beyond += 1;
            }
        }
        assert!(checked >= 200, "only {checked} cases checked");
        assert!(beyond >= 20, "only {beyond} points between light and plane");
    }

    #[test]
    fn a_directional_light_casts_parallel_shadows() {
        let mut numbers = Numbers(0x5ad0_0004);
        let mut checked = 0;
        for _ in 0..CASES {
            let plane = numbers.plane();
            let light = directional_light(&mut numbers);
            let LightSource::Directional { direction } = light else {
                unreachable!()
            };
            let p = numbers.vec3(10.0);
            if !well_posed(plane, light, p) {
                continue;
            }
            let offset = shadow_matrix(plane, light).project_point3(p) - p;
            // p already on the plane has no offset to compare.
            if offset.length() < 1e-2 {
                continue;
            }
            let sine = offset.cross(direction).length() / offset.length();
            assert!(sine < EPS, "offset {offset} is not along {direction}");
            checked += 1;
        }
        assert!(checked >= 200, "only {checked} cases checked");
    }

    #[test]
    fn lit_points_keep_a_positive_w() {
        // The sun shining straight down is the 4-vector pointing up to it.
        let sun = LightSource::Directional {
            direction: -Vec3::Y,
        };
        assert_eq!(sun.as_vec4(), Vec4::new(0.0, 1.0, 0.0, 0.0));
        let mut numbers = Numbers(0x5ad0_0008);
        let mut checked = 0;
        // About a quarter of random cases are lit points, so draw four times as many.
        for i in 0..4 * CASES {
            let plane = numbers.plane();
            let light = if i % 2 == 0 {
                point_light(&mut numbers)
            } else {
                directional_light(&mut numbers)
            };
            let p = numbers.vec3(10.0);
            let p_side = plane.signed_distance(p);
            // The light in front of the plane, p in front too and nearer the plane than a point light.
            let lit = match light {
                LightSource::Directional { direction } => plane.normal.dot(direction) < 0.0,
                LightSource::Point { position } => plane.signed_distance(position) > p_side,
            };
            if !lit || p_side < 0.0 {
                continue;
            }
            assert!(
                shadow_w(plane, light, p) > 0.0,
                "{p} from {light:?} onto {plane:?}"
            );
            checked += 1;
        }
        assert!(checked >= 200, "only {checked} cases checked");
    }

    #[test]
    fn reflected_lights_are_points_or_vectors() {
        let mut numbers = Numbers(0x5ad0_0005);
        for _ in 0..CASES {
            let mirror = reflection(numbers.plane());
            let position = numbers.vec3(10.0);
            let direction = numbers.unit();
            assert_eq!(
                LightSource::Point { position }.reflected(mirror),
                LightSource::Point {
                    position: mirror.transform_point3(position)
                }
            );
            assert_eq!(
                LightSource::Directional { direction }.reflected(mirror),
                LightSource::Directional {
                    direction: mirror.transform_vector3(direction)
                }
            );
        }
    }

    #[test]
    fn the_shadow_in_the_mirror_is_the_mirrored_shadow() {
        // Reflect the floor and the light and cast, or cast and reflect the shadow: the same point.
        let mut numbers = Numbers(0x5ad0_0006);
        let mut checked = 0;
        for i in 0..CASES {
            let mirror = reflection(numbers.plane());
            let floor = numbers.plane();
            let light = if i % 2 == 0 {
                point_light(&mut numbers)
            } else {
                directional_light(&mut numbers)
            };
            let p = numbers.vec3(10.0);
            if !well_posed(floor, light, p) {
                continue;
            }
            let cast_then_mirrored =
                mirror.transform_point3(shadow_matrix(floor, light).project_point3(p));
            let mirrored_then_cast =
                shadow_matrix(floor.transformed(mirror), light.reflected(mirror))
                    .project_point3(mirror.transform_point3(p));
            let tolerance = EPS * cast_then_mirrored.length().max(1.0);
            assert!(cast_then_mirrored.abs_diff_eq(mirrored_then_cast, tolerance));
            checked += 1;
        }
        assert!(checked >= 200, "only {checked} cases checked");
    }

    #[test]
    fn xm_matrix_shadow_rows_are_our_columns() {
        // XMMatrixShadow(plane y = 0, light (0, 10, 0, 1)) as DirectXMath returns it, row by row
        // (row i is −Pᵢ L plus P·L = 10 on the diagonal; row vectors: p' = p M).
        let xm_rows = [
            [10.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, -1.0],
            [0.0, 0.0, 10.0, 0.0],
            [0.0, 0.0, 0.0, 10.0],
        ];
        // The matrix in the maths' sense (rows as rows), then transposed for column vectors.
        let xm = Mat4::from_cols_array_2d(&xm_rows).transpose();
        let ours = shadow_matrix(
            Plane::new(Vec3::Y, 0.0),
            LightSource::Point {
                position: Vec3::new(0.0, 10.0, 0.0),
            },
        );
        assert_eq!(ours, xm.transpose());
        // A point at height 5, one to the side, throws its shadow two to the side.
        let s = ours.project_point3(Vec3::new(1.0, 5.0, 0.0));
        assert!(s.abs_diff_eq(Vec3::new(2.0, 0.0, 0.0), 1e-6));
    }

    #[test]
    fn xm_matrix_shadow_formula_for_many_cases() {
        // DirectXMath's code, element by element: M[i][j] = (P·L) δᵢⱼ − Pᵢ Lⱼ (row-major, row vectors).
        let mut numbers = Numbers(0x5ad0_0007);
        for i in 0..CASES {
            let plane = numbers.plane();
            let light = if i % 2 == 0 {
                point_light(&mut numbers)
            } else {
                directional_light(&mut numbers)
            };
            let (p, l) = (plane.as_vec4().to_array(), light.as_vec4().to_array());
            let dot = plane.as_vec4().dot(light.as_vec4());
            let xm_rows: [[f32; 4]; 4] = std::array::from_fn(|row| {
                std::array::from_fn(|col| {
                    let diagonal = if row == col { dot } else { 0.0 };
                    diagonal - p[row] * l[col]
                })
            });
            // The same sixteen numbers: D3D reads them as rows, glam as columns.
            let from_d3d = Mat4::from_cols_array_2d(&xm_rows);
            assert!(from_d3d.abs_diff_eq(shadow_matrix(plane, light), 1e-5));
        }
    }
}
