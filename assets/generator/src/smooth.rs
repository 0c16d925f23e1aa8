//! Mesh clean-up after meshing: dropping specks, Taubin smoothing (which,
//! unlike plain Laplacian smoothing, does not shrink the mesh), snapping
//! vertices back onto the implicit surface, and smooth vertex normals.

use glam::Vec3;

use crate::mesher::Mesh;

/// Vertex neighbourhoods in compressed form: the neighbours of vertex `v`
/// are `list[start[v]..start[v + 1]]`, sorted and without duplicates.
struct Adjacency {
    start: Vec<usize>,
    list: Vec<u32>,
}

impl Adjacency {
    fn new(mesh: &Mesh) -> Adjacency {
        let mut pairs: Vec<(u32, u32)> = Vec::with_capacity(mesh.triangles.len() * 6);
        for t in &mesh.triangles {
            for e in 0..3 {
                let (a, b) = (t[e], t[(e + 1) % 3]);
                pairs.push((a, b));
                pairs.push((b, a));
            }
        }
        pairs.sort_unstable();
        pairs.dedup();
        let mut start = vec![0; mesh.positions.len() + 1];
        for &(a, _) in &pairs {
            start[a as usize + 1] += 1;
        }
        for v in 0..mesh.positions.len() {
            start[v + 1] += start[v];
        }
        Adjacency {
            start,
            list: pairs.into_iter().map(|(_, b)| b).collect(),
        }
    }

    fn neighbours(&self, v: usize) -> &[u32] {
        &self.list[self.start[v]..self.start[v + 1]]
    }
}

/// Moves every vertex toward the zero level set of `f` with one Newton step
/// along the (tetrahedral finite-difference) gradient, by at most
/// `max_move`. Vertices whose move would flip a triangle stay put.
pub fn project(mesh: &mut Mesh, f: &impl Fn(Vec3) -> f32, max_move: f32) {
    const E: f32 = 1e-3;
    // Four samples at the corners of a tetrahedron give value and gradient.
    const K: [Vec3; 4] = [
        Vec3::new(1.0, -1.0, -1.0),
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(-1.0, 1.0, -1.0),
        Vec3::new(1.0, 1.0, 1.0),
    ];
    let old = mesh.positions.clone();
    for p in &mut mesh.positions {
        let samples = K.map(|k| f(*p + k * E));
        let d = samples.iter().sum::<f32>() / 4.0;
        let g = K.iter().zip(samples).map(|(k, s)| *k * s).sum::<Vec3>() / (4.0 * E);
        let g2 = g.length_squared();
        if g2 < 1e-8 {
            continue;
        }
        let step = g * (d / g2);
        let len = step.length();
        *p -= if len > max_move {
            step * (max_move / len)
        } else {
            step
        };
    }
    // Undo moves that turn a triangle over; repeat, as undoing one vertex
    // can uncover another.
    for _ in 0..4 {
        let mut undo = vec![false; old.len()];
        for t in &mesh.triangles {
            let [a, b, c] = t.map(|i| old[i as usize]);
            let [na, nb, nc] = t.map(|i| mesh.positions[i as usize]);
            let before = (b - a).cross(c - a);
            let after = (nb - na).cross(nc - na);
            if after.dot(before) <= 0.5 * after.length() * before.length() {
                for &i in t {
                    undo[i as usize] = true;
                }
            }
        }
        if !undo.contains(&true) {
            break;
        }
        for (i, u) in undo.into_iter().enumerate() {
            if u {
                mesh.positions[i] = old[i];
            }
        }
    }
}

/// Taubin lambda/mu smoothing with uniform weights.
pub fn taubin(mesh: &mut Mesh, iterations: usize) {
    let adj = Adjacency::new(mesh);
    for _ in 0..iterations {
        for factor in [0.5, -0.53] {
            let old = mesh.positions.clone();
            for (v, p) in mesh.positions.iter_mut().enumerate() {
                let nb = adj.neighbours(v);
                if nb.is_empty() {
                    continue;
                }
                let mean = nb.iter().map(|&n| old[n as usize]).sum::<Vec3>() / nb.len() as f32;
                *p += factor * (mean - old[v]);
            }
        }
    }
}

/// Area-weighted vertex normals, normalised.
pub fn vertex_normals(mesh: &Mesh) -> Vec<Vec3> {
    let mut normals = vec![Vec3::ZERO; mesh.positions.len()];
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
        let n = (b - a).cross(c - a);
        for &i in t {
            normals[i as usize] += n;
        }
    }
    normals
        .into_iter()
        .map(|n| n.try_normalize().unwrap_or(Vec3::Y))
        .collect()
}

/// Signed volume enclosed by the mesh: positive when triangles are
/// counter-clockwise seen from outside.
pub fn signed_volume(mesh: &Mesh) -> f32 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            a.dot(b.cross(c)) / 6.0
        })
        .sum()
}

/// Drops connected pieces with fewer than `min_triangles` triangles (specks
/// the mesher finds where two surfaces nearly touch) and unused vertices.
pub fn remove_small_pieces(mesh: &mut Mesh, min_triangles: usize) {
    let mut parent: Vec<u32> = (0..mesh.positions.len() as u32).collect();
    fn root(parent: &mut [u32], mut v: u32) -> u32 {
        while parent[v as usize] != v {
            parent[v as usize] = parent[parent[v as usize] as usize];
            v = parent[v as usize];
        }
        v
    }
    for t in &mesh.triangles {
        let a = root(&mut parent, t[0]);
        for &v in &t[1..] {
            let b = root(&mut parent, v);
            if a != b {
                parent[b as usize] = a;
            }
        }
    }
    let mut count = vec![0usize; mesh.positions.len()];
    let roots: Vec<u32> = mesh
        .triangles
        .iter()
        .map(|t| root(&mut parent, t[0]))
        .collect();
    for &r in &roots {
        count[r as usize] += 1;
    }
    let mut remap = vec![u32::MAX; mesh.positions.len()];
    let mut kept = Mesh::default();
    for (t, &r) in mesh.triangles.iter().zip(&roots) {
        if count[r as usize] < min_triangles {
            continue;
        }
        let t = t.map(|v| {
            if remap[v as usize] == u32::MAX {
                remap[v as usize] = kept.positions.len() as u32;
                kept.positions.push(mesh.positions[v as usize]);
            }
            remap[v as usize]
        });
        kept.triangles.push(t);
    }
    *mesh = kept;
}
