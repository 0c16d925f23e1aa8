//! Quadric-error edge-collapse decimation (Garland & Heckbert 1997).
//!
//! The mesher works on a uniform grid, so flat areas get as many triangles
//! as the teeth. Decimation spends the triangle budget where the shape
//! needs it. Collapses that would break the manifold structure (link
//! condition), flip or crush a triangle are refused, so the mesh stays
//! closed and consistently wound.

use std::cmp::Reverse;
use std::collections::BinaryHeap;

use glam::{DMat3, DVec3};

use crate::mesher::Mesh;

/// Symmetric 4x4 error quadric, upper triangle stored row by row.
#[derive(Clone, Copy, Default)]
struct Quadric([f64; 10]);

impl Quadric {
    /// Squared distance to the plane `n . x + d = 0`, weighted by `w`.
    fn plane(n: DVec3, d: f64, w: f64) -> Quadric {
        Quadric(
            [
                n.x * n.x,
                n.x * n.y,
                n.x * n.z,
                n.x * d,
                n.y * n.y,
                n.y * n.z,
                n.y * d,
                n.z * n.z,
                n.z * d,
                d * d,
            ]
            .map(|v| v * w),
        )
    }

    fn add(&self, o: &Quadric) -> Quadric {
        let mut r = *self;
        for (a, b) in r.0.iter_mut().zip(o.0) {
            *a += b;
        }
        r
    }

    fn error(&self, p: DVec3) -> f64 {
        let q = &self.0;
        q[0] * p.x * p.x
            + 2.0 * q[1] * p.x * p.y
            + 2.0 * q[2] * p.x * p.z
            + 2.0 * q[3] * p.x
            + q[4] * p.y * p.y
            + 2.0 * q[5] * p.y * p.z
            + 2.0 * q[6] * p.y
            + q[7] * p.z * p.z
            + 2.0 * q[8] * p.z
            + q[9]
    }

    /// The point of least error, if the quadric is well conditioned.
    fn minimum(&self) -> Option<DVec3> {
        let q = &self.0;
        let a = DMat3::from_cols_array(&[q[0], q[1], q[2], q[1], q[4], q[5], q[2], q[5], q[7]]);
        let det = a.determinant();
        let scale = (q[0] + q[4] + q[7]).powi(3);
        if det.abs() <= 1e-6 * scale {
            return None;
        }
        Some(-(a.inverse() * DVec3::new(q[3], q[6], q[8])))
    }
}

/// Heap entry: (cost bits, vertex a, vertex b, stamp a, stamp b). Costs are
/// non-negative, so their bit patterns order like the numbers themselves.
type Entry = Reverse<(u64, u32, u32, u32, u32)>;

struct Decimator {
    pos: Vec<DVec3>,
    quadrics: Vec<Quadric>,
    tris: Vec<[u32; 3]>,
    tri_alive: Vec<bool>,
    /// Triangles around each vertex (may list dead triangles).
    vert_tris: Vec<Vec<u32>>,
    /// Bumped whenever a vertex moves, to invalidate stale heap entries.
    stamp: Vec<u32>,
    alive: Vec<bool>,
    /// Scratch lists, kept to avoid allocating on every query.
    scratch: [Vec<u32>; 3],
}

impl Decimator {
    fn new(mesh: &Mesh) -> Decimator {
        let n = mesh.positions.len();
        let mut d = Decimator {
            pos: mesh.positions.iter().map(|p| p.as_dvec3()).collect(),
            quadrics: vec![Quadric::default(); n],
            tris: mesh.triangles.clone(),
            tri_alive: vec![true; mesh.triangles.len()],
            vert_tris: vec![Vec::new(); n],
            stamp: vec![0; n],
            alive: vec![true; n],
            scratch: Default::default(),
        };
        for (t, tri) in mesh.triangles.iter().enumerate() {
            let p = tri.map(|i| d.pos[i as usize]);
            let cross = (p[1] - p[0]).cross(p[2] - p[0]);
            if let Some(normal) = cross.try_normalize() {
                let q = Quadric::plane(normal, -normal.dot(p[0]), 0.5 * cross.length());
                for &i in tri {
                    d.quadrics[i as usize] = d.quadrics[i as usize].add(&q);
                }
            }
            for &i in tri {
                d.vert_tris[i as usize].push(t as u32);
            }
        }
        d
    }

    fn live_tris(&self, v: u32) -> impl Iterator<Item = u32> + '_ {
        self.vert_tris[v as usize]
            .iter()
            .copied()
            .filter(|&t| self.tri_alive[t as usize])
    }

    /// The vertices sharing an edge with `v`, sorted, into `out`.
    fn neighbours(&self, v: u32, out: &mut Vec<u32>) {
        out.clear();
        for t in self.live_tris(v) {
            out.extend(self.tris[t as usize].iter().filter(|&&w| w != v));
        }
        out.sort_unstable();
        out.dedup();
    }

    /// Best position for collapsing edge (a, b) and its error.
    fn plan(&self, a: u32, b: u32) -> (f64, DVec3) {
        let q = self.quadrics[a as usize].add(&self.quadrics[b as usize]);
        let (pa, pb) = (self.pos[a as usize], self.pos[b as usize]);
        let mid = 0.5 * (pa + pb);
        let mut best = (q.error(mid), mid);
        // Trust the optimum only when it stays near the edge.
        let optimum = q.minimum().filter(|m| m.distance(mid) <= pa.distance(pb));
        for c in [Some(pa), Some(pb), optimum].into_iter().flatten() {
            let e = q.error(c);
            if e < best.0 {
                best = (e, c);
            }
        }
        (best.0.max(0.0), best.1)
    }

    fn entry(&self, a: u32, b: u32) -> Entry {
        let (a, b) = (a.min(b), a.max(b));
        let (cost, _) = self.plan(a, b);
        Reverse((
            cost.to_bits(),
            a,
            b,
            self.stamp[a as usize],
            self.stamp[b as usize],
        ))
    }

    /// Whether collapsing (a, b) to `target` keeps the mesh well formed.
    fn can_collapse(&mut self, a: u32, b: u32, target: DVec3) -> bool {
        let mut scratch = std::mem::take(&mut self.scratch);
        let ok = self.collapse_keeps_manifold(a, b, &mut scratch)
            && self.collapse_keeps_shape(a, b, target);
        self.scratch = scratch;
        ok
    }

    /// Link condition: `a` and `b` share exactly the two vertices opposite
    /// their edge, and no vertex is left with fewer than three neighbours.
    fn collapse_keeps_manifold(&self, a: u32, b: u32, scratch: &mut [Vec<u32>; 3]) -> bool {
        let [na, nb, nc] = scratch;
        let shared = self
            .live_tris(a)
            .filter(|&t| self.tris[t as usize].contains(&b))
            .count();
        if shared != 2 {
            return false;
        }
        self.neighbours(a, na);
        self.neighbours(b, nb);
        if na.len() + nb.len() < 2 + 2 + 3 {
            return false;
        }
        let mut common = 0;
        for &v in na.iter() {
            if nb.binary_search(&v).is_ok() {
                common += 1;
                self.neighbours(v, nc);
                if nc.len() <= 3 {
                    return false;
                }
            }
        }
        common == 2
    }

    /// No triangle around the edge may flip or become a sliver.
    fn collapse_keeps_shape(&self, a: u32, b: u32, target: DVec3) -> bool {
        for v in [a, b] {
            for t in self.live_tris(v) {
                let tri = self.tris[t as usize];
                if tri.contains(&a) && tri.contains(&b) {
                    continue;
                }
                let old = tri.map(|i| self.pos[i as usize]);
                let new = tri.map(|i| {
                    if i == a || i == b {
                        target
                    } else {
                        self.pos[i as usize]
                    }
                });
                let n_old = (old[1] - old[0]).cross(old[2] - old[0]);
                let n_new = (new[1] - new[0]).cross(new[2] - new[0]);
                if n_new.dot(n_old) <= 0.3 * n_new.length() * n_old.length() {
                    return false;
                }
                if quality(new) < 0.05 && quality(new) < quality(old) {
                    return false;
                }
            }
        }
        true
    }

    /// Merges `b` into `a` at `target`.
    fn collapse(&mut self, a: u32, b: u32, target: DVec3) {
        let (ai, bi) = (a as usize, b as usize);
        self.pos[ai] = target;
        self.quadrics[ai] = self.quadrics[ai].add(&self.quadrics[bi]);
        self.alive[bi] = false;
        self.stamp[ai] += 1;
        for t in std::mem::take(&mut self.vert_tris[bi]) {
            let ti = t as usize;
            if !self.tri_alive[ti] {
                continue;
            }
            if self.tris[ti].contains(&a) {
                self.tri_alive[ti] = false;
            } else {
                for v in &mut self.tris[ti] {
                    if *v == b {
                        *v = a;
                    }
                }
                self.vert_tris[ai].push(t);
            }
        }
        let live = &self.tri_alive;
        self.vert_tris[ai].retain(|&t| live[t as usize]);
    }

    /// The live triangles, with the vertices they use renumbered densely.
    fn into_mesh(self) -> Mesh {
        let mut remap = vec![u32::MAX; self.pos.len()];
        let mut out = Mesh::default();
        for (tri, _) in self.tris.iter().zip(&self.tri_alive).filter(|t| *t.1) {
            let tri = tri.map(|v| {
                if remap[v as usize] == u32::MAX {
                    remap[v as usize] = out.positions.len() as u32;
                    out.positions.push(self.pos[v as usize].as_vec3());
                }
                remap[v as usize]
            });
            out.triangles.push(tri);
        }
        out
    }
}

/// 1 for an equilateral triangle, 0 for a degenerate one.
fn quality(p: [DVec3; 3]) -> f64 {
    let area2 = (p[1] - p[0]).cross(p[2] - p[0]).length();
    let sum =
        p[0].distance_squared(p[1]) + p[1].distance_squared(p[2]) + p[2].distance_squared(p[0]);
    if sum == 0.0 {
        0.0
    } else {
        2.0 * 3f64.sqrt() * area2 / sum
    }
}

/// Collapses edges, cheapest first, until at most `target` triangles remain
/// (or no legal collapse is left).
pub fn decimate(mesh: &Mesh, target: usize) -> Mesh {
    let mut d = Decimator::new(mesh);
    let mut heap: BinaryHeap<Entry> = mesh
        .triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .filter(|(a, b)| a < b)
        .map(|(a, b)| d.entry(a, b))
        .collect();
    let mut live = mesh.triangles.len();
    // Edges refused so far: a collapse nearby may make them legal, so they
    // get another chance whenever the queue runs dry.
    let mut refused: Vec<(u32, u32)> = Vec::new();
    let mut progress = false;
    let mut around = Vec::new();
    while live > target {
        let Some(Reverse((_, a, b, sa, sb))) = heap.pop() else {
            // Stop once a whole pass over the refused edges changed nothing.
            if !progress || refused.is_empty() {
                break;
            }
            progress = false;
            let retry: Vec<Entry> = refused
                .drain(..)
                .filter(|&(a, b)| d.alive[a as usize] && d.alive[b as usize])
                .map(|(a, b)| d.entry(a, b))
                .collect();
            heap.extend(retry);
            continue;
        };
        let (ai, bi) = (a as usize, b as usize);
        if !d.alive[ai] || !d.alive[bi] || d.stamp[ai] != sa || d.stamp[bi] != sb {
            continue;
        }
        let (_, target_pos) = d.plan(a, b);
        if !d.can_collapse(a, b, target_pos) {
            refused.push((a, b));
            continue;
        }
        d.collapse(a, b, target_pos);
        live -= 2;
        progress = true;
        // Only the edges at `a` changed cost; their old entries are stale
        // now that `a`'s stamp moved on.
        d.neighbours(a, &mut around);
        for &v in &around {
            heap.push(d.entry(a, v));
        }
    }
    d.into_mesh()
}

#[cfg(test)]
mod tests {
    use glam::{UVec3, Vec3};

    use super::*;
    use crate::mesher::{Grid, assert_closed_manifold, marching_tetrahedra};

    #[test]
    fn decimated_torus_stays_closed() {
        let f = |p: Vec3| {
            let q = glam::Vec2::new(glam::Vec2::new(p.x, p.z).length() - 0.4, p.y);
            q.length() - 0.15
        };
        let grid = Grid {
            min: Vec3::splat(-0.62),
            step: 0.04,
            cells: UVec3::splat(31),
        };
        let mesh = marching_tetrahedra(&f, &grid);
        let small = decimate(&mesh, 800);
        assert!(small.triangles.len() <= 800, "{}", small.triangles.len());
        assert_closed_manifold(&small);
        // A torus: V - E + F = 0.
        let (v, f) = (small.positions.len() as i64, small.triangles.len() as i64);
        assert_eq!(v - f * 3 / 2 + f, 0);
        let before = crate::smooth::signed_volume(&mesh);
        let after = crate::smooth::signed_volume(&small);
        assert!(
            (after - before).abs() < 0.03 * before,
            "{before} -> {after}"
        );
    }
}
