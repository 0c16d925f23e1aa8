//! What the room is made of besides code: the skull (or a model of the learner's) and six textures,
//! all made by `cargo assets`. The native runners read them from `assets/`; the web page fetches the
//! same files over HTTP, so both draw the room from the very same bytes.

#[cfg(not(target_arch = "wasm32"))]
use std::path::Path;

use anyhow::Result;

use crate::room::mesh::MeshData;
use crate::room::texture::{self, Mipmapped};

/// The skull's file in the assets folder.
pub const MODEL_FILE: &str = "skull.obj";

/// The textures' files, in the order of [`Assets::textures`]: the floor's checker, the wall's
/// bricks, the mirror's ice, the crate, the wire fence and the water.
pub const TEXTURE_FILES: [&str; 6] = [
    "checker.png",
    "bricks.png",
    "ice.png",
    "crate.png",
    "wirefence.png",
    "water.png",
];

/// The room's assets, decoded.
pub struct Assets {
    /// The skull, or the model `--model` names.
    pub model: std::sync::Arc<MeshData>,
    /// The textures of [`TEXTURE_FILES`], in that order, with their mipmaps.
    pub textures: [Mipmapped; 6],
}

impl Assets {
    /// Reads the assets from the folder `assets`, the model from `model` if given: the textures
    /// on a thread of their own, beside the model (each takes about as long).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn load(assets: &Path, model: Option<&Path>) -> Result<Self> {
        let model_path = model.map_or_else(|| assets.join(MODEL_FILE), Path::to_path_buf);
        let load_textures = || -> Result<Vec<Mipmapped>> {
            let load = |name| Ok(Mipmapped::new(texture::load_png(&assets.join(name))?));
            TEXTURE_FILES.iter().map(load).collect()
        };
        let (model, textures) = std::thread::scope(|scope| {
            let textures = std::thread::Builder::new()
                .name("textures".into())
                .spawn_scoped(scope, load_textures);
            let model = MeshData::load_obj(&model_path);
            let textures = match textures {
                Ok(thread) => thread
                    .join()
                    .unwrap_or_else(|p| std::panic::resume_unwind(p)),
                Err(_) => load_textures(),
            };
            (model, textures)
        });
        Ok(Self {
            model: std::sync::Arc::new(model?),
            textures: textures?.try_into().expect("one picture per texture file"),
        })
    }

    /// Decodes the assets from their files' bytes: the model's OBJ text (`model_name` names it in
    /// errors) and the textures' PNGs in the order of [`TEXTURE_FILES`].
    pub fn decode(model_name: &str, model: &[u8], textures: &[Vec<u8>; 6]) -> Result<Self> {
        let model = MeshData::parse_obj(model_name, model)?;
        let mut decoded = Vec::with_capacity(TEXTURE_FILES.len());
        for (name, bytes) in TEXTURE_FILES.iter().zip(textures) {
            decoded.push(Mipmapped::new(texture::decode_png(name, bytes)?));
        }
        Ok(Self {
            model: std::sync::Arc::new(model),
            textures: decoded.try_into().expect("one picture per texture file"),
        })
    }
}
