// SHOW_TEXTURE: a texture of another size drawn over the whole target, filtered (the window and the
// film show a step drawn into a lesson's own target, such as lesson 9's reflection texture).

@group(0) @binding(0) var source: texture_2d<f32>;
@group(0) @binding(1) var source_sampler: sampler;

struct Out {
    @builtin(position) position: vec4<f32>,
    @location(0) uv: vec2<f32>,
};

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> Out {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    var out: Out;
    out.position = vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
    out.uv = vec2<f32>(uv.x, 1.0 - uv.y);
    return out;
}

@fragment
fn fs_texture(in: Out) -> @location(0) vec4<f32> {
    return textureSample(source, source_sampler, in.uv);
}
