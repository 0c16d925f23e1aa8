//! Named render-state recipes, as Luna names his `RenderStates`.
//!
//! In D3D11 the depth-stencil, blend and rasterizer states are separate objects bound before a draw;
//! in wgpu they are baked into a `RenderPipeline`. So each named state combination of the book is a
//! [`Recipe`] here, and [`crate::scene::Scene::pipeline`] bakes it, labelled with its name. Lessons build
//! on these with struct update syntax (`Recipe { depth_compare, ..OPAQUE }`), so a recipe lives once.

use wgpu::{
    BlendState, ColorWrites, CompareFunction, Face, FrontFace, StencilFaceState, StencilState,
};

use crate::gpu::DEPTH_STENCIL_FORMAT;

// ANCHOR: recipe
/// One combination of depth-stencil, blend and rasterizer state: one pipeline.
#[derive(Debug, Clone)]
pub struct Recipe {
    /// The name the book uses; also the pipeline's label.
    pub name: &'static str,
    /// Does a fragment that passes write its depth?
    pub depth_write: bool,
    /// Keep the fragment when `its depth CMP stored depth`.
    pub depth_compare: CompareFunction,
    pub stencil: StencilState,
    /// Which triangles to throw away: those facing away (`Back`), towards (`Front`), or none.
    pub cull_mode: Option<Face>,
    /// Which winding on screen counts as facing the camera. wgpu's default is `Ccw`, D3D's is clockwise.
    pub front_face: FrontFace,
    /// How the fragment's colour mixes with the target's; `None` replaces it.
    pub blend: Option<BlendState>,
    /// Which colour channels are written at all.
    pub color_writes: ColorWrites,
}
// ANCHOR_END: recipe

/// A stencil state that neither tests nor writes: every fragment passes, the buffer is untouched.
pub const NO_STENCIL: StencilState = StencilState {
    front: StencilFaceState::IGNORE,
    back: StencilFaceState::IGNORE,
    read_mask: 0,
    write_mask: 0,
};

// ANCHOR: opaque
/// Solid objects, the usual way: depth test `Less`, depth write on, back faces culled, no blending.
/// (Luna draws these with the default states.)
pub const OPAQUE: Recipe = Recipe {
    name: "OPAQUE",
    depth_write: true,
    depth_compare: CompareFunction::Less,
    stencil: NO_STENCIL,
    cull_mode: Some(Face::Back),
    front_face: FrontFace::Ccw,
    blend: None,
    color_writes: ColorWrites::ALL,
};
// ANCHOR_END: opaque

impl Recipe {
    /// The `DepthStencilState` of this recipe for the workbook's depth-stencil format.
    pub fn depth_stencil(&self) -> wgpu::DepthStencilState {
        wgpu::DepthStencilState {
            format: DEPTH_STENCIL_FORMAT,
            depth_write_enabled: Some(self.depth_write),
            depth_compare: Some(self.depth_compare),
            stencil: self.stencil.clone(),
            bias: wgpu::DepthBiasState::default(),
        }
    }
}

/// A comparison function by the name the knobs use (see [`crate::knobs::COMPARE_VALUES`]).
///
/// # Panics
/// On a name outside that list: knob values are checked before a lesson sees them.
pub fn compare_function(name: &str) -> CompareFunction {
    match name {
        "never" => CompareFunction::Never,
        "less" => CompareFunction::Less,
        "equal" => CompareFunction::Equal,
        "less-equal" => CompareFunction::LessEqual,
        "greater" => CompareFunction::Greater,
        "not-equal" => CompareFunction::NotEqual,
        "greater-equal" => CompareFunction::GreaterEqual,
        "always" => CompareFunction::Always,
        other => panic!("not a comparison function: {other}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::knobs::COMPARE_VALUES;

    #[test]
    fn every_compare_knob_value_names_a_distinct_function() {
        let functions: Vec<_> = COMPARE_VALUES.iter().map(|n| compare_function(n)).collect();
        for (i, a) in functions.iter().enumerate() {
            for b in &functions[i + 1..] {
                assert_ne!(a, b);
            }
        }
    }
}
