// view=stencil: the stencil buffer in false colour. One full-screen triangle per stencil value v,
// drawn with the stencil test `v == stored` (compare Equal, reference v): each pixel is painted by
// exactly the draw whose value it holds. No copy of the stencil buffer is needed, so this works on
// every backend.

struct Palette {
    colours: array<vec4<f32>, 256>,
};

@group(0) @binding(0) var<uniform> palette: Palette;

struct Out {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) value: u32,
};

@vertex
fn vs_value(@builtin(vertex_index) index: u32, @builtin(instance_index) value: u32) -> Out {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    var out: Out;
    out.position = vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
    out.value = value;
    return out;
}

@fragment
fn fs_value(in: Out) -> @location(0) vec4<f32> {
    return palette.colours[in.value];
}
