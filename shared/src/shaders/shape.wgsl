// Flat shapes for the stencil lesson: 2-D triangles given in screen units (y from -1 at the bottom
// to 1 at the top, x likewise but divided by the aspect ratio, so a circle stays round).

struct Frame {
    view_projection: mat4x4<f32>,
    // xyz: the eye; w: the target's aspect ratio (width / height).
    eye: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;

@vertex
fn vs_shape(@location(0) position: vec2<f32>) -> @builtin(position) vec4<f32> {
    return vec4<f32>(position.x / frame.eye.w, position.y, 0.0, 1.0);
}

@fragment
fn fs_shape() -> @location(0) vec4<f32> {
    return vec4<f32>(1.0);
}
