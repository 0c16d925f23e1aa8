//! Marching tetrahedra: turns a signed-distance function into a closed,
//! consistently wound triangle mesh.
//!
//! The field is sampled on a regular grid (only near the surface: blocks that
//! are provably far from it are skipped). Every grid cell is split into six
//! tetrahedra around its main diagonal (the Kuhn split, which matches up
//! across neighbouring cells) and the zero level set of the piecewise-linear
//! interpolant is extracted tetrahedron by tetrahedron. The level set of a
//! piecewise-linear function is a proper 2-manifold, so every edge of the
//! result is shared by exactly two triangles, with opposite directions.

use std::collections::HashMap;

use glam::{IVec3, USizeVec3, UVec3, Vec3};

/// An indexed triangle mesh, counter-clockwise when seen from outside.
#[derive(Clone, Debug, Default)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
}

/// A box of `cells` cubic cells of edge `step`, starting at `min`.
pub struct Grid {
    pub min: Vec3,
    pub step: f32,
    pub cells: UVec3,
}

const BLOCK: usize = 4;

impl Grid {
    fn point(&self, i: usize, j: usize, k: usize) -> Vec3 {
        self.min + self.step * Vec3::new(i as f32, j as f32, k as f32)
    }

    /// Samples `f` at every grid point that may lie near the surface; far
    /// away points get the value at their block's centre (right sign, rough
    /// magnitude), which is all that is needed there.
    fn sample(&self, f: &impl Fn(Vec3) -> f32) -> Vec<f32> {
        let n = (self.cells + UVec3::ONE).as_usizevec3();
        let mut values = vec![0.0; n.x * n.y * n.z];
        for bk in (0..n.z).step_by(BLOCK) {
            for bj in (0..n.y).step_by(BLOCK) {
                for bi in (0..n.x).step_by(BLOCK) {
                    let hi = [
                        (bi + BLOCK).min(n.x),
                        (bj + BLOCK).min(n.y),
                        (bk + BLOCK).min(n.z),
                    ];
                    let lo = self.point(bi, bj, bk);
                    let top = self.point(hi[0] - 1, hi[1] - 1, hi[2] - 1);
                    let centre = 0.5 * (lo + top);
                    let radius = 0.5 * (top - lo).length();
                    let d = f(centre);
                    // The field is close to, but not exactly, a distance:
                    // keep a generous safety margin.
                    let far = d.abs() > 1.5 * radius + 2.0 * self.step;
                    for k in bk..hi[2] {
                        for j in bj..hi[1] {
                            for i in bi..hi[0] {
                                values[i + n.x * (j + n.y * k)] =
                                    if far { d } else { f(self.point(i, j, k)) };
                            }
                        }
                    }
                }
            }
        }
        values
    }
}

/// Meshes the zero level set of `f` inside `grid`. The field must be
/// positive (outside) on the grid's boundary.
pub fn marching_tetrahedra(f: &impl Fn(Vec3) -> f32, grid: &Grid) -> Mesh {
    // The six tetrahedra of a cell, as corner numbers (bit 0 = +x, bit 1 =
    // +y, bit 2 = +z): the paths from corner 0 to corner 7 along the axes.
    const TETS: [[usize; 4]; 6] = [
        [0, 1, 3, 7],
        [0, 1, 5, 7],
        [0, 2, 3, 7],
        [0, 2, 6, 7],
        [0, 4, 5, 7],
        [0, 4, 6, 7],
    ];
    let corner =
        |b: usize| IVec3::new((b & 1) as i32, ((b >> 1) & 1) as i32, ((b >> 2) & 1) as i32);
    let values = grid.sample(f);
    let c = grid.cells.as_usizevec3();
    let n = c + USizeVec3::ONE;
    let point = |id: u32| {
        let id = id as usize;
        grid.point(id % n.x, (id / n.x) % n.y, id / (n.x * n.y))
    };

    let mut mesh = Mesh::default();
    // One vertex per grid-point pair whose segment crosses the surface.
    let mut edge_vertex: HashMap<(u32, u32), u32> = HashMap::new();
    let mut crossing = |inside: u32, outside: u32, mesh: &mut Mesh| -> u32 {
        *edge_vertex.entry((inside, outside)).or_insert_with(|| {
            let (a, b) = (values[inside as usize], values[outside as usize]);
            // Kept off the end points so no triangle is exactly degenerate.
            let t = (a / (a - b)).clamp(0.01, 0.99);
            mesh.positions.push(point(inside).lerp(point(outside), t));
            (mesh.positions.len() - 1) as u32
        })
    };
    for k in 0..c.z {
        for j in 0..c.y {
            for i in 0..c.x {
                let ids: [u32; 8] = std::array::from_fn(|b| {
                    let o = corner(b).as_usizevec3();
                    (i + o.x + n.x * (j + o.y + n.y * (k + o.z))) as u32
                });
                let inside = ids.map(|id| values[id as usize] < 0.0);
                if inside.iter().all(|&x| x) || !inside.iter().any(|&x| x) {
                    continue;
                }
                for tet in TETS {
                    let (ins, outs): (Vec<usize>, Vec<usize>) =
                        tet.iter().partition(|&&b| inside[b]);
                    let mut cross =
                        |a: usize, b: usize, mesh: &mut Mesh| crossing(ids[a], ids[b], mesh);
                    match (ins.as_slice(), outs.as_slice()) {
                        (&[i0], &[o0, o1, o2]) => {
                            // Facing away from the lone inside corner.
                            let tri = [
                                cross(i0, o0, &mut mesh),
                                cross(i0, o1, &mut mesh),
                                cross(i0, o2, &mut mesh),
                            ];
                            push_oriented(
                                &mut mesh,
                                tri,
                                det(corner(i0), corner(o0), corner(o1), corner(o2)) > 0,
                            );
                        }
                        (&[i0, i1, i2], &[o0]) => {
                            // Facing toward the lone outside corner.
                            let tri = [
                                cross(i0, o0, &mut mesh),
                                cross(i1, o0, &mut mesh),
                                cross(i2, o0, &mut mesh),
                            ];
                            push_oriented(
                                &mut mesh,
                                tri,
                                det(corner(o0), corner(i0), corner(i1), corner(i2)) < 0,
                            );
                        }
                        (&[i0, i1], &[o0, o1]) => {
                            let quad = [
                                cross(i0, o0, &mut mesh),
                                cross(i0, o1, &mut mesh),
                                cross(i1, o1, &mut mesh),
                                cross(i1, o0, &mut mesh),
                            ];
                            // The quad is a deformed copy of the parallelogram of
                            // edge midpoints, whose orientation is exact here.
                            let (ci0, ci1, co0, co1) =
                                (corner(i0), corner(i1), corner(o0), corner(o1));
                            let normal = (co1 - co0).cross(ci1 - ci0);
                            let keep = normal.dot(co0 + co1 - ci0 - ci1) > 0;
                            push_oriented(&mut mesh, [quad[0], quad[1], quad[2]], keep);
                            push_oriented(&mut mesh, [quad[0], quad[2], quad[3]], keep);
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    mesh
}

/// Six times the signed volume of the tetrahedron (a, b, c, d), exactly.
fn det(a: IVec3, b: IVec3, c: IVec3, d: IVec3) -> i32 {
    (b - a).dot((c - a).cross(d - a))
}

fn push_oriented(mesh: &mut Mesh, t: [u32; 3], keep: bool) {
    mesh.triangles
        .push(if keep { t } else { [t[0], t[2], t[1]] });
}

/// Test helper: panics unless every directed edge appears once and its
/// reverse once too (closed, manifold, consistently wound).
#[cfg(test)]
pub(crate) fn assert_closed_manifold(mesh: &Mesh) {
    let mut edges: Vec<(u32, u32)> = mesh
        .triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .collect();
    edges.sort_unstable();
    assert!(
        edges.windows(2).all(|w| w[0] != w[1]),
        "an edge is used twice in the same direction"
    );
    for &(a, b) in &edges {
        assert!(
            edges.binary_search(&(b, a)).is_ok(),
            "edge {a}-{b} has no twin"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_is_closed_and_faces_outward() {
        let f = |p: Vec3| p.length() - 0.5;
        let grid = Grid {
            min: Vec3::splat(-0.6),
            step: 0.05,
            cells: UVec3::splat(24),
        };
        let mesh = marching_tetrahedra(&f, &grid);
        assert_closed_manifold(&mesh);
        let volume = crate::smooth::signed_volume(&mesh);
        let exact = 4.0 / 3.0 * std::f32::consts::PI * 0.125;
        assert!(
            (volume - exact).abs() < 0.03 * exact,
            "volume {volume} vs {exact}"
        );
        for p in &mesh.positions {
            assert!((p.length() - 0.5).abs() < 0.01);
        }
    }
}
