//! A solid's shadow volume, built on the CPU: the space the solid keeps the light from, bounded by
//! the solid's dark side, the sides swept from its silhouette away from the light, and the dark
//! side again at infinity.

use workbook::glam::{Mat4, Vec3, Vec4};
use workbook::math::shadow::LightSource;
use workbook::room::mesh::MeshData;

/// A solid's shadow volume from a light: triangles, three points each, in homogeneous
/// coordinates — w = 1 on the solid, w = 0 for a point at infinity (xyz is then the direction it
/// lies in). Every triangle is counter-clockwise seen from outside the volume.
#[derive(Debug, Clone, Default)]
pub struct Volume {
    /// Two triangles for each silhouette edge: the edge swept away from the light, to infinity.
    pub sides: Vec<Vec4>,
    /// The solid's triangles that face away from the light, twice: turned round where they are
    /// (the near cap) and moved to infinity (the far cap). Only z-fail draws them.
    pub caps: Vec<Vec4>,
    /// How many edges the silhouette has.
    pub silhouette_edges: usize,
}

// ANCHOR: extrude
/// A point moved away from the light to infinity: the direction the light's ray through it
/// travels, w = 0. The light as a 4-vector L = (position, 1), or (−direction, 0) for a directional
/// light, makes that direction w·p − L.xyz either way: p − position, or the light's direction (every
/// point then goes to the same point at infinity).
pub fn at_infinity(point: Vec3, light: LightSource) -> Vec4 {
    let l = light.as_vec4();
    (point * l.w - l.truncate()).extend(0.0)
}

/// Whether the light falls on the front of the triangle a, b, c (counter-clockwise from its
/// front): the way to the light, L.xyz − w·a, on the side its normal points to.
pub fn faces_the_light([a, b, c]: [Vec3; 3], light: LightSource) -> bool {
    let l = light.as_vec4();
    (b - a).cross(c - a).dot(l.truncate() - a * l.w) > 0.0
}
// ANCHOR_END: extrude

// ANCHOR: volume
/// The shadow volume of the closed mesh `shape`, placed in the world by `world`, from `light`.
pub fn shadow_volume(shape: &MeshData, world: Mat4, light: LightSource) -> Volume {
    let points: Vec<Vec3> = (shape.vertices.iter())
        .map(|vertex| world.transform_point3(Vec3::from(vertex.position)))
        .collect();
    let triangles: Vec<[u32; 3]> = (shape.indices.chunks_exact(3))
        .map(|t| [t[0], t[1], t[2]])
        .collect();
    // Which triangles the light falls on: those it sees counter-clockwise, from their front.
    let lit: Vec<bool> = (triangles.iter())
        .map(|t| faces_the_light(t.map(|i| points[i as usize]), light))
        .collect();
    // Across each edge of each triangle, the triangle on the other side.
    let neighbours = shape.neighbours();
    let mut volume = Volume::default();
    let finite = |i: u32| points[i as usize].extend(1.0);
    let infinite = |i: u32| at_infinity(points[i as usize], light);
    for (t, &[a, b, c]) in triangles.iter().enumerate() {
        if !lit[t] {
            // The dark side: the near cap turned round (the volume lies behind it, away from
            // the light), the far cap as it is (its outside faces away from the light).
            volume.caps.extend([finite(a), finite(c), finite(b)]);
            volume.caps.extend([infinite(a), infinite(b), infinite(c)]);
            continue;
        }
        // A silhouette edge: lit on this side, dark (or open) on the other.
        for (k, (from, to)) in [(a, b), (b, c), (c, a)].into_iter().enumerate() {
            if neighbours[t][k].is_none_or(|other| !lit[other as usize]) {
                // The edge swept to infinity, turned as the lit triangle's neighbour would be.
                let (a, b) = (finite(to), finite(from));
                let (a_far, b_far) = (infinite(to), infinite(from));
                volume.sides.extend([a, b, b_far, a, b_far, a_far]);
                volume.silhouette_edges += 1;
            }
        }
    }
    volume
}
// ANCHOR_END: volume

#[cfg(test)]
mod tests {
    use super::*;

    fn point(position: Vec3) -> LightSource {
        LightSource::Point { position }
    }

    /// The volume with its points at infinity brought to `distance` from the light: a closed
    /// mesh, to measure.
    fn finite(points: &[Vec4], light: Vec3, distance: f32) -> Vec<Vec3> {
        (points.iter())
            .map(|p| match p.w {
                0.0 => light + p.truncate().normalize() * distance,
                _ => p.truncate(),
            })
            .collect()
    }

    /// The signed volume of a closed triangle soup (positive: counter-clockwise from outside).
    fn signed_volume(points: &[Vec3]) -> f32 {
        (points.chunks_exact(3))
            .map(|t| t[0].dot(t[1].cross(t[2])) / 6.0)
            .sum()
    }

    /// Every edge of the soup is met once each way round: the volume is closed and its faces
    /// turn one way.
    fn closed(points: &[Vec3]) -> bool {
        let key = |p: Vec3| (p * 1e4).round().as_ivec3().to_array();
        let mut edges: Vec<_> = (points.chunks_exact(3))
            .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
            .map(|(a, b)| (key(a), key(b)))
            .collect();
        edges.sort();
        (edges.iter()).all(|&(a, b)| edges.binary_search(&(b, a)).is_ok())
    }

    #[test]
    fn a_point_at_infinity_lands_on_the_far_plane_inside_the_clip_volume() {
        use workbook::room::camera::{BOOK_POSE, Camera};
        let view_projection = Camera::projection_to_infinity(16.0 / 9.0) * BOOK_POSE.view();
        for direction in [Vec3::new(1.0, -1.0, -1.0), Vec3::new(-0.3, -0.2, -2.0)] {
            let clip = view_projection * direction.extend(0.0);
            // In front of the eye, at depth z / w = 1 exactly: the far cap is not clipped.
            assert!(clip.w > 0.0);
            assert_eq!(clip.z, clip.w, "{direction}: depth {}", clip.z / clip.w);
        }
    }

    #[test]
    fn a_cubes_volume_is_closed_and_turned_outwards() {
        let cube = MeshData::cuboid(Vec3::ONE);
        let light = Vec3::new(0.3, 4.0, 0.2);
        let volume = shadow_volume(&cube, Mat4::IDENTITY, point(light));
        // Lit from above: the top is lit, its four edges are the silhouette.
        assert_eq!(volume.silhouette_edges, 4);
        let all = [volume.sides.clone(), volume.caps].concat();
        let soup = finite(&all, light, 50.0);
        assert!(closed(&soup), "the volume has an open edge");
        assert!(
            signed_volume(&soup) > 0.0,
            "the volume is turned inside out"
        );
    }

    #[test]
    fn a_cube_lit_from_a_corner_has_a_silhouette_of_six_edges() {
        let cube = MeshData::cuboid(Vec3::ONE);
        let light = Vec3::new(3.0, 4.0, 5.0);
        let volume = shadow_volume(&cube, Mat4::from_translation(Vec3::X), point(light));
        assert_eq!(volume.silhouette_edges, 6);
        let soup = finite(&[volume.sides, volume.caps].concat(), light, 50.0);
        assert!(closed(&soup) && signed_volume(&soup) > 0.0);
    }
}
