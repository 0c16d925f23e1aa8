// --show depth and --show raw-depth: the depth buffer drawn as grey levels, either linearised back to
// distances (black at the near plane, white at the far plane) or as the raw values wgpu stores.

struct Planes {
    near: f32,
    far: f32,
};

@group(0) @binding(0) var depth_buffer: texture_depth_2d;
@group(0) @binding(1) var<uniform> planes: Planes;

// ANCHOR: linearise
// wgpu's projection maps view distance z in [near, far] to depth d = far (z - near) / (z (far - near)),
// so z = near far / (far - d (far - near)). No `* 2 - 1` step: wgpu's depth range is 0..1, not GL's -1..1.
fn linearise(d: f32) -> f32 {
    let z = planes.near * planes.far / (planes.far - d * (planes.far - planes.near));
    return (z - planes.near) / (planes.far - planes.near);
}
// ANCHOR_END: linearise

@fragment
fn fs_depth(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let d = textureLoad(depth_buffer, vec2<i32>(position.xy), 0);
    return vec4<f32>(vec3<f32>(linearise(d)), 1.0);
}

@fragment
fn fs_raw_depth(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let d = textureLoad(depth_buffer, vec2<i32>(position.xy), 0);
    return vec4<f32>(vec3<f32>(d), 1.0);
}

// Depth readback for tests: the depth buffer copied into an R32Float colour target.
@fragment
fn fs_copy_depth(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return vec4<f32>(textureLoad(depth_buffer, vec2<i32>(position.xy), 0), 0.0, 0.0, 1.0);
}
