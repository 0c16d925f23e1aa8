//! Procedural assets for the mirror/stencil workbook.
//!
//! Everything in `assets/` is generated here, deterministically (no clock, no
//! OS randomness, only fixed-seed hashes), so the files can be regenerated
//! and compared byte for byte:
//!
//! * `skull.obj`: a skull modelled as a signed-distance function
//!   ([`skull`], built from the primitives in [`sdf`]), meshed with marching
//!   tetrahedra ([`mesher`]), Taubin-smoothed and snapped back onto the
//!   surface ([`smooth`]), decimated to its triangle budget ([`decimate`])
//!   and written as OBJ ([`obj`]).
//! * six RGBA8 PNG textures ([`textures`]).

pub mod decimate;
pub mod mesher;
pub mod obj;
pub mod sdf;
pub mod skull;
pub mod smooth;
pub mod textures;

use std::path::Path;

use anyhow::Context;
use glam::{UVec3, Vec3};

use mesher::{Grid, Mesh};

/// Every generated file, in the order [`generate_all`] returns them.
pub const FILES: &[&str] = &[
    "skull.obj",
    "checker.png",
    "bricks.png",
    "ice.png",
    "wirefence.png",
    "crate.png",
    "water.png",
];

/// Grid step of the skull mesher, in skull units (the skull is ~2 tall).
const STEP: f32 = 0.02;
/// Triangle budget of the final skull mesh.
const SKULL_TRIANGLES: usize = 28_000;

/// Builds the final skull mesh and its vertex normals: mesh the distance
/// field finely, smooth, decimate to the triangle budget, smooth again and
/// pull the vertices back onto the surface.
pub fn skull_mesh() -> (Mesh, Vec<Vec3>) {
    let skull = skull::Skull::new();
    let f = |p: Vec3| skull.distance(p);
    let min = Vec3::new(-0.84, -1.14, -1.04);
    let max = Vec3::new(0.84, 1.1, 1.0);
    let grid = Grid {
        min,
        step: STEP,
        cells: ((max - min) / STEP).ceil().as_uvec3().max(UVec3::ONE),
    };
    let mut mesh = mesher::marching_tetrahedra(&f, &grid);
    smooth::remove_small_pieces(&mut mesh, 500);
    smooth::taubin(&mut mesh, 4);
    let mut mesh = decimate::decimate(&mesh, SKULL_TRIANGLES);
    smooth::taubin(&mut mesh, 3);
    smooth::project(&mut mesh, &f, 0.5 * STEP);
    // Broaden the skull a little toward the requested proportions.
    for p in &mut mesh.positions {
        *p *= skull::PROPORTIONS;
    }
    let normals = smooth::vertex_normals(&mesh);
    (mesh, normals)
}

/// Generates every asset: `(file name, exact file bytes)`, in [`FILES`] order.
pub fn generate_all() -> anyhow::Result<Vec<(&'static str, Vec<u8>)>> {
    let (mesh, normals) = skull_mesh();
    let mut files = vec![(FILES[0], obj::write_obj(&mesh, &normals).into_bytes())];
    for (name, image) in textures::all() {
        files.push((
            name,
            textures::encode_png(&image).with_context(|| format!("encoding {name}"))?,
        ));
    }
    debug_assert_eq!(files.iter().map(|f| f.0).collect::<Vec<_>>(), FILES);
    Ok(files)
}

/// Generates every asset and writes it into `dir`.
pub fn write_all(dir: &Path) -> anyhow::Result<()> {
    for (name, bytes) in generate_all()? {
        let path = dir.join(name);
        std::fs::write(&path, bytes).with_context(|| format!("writing {}", path.display()))?;
    }
    Ok(())
}
