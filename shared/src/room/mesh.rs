//! Meshes: the vertex layout, OBJ files through `tobj` (normals computed when a file has none, placed
//! and scaled to fit), the room's boxes and quads, and their GPU buffers.

use std::io::Read;
use std::path::Path;

use anyhow::{Context, Result, bail};
use glam::{Vec2, Vec3};
use wgpu::util::DeviceExt;

use crate::gpu::pass::Pass;

/// One vertex as every shader of the workbook reads it.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
pub struct Vertex {
    pub position: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
}

impl Vertex {
    pub const ATTRIBUTES: [wgpu::VertexAttribute; 3] =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x2];

    pub const LAYOUT: wgpu::VertexBufferLayout<'static> = wgpu::VertexBufferLayout {
        array_stride: std::mem::size_of::<Vertex>() as wgpu::BufferAddress,
        step_mode: wgpu::VertexStepMode::Vertex,
        attributes: &Self::ATTRIBUTES,
    };

    fn new(position: Vec3, normal: Vec3, uv: Vec2) -> Self {
        Self {
            position: position.into(),
            normal: normal.into(),
            uv: uv.into(),
        }
    }
}

/// The largest model file [`MeshData::load_obj`] reads: 256 MiB. The scanned skulls people show
/// are 5–50 MB of text; reading is bounded so that a wrong file (a disk image, a log) cannot take
/// the machine's memory.
pub const MAX_MODEL_BYTES: u64 = 256 << 20;

/// The most triangles a model may have: 5 million (a 50 MB scan has one or two). The loader's
/// memory grows with them more than with the file's size — tobj keeps every face as 104 bytes
/// until the end, in a list that doubles as it grows — so they are bounded too.
pub const MAX_TRIANGLES: usize = 5_000_000;

/// The most heap [`MeshData::load_obj`] holds at once, as a multiple of the file's size, for a
/// dense mesh as a scan is; a test in the suite (`fuzz::loading_a_model_holds_...`) keeps it under
/// this. Measured: 4.15 for the skull (1.7 MB), 6.46 for a 71 MB grid of a million vertices and two
/// million triangles, whose 460 MB peak is, in MB: the file's text 71; tobj's faces, 104 bytes
/// each in a list of room for 2²¹, 218; tobj's table of distinct corners 69, and 35 more while it
/// doubles; tobj's vertex lists and indices 67. All but the text are tobj's own, so that only a
/// loader of our own could make the multiple much smaller. A file of nothing but short triangle
/// lines (`f 1 2 3`) costs more per byte, and [`MAX_TRIANGLES`] bounds it: at the limit (5 million
/// such lines, 40 MB) the lesson's peak memory grew by 0.66 GB, measured.
pub const MAX_MEMORY_MULTIPLE: f64 = 7.0;

/// What a path that is not a regular file is, for the error message.
fn kind_of(file_type: &std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_char_device() || file_type.is_block_device() {
            return "a device, not a file";
        }
        if file_type.is_fifo() {
            return "a FIFO (a pipe), not a file";
        }
        if file_type.is_socket() {
            return "a socket, not a file";
        }
    }
    if file_type.is_dir() {
        "a folder, not a file"
    } else {
        "not a regular file"
    }
}

/// A triangle mesh on the CPU; triangles are counter-clockwise seen from outside.
#[derive(Debug, Clone, Default)]
pub struct MeshData {
    pub vertices: Vec<Vertex>,
    pub indices: Vec<u32>,
}

impl MeshData {
    /// Reads an OBJ file: every object in it, triangulated, as one mesh, centred on the origin and
    /// scaled so that its largest side is 1. Vertex normals are computed when the file has none, or one
    /// that is zero or not finite; the file's others are normalised.
    ///
    /// Only a regular file is read (a device such as `/dev/zero`, a FIFO or a folder is refused
    /// before reading), and no more than [`MAX_MODEL_BYTES`] of it.
    pub fn load_obj(path: &Path) -> Result<Self> {
        let shown = path.display();
        let cannot_read = || format!("cannot read model `{shown}`");
        let metadata = std::fs::metadata(path).with_context(cannot_read)?;
        if !metadata.is_file() {
            bail!(
                "model `{shown}` is {}: --model takes an OBJ file",
                kind_of(&metadata.file_type())
            );
        }
        let too_large = || {
            anyhow::anyhow!(
                "model `{shown}` is larger than {} MiB, the most a model may be",
                MAX_MODEL_BYTES >> 20
            )
        };
        if metadata.len() > MAX_MODEL_BYTES {
            return Err(too_large());
        }
        // At most one byte past the limit, should the file have grown since it was measured.
        let mut bytes = Vec::with_capacity(metadata.len() as usize);
        let file = std::fs::File::open(path).with_context(cannot_read)?;
        file.take(MAX_MODEL_BYTES + 1)
            .read_to_end(&mut bytes)
            .with_context(cannot_read)?;
        if bytes.len() as u64 > MAX_MODEL_BYTES {
            return Err(too_large());
        }
        let name = shown.to_string();
        let models = read_models(&name, &bytes)?;
        // The text is not needed once tobj has read it: the mesh is built without it.
        drop(bytes);
        Self::from_models(&name, models)
    }

    /// [`MeshData::load_obj`] on the text of an OBJ file already in memory; `name` names the model in
    /// error messages (`load_obj` passes the file's path).
    pub fn parse_obj(name: &str, bytes: &[u8]) -> Result<Self> {
        Self::from_models(name, read_models(name, bytes)?)
    }

    /// The mesh of tobj's models, each freed as soon as its part of the mesh is built.
    fn from_models(name: &str, models: Vec<tobj::Model>) -> Result<Self> {
        let shown = name;
        let mut mesh = MeshData::default();
        let vertices: usize = models.iter().map(|m| m.mesh.positions.len() / 3).sum();
        let indices: usize = models.iter().map(|m| m.mesh.indices.len()).sum();
        mesh.vertices.reserve_exact(vertices);
        mesh.indices.reserve_exact(indices);
        let mut all_have_normals = true;
        for model in models {
            let m = model.mesh;
            let base = mesh.vertices.len() as u32;
            let count = m.positions.len() / 3;
            let has_normals = m.normals.len() == m.positions.len();
            all_have_normals &= has_normals;
            for i in 0..count {
                let position = Vec3::from_slice(&m.positions[3 * i..3 * i + 3]);
                let normal = if has_normals {
                    Vec3::from_slice(&m.normals[3 * i..3 * i + 3])
                } else {
                    Vec3::ZERO
                };
                let uv = if m.texcoords.len() == 2 * count {
                    Vec2::from_slice(&m.texcoords[2 * i..2 * i + 2])
                } else {
                    Vec2::ZERO
                };
                mesh.vertices.push(Vertex::new(position, normal, uv));
            }
            for &index in &m.indices {
                if index as usize >= count {
                    bail!("model `{shown}` has a face that names a missing vertex");
                }
                mesh.indices.push(base + index);
            }
        }
        if mesh.indices.len() < 3 {
            bail!("model `{shown}` has no triangles: is it an OBJ file?");
        }
        if mesh
            .vertices
            .iter()
            .flat_map(|v| v.position)
            .any(|c| !c.is_finite())
        {
            bail!("model `{shown}` has coordinates that are not finite numbers");
        }
        if mesh
            .vertices
            .iter()
            .flat_map(|v| v.uv)
            .any(|c| !c.is_finite())
        {
            bail!("model `{shown}` has texture coordinates that are not finite numbers");
        }
        // The file's normals are used where they are of unit length and normalised where not; when
        // one cannot be (zero, or not a finite number), all are computed as for a file without them.
        let mut usable_normals = all_have_normals;
        if all_have_normals {
            for vertex in &mut mesh.vertices {
                let normal = Vec3::from(vertex.normal);
                let error = (normal.length() - 1.0).abs();
                if error > 1e-3 || error.is_nan() {
                    let Some(unit) = unit_length(normal) else {
                        usable_normals = false;
                        break;
                    };
                    vertex.normal = unit.into();
                }
            }
        }
        mesh.fit_unit_box()
            .with_context(|| format!("model `{shown}` cannot be placed"))?;
        // After placing: in the unit box the edges' cross products neither overflow nor vanish.
        if !usable_normals {
            mesh.compute_normals();
        }
        Ok(mesh)
    }

    /// Smooth vertex normals: the area-weighted sum of the normals of the triangles around each vertex.
    pub fn compute_normals(&mut self) {
        let mut sums = vec![Vec3::ZERO; self.vertices.len()];
        for triangle in self.indices.chunks_exact(3) {
            let [a, b, c] =
                [0, 1, 2].map(|k| Vec3::from(self.vertices[triangle[k] as usize].position));
            let face = (b - a).cross(c - a); // length = twice the area
            for &index in triangle {
                sums[index as usize] += face;
            }
        }
        for (vertex, sum) in self.vertices.iter_mut().zip(sums) {
            vertex.normal = unit_length(sum).unwrap_or(Vec3::Y).into();
        }
    }

    /// Moves the mesh so its bounding box is centred on the origin and scales it so the box's
    /// largest side is 1: a model far from the origin or of odd size still lands where the skull goes.
    pub fn fit_unit_box(&mut self) -> Result<()> {
        let (min, max) = self.bounds();
        // In halves: `min + max` and `max - min` overflow for huge coordinates where these do not,
        // and for others they are the same numbers (halving is exact).
        let centre = min * 0.5 + max * 0.5;
        let half_extent = (max * 0.5 - min * 0.5).max_element();
        if !(half_extent > 0.5e-6 && half_extent.is_finite()) {
            bail!("all its vertices are at one point");
        }
        for vertex in &mut self.vertices {
            let offset = Vec3::from(vertex.position) - centre;
            vertex.position = (offset / half_extent * 0.5).into();
        }
        Ok(())
    }

    /// The corners of the axis-aligned bounding box.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.vertices.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(min, max), v| (min.min(v.position.into()), max.max(v.position.into())),
        )
    }

    /// Appends a rectangle with corner `origin` spanned by `u` and `v`, facing `u × v`, with texture
    /// coordinates running from 0 to `repeat`.
    pub fn add_quad(&mut self, origin: Vec3, u: Vec3, v: Vec3, repeat: Vec2) {
        let normal = u.cross(v).normalize();
        let base = self.vertices.len() as u32;
        let corners = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
        for (s, t) in corners {
            let position = origin + u * s + v * t;
            // Texture v runs downwards in images, upwards along `v` here.
            let uv = Vec2::new(s * repeat.x, (1.0 - t) * repeat.y);
            self.vertices.push(Vertex::new(position, normal, uv));
        }
        self.indices
            .extend([base, base + 1, base + 2, base, base + 2, base + 3]);
    }

    /// An axis-aligned box centred on the origin, each face textured once.
    pub fn cuboid(size: Vec3) -> Self {
        let h = size * 0.5;
        let mut mesh = Self::default();
        let (x, y, z) = (Vec3::X * size.x, Vec3::Y * size.y, Vec3::Z * size.z);
        let one = Vec2::ONE;
        mesh.add_quad(Vec3::new(-h.x, -h.y, h.z), x, y, one); // front (+z)
        mesh.add_quad(Vec3::new(h.x, -h.y, -h.z), -x, y, one); // back (-z)
        mesh.add_quad(Vec3::new(h.x, -h.y, h.z), -z, y, one); // right (+x)
        mesh.add_quad(Vec3::new(-h.x, -h.y, -h.z), z, y, one); // left (-x)
        mesh.add_quad(Vec3::new(-h.x, h.y, h.z), x, -z, one); // top (+y)
        mesh.add_quad(Vec3::new(-h.x, -h.y, -h.z), x, z, one); // bottom (-y)
        mesh
    }

    /// A ball of `radius` centred on the origin, its triangles facing out: 24 rings of 48 quads
    /// between the poles, texture coordinates running once round and once from pole to pole.
    pub fn ball(radius: f32) -> Self {
        let (rings, segments) = (24, 48);
        let mut mesh = Self::default();
        for ring in 0..=rings {
            let theta = std::f32::consts::PI * ring as f32 / rings as f32;
            for segment in 0..=segments {
                let phi = std::f32::consts::TAU * segment as f32 / segments as f32;
                let normal = Vec3::new(
                    theta.sin() * phi.cos(),
                    theta.cos(),
                    theta.sin() * phi.sin(),
                );
                let uv = Vec2::new(segment as f32 / segments as f32, ring as f32 / rings as f32);
                mesh.vertices.push(Vertex::new(normal * radius, normal, uv));
            }
        }
        let at = |ring: u32, segment: u32| ring * (segments + 1) + segment;
        for ring in 0..rings {
            for segment in 0..segments {
                let [a, b] = [at(ring, segment), at(ring + 1, segment)];
                let [c, d] = [at(ring + 1, segment + 1), at(ring, segment + 1)];
                mesh.indices.extend([a, c, b, a, d, c]);
            }
        }
        mesh
    }

    /// The mesh turned inside out: every triangle's winding reversed and every normal turned round,
    /// so that what faced out faces in (the inner wall of a hollow solid).
    pub fn inside_out(mut self) -> Self {
        for triangle in self.indices.chunks_exact_mut(3) {
            triangle.swap(1, 2);
        }
        for vertex in &mut self.vertices {
            vertex.normal = (-Vec3::from(vertex.normal)).into();
        }
        self
    }

    /// The mesh moved by `offset`.
    pub fn translated(mut self, offset: Vec3) -> Self {
        for vertex in &mut self.vertices {
            vertex.position = (Vec3::from(vertex.position) + offset).into();
        }
        self
    }

    /// Adds another mesh's triangles to this one.
    pub fn append(&mut self, other: MeshData) {
        let base = self.vertices.len() as u32;
        self.vertices.extend(other.vertices);
        self.indices.extend(other.indices.iter().map(|i| i + base));
    }

    pub fn triangle_count(&self) -> usize {
        self.indices.len() / 3
    }

    /// For each triangle, the triangle across each of its edges (a → b, b → c, c → a): the one that
    /// runs along the same edge the other way, b → a, as the neighbour in a closed mesh turned one
    /// way does; `None` across an edge of a hole. Vertices at the same place (to 0.01 mm) count as
    /// one: a mesh splits them where its normals or texture coordinates do.
    pub fn neighbours(&self) -> Vec<[Option<u32>; 3]> {
        // Each vertex named by the first at its place.
        let key = |v: &Vertex| Vec3::from(v.position) * 1e5;
        let keys: Vec<[i64; 3]> = (self.vertices.iter())
            .map(|v| key(v).round().as_i64vec3().to_array())
            .collect();
        let mut order: Vec<u32> = (0..keys.len() as u32).collect();
        order.sort_unstable_by_key(|&i| keys[i as usize]);
        let mut welded: Vec<u32> = (0..keys.len() as u32).collect();
        for pair in order.windows(2) {
            if keys[pair[0] as usize] == keys[pair[1] as usize] {
                welded[pair[1] as usize] = welded[pair[0] as usize];
            }
        }
        // Every edge, filed under the vertex it starts from: the edges from v are
        // `from[start[v]..start[v + 1]]`, each as (the vertex it goes to, its triangle).
        let edge = |t: usize, k: usize| {
            let index = |k: usize| welded[self.indices[3 * t + k % 3] as usize] as usize;
            (index(k), index(k + 1))
        };
        let triangles = self.triangle_count();
        let mut start = vec![0usize; keys.len() + 1];
        for t in 0..triangles {
            for k in 0..3 {
                start[edge(t, k).0 + 1] += 1;
            }
        }
        for v in 0..keys.len() {
            start[v + 1] += start[v];
        }
        let mut filled = start.clone();
        let mut from = vec![(0usize, 0u32); 3 * triangles];
        for t in 0..triangles {
            for k in 0..3 {
                let (a, b) = edge(t, k);
                from[filled[a]] = (b, t as u32);
                filled[a] += 1;
            }
        }
        // Across the edge a → b: the triangle with an edge from b back to a.
        let mut neighbours = vec![[None; 3]; triangles];
        for (t, across) in neighbours.iter_mut().enumerate() {
            for (k, neighbour) in across.iter_mut().enumerate() {
                let (a, b) = edge(t, k);
                let back = from[start[b]..start[b + 1]].iter();
                *neighbour = back
                    .filter(|&&(to, other)| to == a && other != t as u32)
                    .map(|&(_, other)| other)
                    .next();
            }
        }
        neighbours
    }
}

/// `v` scaled to unit length, if it has a direction: divided by its largest component first, so that
/// the squares of huge components do not overflow nor those of tiny ones lose their precision.
fn unit_length(v: Vec3) -> Option<Vec3> {
    (v / v.abs().max_element()).try_normalize()
}

/// What tobj does not check in the faces: the first face (its line, counted from 1) that names a
/// texture coordinate or a normal before the first one or past 2³², if any — `tobj` turns such an
/// index into a huge `usize` and multiplies it unchecked, which panics in a debug build (an
/// optimised build refuses the face as out of bounds): `f 1/-2/1 ...` with fewer than two `vt`
/// lines before it, for example — and more than [`MAX_TRIANGLES`] triangles in all.
///
/// It reads bytes, not characters, for speed in a debug build, where it read by `str::lines` and
/// `split_whitespace` took most of the skull's load (47 of 54-76 ms, the fastest of five loads;
/// the grid of [`MAX_MEMORY_MULTIPLE`], 2.4 of 4.1-4.6 s); by bytes, 6-7 ms, and the loads take
/// 27-39 ms and 2.2-2.5 s (three runs in turns on a busy machine). Only a line of ASCII is split here, on the ASCII whitespace that
/// `split_whitespace` knows; any other line is read as tobj reads it, by `split_whitespace`.
fn check_faces(text: &str) -> Result<(), FaceProblem> {
    let mut seen = Seen::default();
    for (number, line) in text.as_bytes().split(|&byte| byte == b'\n').enumerate() {
        let checked = if line.is_ascii() {
            seen.line(
                line.split(|&byte| is_space(byte))
                    .filter(|word| !word.is_empty()),
            )
        } else {
            // Cut at a newline, the line is UTF-8 as the whole text is.
            let line = std::str::from_utf8(line).unwrap_or_default();
            seen.line(line.split_whitespace().map(str::as_bytes))
        };
        if checked.is_err() {
            return Err(FaceProblem::PastTheEnd(number + 1));
        }
        if seen.triangles > MAX_TRIANGLES {
            return Err(FaceProblem::TooMany);
        }
    }
    Ok(())
}

/// The ASCII characters that `split_whitespace` (and so tobj) takes for whitespace.
fn is_space(byte: u8) -> bool {
    matches!(byte, b' ' | b'\t' | b'\n' | 0x0b | 0x0c | b'\r')
}

/// What [`check_faces`] has seen so far.
#[derive(Default)]
struct Seen {
    texcoords: i64,
    normals: i64,
    triangles: usize,
}

impl Seen {
    /// Counts one line, given as its words; `Err` for a face that names a texture coordinate or
    /// normal that is not there.
    fn line<'a>(&mut self, mut words: impl Iterator<Item = &'a [u8]>) -> Result<(), ()> {
        let face = match words.next() {
            Some(b"vt") => {
                self.texcoords += 1;
                return Ok(());
            }
            Some(b"vn") => {
                self.normals += 1;
                return Ok(());
            }
            // tobj reads `l` lines as it reads faces.
            Some(b"f") => true,
            Some(b"l") => false,
            _ => return Ok(()),
        };
        let mut corners = 0usize;
        for corner in words {
            corners += 1;
            // v/vt/vn: tobj guards the vertex index itself, and refuses what does not parse.
            let parts = corner.split(|&byte| byte == b'/').skip(1);
            for (part, count) in parts.zip([self.texcoords, self.normals]) {
                let Some(index) = parse_i64(part) else {
                    continue;
                };
                if index < -count || index > i64::from(u32::MAX) {
                    return Err(());
                }
            }
        }
        // A polygon of n corners is n - 2 triangles.
        if face {
            self.triangles += corners.saturating_sub(2);
        }
        Ok(())
    }
}

/// `i64::from_str` on bytes: an optional sign, then digits, and `None` on overflow.
fn parse_i64(text: &[u8]) -> Option<i64> {
    let (negative, digits) = match text {
        [b'-', rest @ ..] => (true, rest),
        [b'+', rest @ ..] => (false, rest),
        _ => (false, text),
    };
    if digits.is_empty() {
        return None;
    }
    let mut value = 0i64;
    for &digit in digits {
        if !digit.is_ascii_digit() {
            return None;
        }
        let digit = i64::from(digit - b'0');
        value = value.checked_mul(10)?;
        value = if negative {
            value.checked_sub(digit)?
        } else {
            value.checked_add(digit)?
        };
    }
    Some(value)
}

/// What [`check_faces`] found wrong.
#[derive(Debug, PartialEq)]
enum FaceProblem {
    /// The face on this line names a texture coordinate or normal that is not there.
    PastTheEnd(usize),
    /// More than [`MAX_TRIANGLES`] triangles.
    TooMany,
}

/// tobj's models of an OBJ file's text, after the checks tobj does not make.
fn read_models(name: &str, bytes: &[u8]) -> Result<Vec<tobj::Model>> {
    let shown = name;
    let Ok(text) = std::str::from_utf8(bytes) else {
        bail!("model `{shown}` is not an OBJ file: OBJ is text, this file is binary");
    };
    match check_faces(text) {
        Ok(()) => {}
        Err(FaceProblem::PastTheEnd(line)) => bail!(
            "model `{shown}` is not a valid OBJ file: the face on line {line} names a texture \
             coordinate or normal that is not there"
        ),
        Err(FaceProblem::TooMany) => bail!(
            "model `{shown}` has more than {MAX_TRIANGLES} triangles, the most a model may have"
        ),
    }
    let mut reader = std::io::BufReader::new(bytes);
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: true,
        ignore_points: true,
        ignore_lines: true,
    };
    // Materials are not used: every model is drawn with the skull's material.
    let (models, _) = tobj::load_obj_buf(&mut reader, &options, |_| {
        Ok((Vec::new(), Default::default()))
    })
    .map_err(|error| anyhow::anyhow!("model `{shown}` is not a valid OBJ file: {error}"))?;
    Ok(models)
}

/// A mesh in GPU buffers.
pub struct GpuMesh {
    pub vertices: wgpu::Buffer,
    pub indices: wgpu::Buffer,
    pub index_count: u32,
}

impl GpuMesh {
    pub fn new(device: &wgpu::Device, name: &str, data: &MeshData) -> Self {
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(&format!("{name} vertices")),
            contents: bytemuck::cast_slice(&data.vertices),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some(&format!("{name} indices")),
            contents: bytemuck::cast_slice(&data.indices),
            usage: wgpu::BufferUsages::INDEX,
        });
        Self {
            vertices,
            indices,
            index_count: data.indices.len() as u32,
        }
    }

    pub fn draw(&self, pass: &mut Pass<'_, '_>) {
        pass.set_vertex_buffer(0, self.vertices.slice(..));
        pass.set_index_buffer(self.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed(0..self.index_count, 0, 0..1);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cuboid_faces_point_outwards() {
        let mesh = MeshData::cuboid(Vec3::new(1.0, 2.0, 3.0));
        for triangle in mesh.indices.chunks_exact(3) {
            let [a, b, c] =
                [0, 1, 2].map(|k| Vec3::from(mesh.vertices[triangle[k] as usize].position));
            let winding_normal = (b - a).cross(c - a);
            let centre = (a + b + c) / 3.0;
            assert!(winding_normal.dot(centre) > 0.0, "a face points inwards");
            assert!(winding_normal.dot(mesh.vertices[triangle[0] as usize].normal.into()) > 0.0);
        }
    }

    /// The ball's triangles (but the poles' slivers, which have no area) face out, and with its
    /// normals; turned inside out, every one faces in.
    #[test]
    fn the_ball_faces_out_and_inside_out_faces_in() {
        for (mesh, out) in [
            (MeshData::ball(2.0), 1.0),
            (MeshData::ball(2.0).inside_out(), -1.0),
        ] {
            let mut faces = 0;
            for triangle in mesh.indices.chunks_exact(3) {
                let vertex = |k: usize| &mesh.vertices[triangle[k] as usize];
                let [a, b, c] = [0, 1, 2].map(|k| Vec3::from(vertex(k).position));
                let winding_normal = (b - a).cross(c - a);
                if winding_normal.length() < 1e-6 {
                    continue;
                }
                faces += 1;
                assert!(
                    out * winding_normal.dot(a + b + c) > 0.0,
                    "a face turned the wrong way"
                );
                assert!(
                    winding_normal.dot(vertex(0).normal.into()) > 0.0,
                    "a normal against its face"
                );
            }
            assert_eq!(
                faces,
                48 * 22 * 2 + 48 * 2,
                "every face but the poles' slivers"
            );
        }
    }

    #[test]
    fn an_obj_without_normals_gets_outward_normals_and_is_placed() {
        // A tetrahedron far from the origin, 10 units across, faces counter-clockwise from outside.
        let obj = "v 100 100 100\nv 110 100 100\nv 100 110 100\nv 100 100 110\n\
                   f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
        let path = std::env::temp_dir().join(format!("tetra-{}.obj", std::process::id()));
        std::fs::write(&path, obj).unwrap();
        let mesh = MeshData::load_obj(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(mesh.triangle_count(), 4);
        let (min, max) = mesh.bounds();
        assert!(
            ((max - min).max_element() - 1.0).abs() < 1e-6,
            "scaled to a unit box"
        );
        assert!((min + max).length() < 1e-5, "centred on the origin");
        let centre = mesh
            .vertices
            .iter()
            .map(|v| Vec3::from(v.position))
            .sum::<Vec3>()
            / 4.0;
        for vertex in &mesh.vertices {
            let normal = Vec3::from(vertex.normal);
            assert!((normal.length() - 1.0).abs() < 1e-5);
            assert!(
                normal.dot(Vec3::from(vertex.position) - centre) > 0.0,
                "normal points out"
            );
        }
    }

    #[test]
    fn fit_centres_and_scales() {
        let mut mesh = MeshData::cuboid(Vec3::new(10.0, 20.0, 40.0));
        for v in &mut mesh.vertices {
            v.position = (Vec3::from(v.position) + Vec3::new(100.0, -50.0, 7.0)).into();
        }
        mesh.fit_unit_box().unwrap();
        let (min, max) = mesh.bounds();
        assert!((min + max).length() < 1e-5);
        assert!(((max - min).max_element() - 1.0).abs() < 1e-6);
    }

    /// [`check_faces`] as it was written before it read bytes: by characters, as tobj reads.
    fn check_faces_by_characters(text: &str) -> Result<(), FaceProblem> {
        let (mut texcoords, mut normals) = (0i64, 0i64);
        let mut triangles = 0usize;
        for (number, line) in text.lines().enumerate() {
            let mut words = line.split_whitespace();
            match words.next() {
                Some("vt") => texcoords += 1,
                Some("vn") => normals += 1,
                Some(kind @ ("f" | "l")) => {
                    let mut corners = 0usize;
                    for corner in words {
                        corners += 1;
                        for (part, count) in corner.split('/').skip(1).zip([texcoords, normals]) {
                            let Ok(index) = part.parse::<i64>() else {
                                continue;
                            };
                            if index < -count || index > i64::from(u32::MAX) {
                                return Err(FaceProblem::PastTheEnd(number + 1));
                            }
                        }
                    }
                    if kind == "f" {
                        triangles += corners.saturating_sub(2);
                        if triangles > MAX_TRIANGLES {
                            return Err(FaceProblem::TooMany);
                        }
                    }
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// What [`faces_are_checked_by_bytes_as_by_characters`] makes its lines of.
    #[rustfmt::skip]
    const PIECES: [&str; 37] = [
        "v", "vt", "vn", "f", "l", "vp", "fo", " ", "  ", "\t", "\r", "\x0b", "\x0c", "\x1c", "\u{a0}",
        "\u{2003}", "\u{85}", "é", "1", "-1", "-2", "+1", "-", "+", "/", "//", "1/-3/1", "1//-2",
        "4294967296", "-9223372036854775808", "99999999999999999999", "0", "\n", "\n", "\n", "\r\n",
        "#",
    ];

    /// Reading bytes finds what reading characters finds, on random lines made of the pieces that
    /// could tell them apart: whitespace that is not ASCII's, vertical tabs, CR LF, signs, indices
    /// past the ends and past 2⁶³.
    #[test]
    fn faces_are_checked_by_bytes_as_by_characters() {
        for c in 0..128u8 {
            assert_eq!(is_space(c), char::from(c).is_whitespace(), "byte {c}");
        }
        let mut state = 0x2545_f491_4f6c_dd1d_u64;
        let mut random = |n: usize| {
            // xorshift64: the same cases every run.
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state % n as u64) as usize
        };
        let mut refused = 0;
        for _ in 0..20_000 {
            let text: String = (0..1 + random(40))
                .map(|_| PIECES[random(PIECES.len())])
                .collect();
            let expected = check_faces_by_characters(&text);
            refused += usize::from(expected.is_err());
            assert_eq!(check_faces(&text), expected, "{text:?}");
        }
        assert!(
            refused > 100,
            "only {refused} cases refused: the test tests little"
        );
        let at_the_limit = "f 1 2 3\n".repeat(MAX_TRIANGLES);
        assert_eq!(
            check_faces(&at_the_limit),
            Ok(()),
            "the limit itself is allowed"
        );
        assert_eq!(
            check_faces(&(at_the_limit + "f 1 2 3\n")),
            Err(FaceProblem::TooMany)
        );
    }

    #[test]
    fn indices_parse_as_i64_from_str_does() {
        for text in ["12", "+12", "-12", "0", "+0", "-9223372036854775808"] {
            assert_eq!(parse_i64(text.as_bytes()), text.parse().ok(), "{text}");
        }
        for text in ["", "+", "-", "1a", "9223372036854775808", "--1", "+-1"] {
            assert_eq!(parse_i64(text.as_bytes()), None, "{text}");
        }
        // A sign does not hide an index past 2³² from the check.
        assert_eq!(
            check_faces("vt 0 0\nf 1/+99999999999 2/1 3/1\n"),
            Err(FaceProblem::PastTheEnd(2))
        );
    }
}
