//! The room of Luna's Mirror demo: the scene on the GPU (floor, wall, mirror, crate, skull, lights),
//! its meshes and textures, the orbit camera, mirror worlds in planes other than the wall mirror's,
//! and the screen shapes of lesson 2.

pub mod assets;
pub mod camera;
pub mod mesh;
pub mod mirror_world;
pub mod scene;
pub mod shapes;
pub mod texture;
pub mod texture_mirror;
