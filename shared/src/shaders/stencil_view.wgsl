// view=stencil: the stencil buffer in false colour, without copying it (the GL backend cannot).
//
// Pass 1 rebuilds each pixel's stencil value in an R8Unorm texture, one bit at a time: draw i uses
// read mask 1 << i, reference 1 << i and compare Equal, so it passes exactly where bit i of the
// stored value is set, and adds 2^i / 255 there (additive blending). After 8 draws the texture
// holds value / 255. Pass 2 looks each value up in the palette.

struct Palette {
    colours: array<vec4<f32>, 256>,
};

struct Bit {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) bit: u32,
};

@vertex
fn vs_bit(@builtin(vertex_index) index: u32, @builtin(instance_index) bit: u32) -> Bit {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    var out: Bit;
    out.position = vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
    out.bit = bit;
    return out;
}

@fragment
fn fs_bit(in: Bit) -> @location(0) vec4<f32> {
    return vec4<f32>(f32(1u << in.bit) / 255.0, 0.0, 0.0, 0.0);
}

@group(0) @binding(0) var values: texture_2d<f32>;
@group(0) @binding(1) var<uniform> palette: Palette;

@vertex
fn vs_fullscreen(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}

@fragment
fn fs_palette(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let value = textureLoad(values, vec2<i32>(position.xy), 0).r;
    return palette.colours[u32(round(value * 255.0))];
}
