// RESET_DEPTH: one triangle over the whole screen at the far plane (depth exactly 1) that writes no
// colour. Drawn with the stencil test, it puts the depth of the marked pixels back to the far plane.
// RESET_TO_THE_SKY writes the sky's colour too (SKY, linear, is appended by the code that loads this).

@vertex
fn vs_far_plane(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 1.0, 1.0);
}

@fragment
fn fs_no_colour() -> @location(0) vec4<f32> {
    return vec4<f32>(0.0);
}

@fragment
fn fs_sky() -> @location(0) vec4<f32> {
    return SKY;
}
