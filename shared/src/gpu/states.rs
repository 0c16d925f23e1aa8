//! Named render-state recipes, as Luna names his `RenderStates`.
//!
//! In D3D11 the depth-stencil, blend and rasterizer states are separate objects bound before a draw;
//! in wgpu they are baked into a `RenderPipeline`. So each named state combination of the book is a
//! [`Recipe`] here, and [`crate::room::scene::Scene::pipeline`] bakes it, labelled with its name. Lessons build
//! on these with struct update syntax (`Recipe { depth_compare, ..OPAQUE }`), so a recipe lives once.

use wgpu::{
    BlendComponent, BlendFactor, BlendOperation, BlendState, ColorWrites, CompareFunction, Face,
    FrontFace, StencilFaceState, StencilOperation, StencilState,
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
    /// Whether, and how, fragments behind the frame's clip plane are thrown away (lesson 8).
    pub clip: Clip,
    /// Added to each fragment's depth before the test: a constant (in the depth format's smallest
    /// steps) and a multiple of the triangle's depth slope (lesson 10's shadow on the floor).
    pub depth_bias: wgpu::DepthBiasState,
}
// ANCHOR_END: recipe

// ANCHOR: clip
/// How a recipe keeps only what lies in front of the frame's clip plane (a mirror's plane, for
/// what is reflected in it). The third way, an oblique near plane, is not a pipeline state: it is in
/// the projection matrix (`math::clip::oblique_projection`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Clip {
    /// Nothing is clipped.
    None,
    /// The vertex shader writes the signed distance to the plane as a user clip distance, and the
    /// rasterizer cuts each triangle where it crosses 0 (`Features::CLIP_DISTANCES`).
    Distances,
    /// The fragment shader discards fragments behind the plane.
    Discard,
}
// ANCHOR_END: clip

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
    clip: Clip::None,
    depth_bias: wgpu::DepthBiasState {
        constant: 0,
        slope_scale: 0.0,
        clamp: 0.0,
    },
};
// ANCHOR_END: opaque

// ANCHOR: mark_mirror
/// Writes 1 into the stencil buffer wherever the mirror is visible — and nothing else: no colour, no
/// depth. The depth test stays on, so a pixel where something nearer (the crate) was drawn first is
/// not marked. (Luna: `MarkMirrorDSS` with `NoRenderTargetWritesBS`.) Set the reference to 1.
pub const MARK_MIRROR: Recipe = Recipe {
    name: "MARK_MIRROR",
    depth_write: false,
    depth_compare: CompareFunction::Less,
    stencil: StencilState {
        front: REPLACE_ALWAYS,
        back: REPLACE_ALWAYS,
        read_mask: 0xff,
        write_mask: 0xff,
    },
    color_writes: ColorWrites::empty(),
    ..OPAQUE
};

/// The stencil test always passes, and a fragment that also passes the depth test writes the reference.
const REPLACE_ALWAYS: StencilFaceState = StencilFaceState {
    compare: CompareFunction::Always,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Keep,
    pass_op: StencilOperation::Replace,
};
// ANCHOR_END: mark_mirror

// ANCHOR: mark_shape
/// Writes the reference into the stencil buffer wherever the shape covers, whatever is there, and
/// nothing else: no colour, no depth.
pub const MARK_SHAPE: Recipe = Recipe {
    name: "MARK_SHAPE",
    depth_compare: CompareFunction::Always,
    ..MARK_MIRROR
};
// ANCHOR_END: mark_shape

// ANCHOR: draw_reflection
/// Draws the mirror image only where the stencil holds the reference (1: the marked mirror), with
/// the usual depth test, leaving the stencil as it is. (Luna: `DrawReflectionDSS`.)
pub const DRAW_REFLECTION: Recipe = Recipe {
    name: "DRAW_REFLECTION",
    stencil: StencilState {
        front: KEEP_IF_EQUAL,
        back: KEEP_IF_EQUAL,
        read_mask: 0xff,
        write_mask: 0xff,
    },
    ..OPAQUE
};

/// The stencil test passes where the stored value equals the reference; nothing is written.
pub const KEEP_IF_EQUAL: StencilFaceState = StencilFaceState {
    compare: CompareFunction::Equal,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Keep,
    pass_op: StencilOperation::Keep,
};
// ANCHOR_END: draw_reflection

// ANCHOR: front_clockwise
/// DRAW_REFLECTION for mirror images: a reflection (determinant −1) turns counter-clockwise
/// triangles clockwise on screen, so the triangles that face the camera are now the clockwise ones.
/// Clockwise is the front, and the back faces, now the counter-clockwise ones, are culled.
/// (Luna: `DrawReflectionDSS` with `CullClockwiseRS`, which tells D3D counter-clockwise is front:
/// D3D's default front is clockwise, so there the same flip culls the clockwise triangles.)
pub const FRONT_CLOCKWISE: Recipe = Recipe {
    name: "FRONT_CLOCKWISE",
    front_face: FrontFace::Cw,
    ..DRAW_REFLECTION
};
// ANCHOR_END: front_clockwise

// ANCHOR: transparent
/// See-through surfaces: the usual depth test, and the colour mixed with what is already there,
/// C = a·Csrc + (1 − a)·Cdst, a the fragment's alpha. (Luna: `TransparentBS`.)
pub const TRANSPARENT: Recipe = Recipe {
    name: "TRANSPARENT",
    blend: Some(BlendState::ALPHA_BLENDING),
    ..OPAQUE
};
// ANCHOR_END: transparent

// ANCHOR: transparent_no_cull
/// TRANSPARENT seen from both sides, for the wire-fence crate (whose far side shows through its
/// holes) and the water. (Luna and MKXJun: `NoCullRS` with `TransparentBS`.)
pub const TRANSPARENT_NO_CULL: Recipe = Recipe {
    name: "TRANSPARENT_NO_CULL",
    cull_mode: None,
    ..TRANSPARENT
};

/// The mirror images of see-through objects: TRANSPARENT_NO_CULL where the stencil holds the
/// reference. (Both sides are drawn, so the flipped winding does not matter.)
pub const REFLECTED_TRANSPARENT: Recipe = Recipe {
    name: "REFLECTED_TRANSPARENT",
    stencil: DRAW_REFLECTION.stencil,
    ..TRANSPARENT_NO_CULL
};
// ANCHOR_END: transparent_no_cull

// ANCHOR: blend_over_mark
/// A mirror's own surface (glass, polished stone) blended over its reflection, only where the mark
/// holds the reference, whatever depth the reflection left there: the mark already knows what stands
/// in front of the mirror, and a reflection drawn with an oblique projection leaves depths the
/// normal projection cannot be compared with. It writes the surface's depth for what comes after.
pub const BLEND_OVER_MARK: Recipe = Recipe {
    name: "BLEND_OVER_MARK",
    depth_compare: CompareFunction::Always,
    stencil: DRAW_REFLECTION.stencil,
    ..TRANSPARENT
};
// ANCHOR_END: blend_over_mark

// ANCHOR: reset_depth
/// Puts the depth of the marked pixels back to the far plane (Kilgard's step between the mark and the
/// reflection): whatever the room drew *behind* the mirror — an object sunk through the floor — must
/// not hide the mirror world. Drawn as one far-plane triangle over the screen (not with the scene's
/// shader: see `lesson::mirror::ResetDepth`), depth test `Always`, where the stencil holds the
/// reference, no colour.
pub const RESET_DEPTH: Recipe = Recipe {
    name: "RESET_DEPTH",
    depth_compare: CompareFunction::Always,
    stencil: DRAW_REFLECTION.stencil,
    cull_mode: None,
    color_writes: ColorWrites::empty(),
    ..OPAQUE
};

/// RESET_DEPTH, writing the sky's colour as well: behind an opening, the room beyond is seen
/// against its own sky.
pub const RESET_TO_THE_SKY: Recipe = Recipe {
    name: "RESET_TO_THE_SKY",
    color_writes: ColorWrites::ALL,
    ..RESET_DEPTH
};
// ANCHOR_END: reset_depth

// ANCHOR: shadow
/// A planar shadow: the object flattened onto a plane by the shadow matrix, black at 50%, blended
/// over what is there; no depth writes, both sides drawn. Every layer of the flattened object
/// darkens again where layers overlap.
pub const SHADOW: Recipe = Recipe {
    name: "SHADOW",
    depth_write: false,
    cull_mode: None,
    ..TRANSPARENT
};

/// SHADOW blended once per pixel (MKXJun's `DSSNoDoubleBlend`): the stencil test passes where the
/// value equals the reference, 0, and increments it, so the next layer at that pixel fails.
pub const NO_DOUBLE_BLEND: Recipe = Recipe {
    name: "NO_DOUBLE_BLEND",
    stencil: StencilState {
        front: INCREMENT_IF_EQUAL,
        back: INCREMENT_IF_EQUAL,
        read_mask: 0xff,
        write_mask: 0xff,
    },
    ..SHADOW
};

/// The stencil test passes where the value equals the reference, and increments it there.
const INCREMENT_IF_EQUAL: StencilFaceState = StencilFaceState {
    compare: CompareFunction::Equal,
    fail_op: StencilOperation::Keep,
    depth_fail_op: StencilOperation::Keep,
    pass_op: StencilOperation::IncrementClamp,
};
// ANCHOR_END: shadow

// ANCHOR: masks
/// The shadow seen in the mirror: the stencil holds two things at once, the mirror's mark in bit 0
/// and "shadow drawn here" in bit 1. Reference 1 and read mask 0b11: pass where the mark is set and
/// the shadow bit is not; increment (1 + 1 = 2) through write mask 0b10: set the shadow bit, leave
/// the mark.
pub const REFLECTED_NO_DOUBLE_BLEND: Recipe = Recipe {
    name: "REFLECTED_NO_DOUBLE_BLEND",
    stencil: StencilState {
        front: INCREMENT_IF_EQUAL,
        back: INCREMENT_IF_EQUAL,
        read_mask: 0b11,
        write_mask: 0b10,
    },
    ..SHADOW
};

/// BLEND_OVER_MARK reading the mark's bit only (read mask 0b01): a pixel of the mirror where a
/// shadow also set bit 1 holds 3, which is still "marked".
pub const BLEND_OVER_MARK_BIT: Recipe = Recipe {
    name: "BLEND_OVER_MARK_BIT",
    stencil: StencilState {
        read_mask: 0b01,
        ..DRAW_REFLECTION.stencil
    },
    ..BLEND_OVER_MARK
};
// ANCHOR_END: masks

// ANCHOR: spe_reflection
/// SPE's first floor mirror (OpenGL): the reflection drawn with no stencil, the depth test off, and
/// mixed at a constant 40% over what is there — `glBlendColor(0, 0, 0, 0.4)` with
/// `GL_CONSTANT_ALPHA`; in wgpu `BlendFactor::Constant` and `set_blend_constant`.
pub const SPE_REFLECTION: Recipe = Recipe {
    name: "SPE_REFLECTION",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    stencil: NO_STENCIL,
    blend: Some(BlendState {
        color: BlendComponent {
            src_factor: BlendFactor::Constant,
            dst_factor: BlendFactor::OneMinusConstant,
            operation: BlendOperation::Add,
        },
        alpha: BlendComponent::OVER,
    }),
    ..FRONT_CLOCKWISE
};
// ANCHOR_END: spe_reflection

// ANCHOR: always_reflection
/// A blog's wall mirror: the reflection where the stencil holds the reference, with the depth test
/// `Always` and no depth writes, so the mirror images cover each other in the order they are drawn.
pub const ALWAYS_REFLECTION: Recipe = Recipe {
    name: "ALWAYS_REFLECTION",
    depth_write: false,
    depth_compare: CompareFunction::Always,
    ..FRONT_CLOCKWISE
};
// ANCHOR_END: always_reflection

impl Recipe {
    /// The `DepthStencilState` of this recipe for the workbook's depth-stencil format.
    pub fn depth_stencil(&self) -> wgpu::DepthStencilState {
        wgpu::DepthStencilState {
            format: DEPTH_STENCIL_FORMAT,
            depth_write_enabled: Some(self.depth_write),
            depth_compare: Some(self.depth_compare),
            stencil: self.stencil.clone(),
            bias: self.depth_bias,
        }
    }
}

/// A comparison function by the name the knobs use (see [`crate::lesson::knobs::COMPARE_VALUES`]).
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
    use crate::lesson::knobs::COMPARE_VALUES;

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
