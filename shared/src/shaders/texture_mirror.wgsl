// Appended to scene.wgsl: a mirror's surface that shows a reflection rendered into a texture
// (Rastertek's tutorial 27), found with projective texture coordinates.

struct Reflection {
    // The reflected camera that drew the texture: world to its clip space.
    view_projection: mat4x4<f32>,
    // x: how much of the reflection is mixed over the surface (Rastertek's 0.15).
    blend: vec4<f32>,
};

@group(2) @binding(0) var reflection_texture: texture_2d<f32>;
@group(2) @binding(1) var reflection_sampler: sampler;
@group(2) @binding(2) var<uniform> reflection: Reflection;

// ANCHOR: projective
@fragment
fn fs_texture_mirror(in: VertexOut) -> @location(0) vec4<f32> {
    // Where this point of the mirror landed in the texture: project it with the camera that drew
    // the texture, then go from clip space (x, y in -1..1, y up) to texture space (0..1, v down).
    let clip = reflection.view_projection * vec4<f32>(in.world_position, 1.0);
    let ndc = clip.xy / clip.w;
    let uv = vec2<f32>(ndc.x * 0.5 + 0.5, 0.5 - ndc.y * 0.5);
    let reflected = textureSample(reflection_texture, reflection_sampler, uv).rgb;
    let surface = shade(in).rgb;
    return vec4<f32>(mix(surface, reflected, reflection.blend.x), 1.0);
}
// ANCHOR_END: projective
