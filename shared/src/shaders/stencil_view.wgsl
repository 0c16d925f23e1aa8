// view=stencil (and view=complexity, another palette): the stencil buffer in false colour, without
// copying it (the GL backend cannot).
//
// Pass 1 rebuilds each pixel's stencil value in an R8Unorm texture, one bit at a time: draw i uses
// read mask 1 << i, reference 1 << i and compare Equal, so it passes exactly where bit i of the
// stored value is set, and adds 2^i / 255 there (additive blending). After 8 draws the texture
// holds value / 255. Pass 2 looks each value up in the palette.

struct Palette {
    colours: array<vec4<f32>, 256>,
    // x: how many boxes the scale in the bottom-left corner has (0: no scale).
    scale: vec4<f32>,
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

@fragment
fn fs_palette(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let value = textureLoad(values, vec2<i32>(position.xy), 0).r;
    let colour = palette.colours[u32(round(value * 255.0))];
    let boxes = i32(palette.scale.x);
    if boxes == 0 {
        return colour;
    }
    return with_scale(colour, vec2<i32>(position.xy), boxes);
}

// The scale over the picture: a row of boxes, box i in colour i and labelled i, the last "i+",
// on a dark frame in the bottom-left corner; sized for the picture (a font pixel a few pixels).
fn with_scale(colour: vec4<f32>, pixel: vec2<i32>, boxes: i32) -> vec4<f32> {
    let size = vec2<i32>(textureDimensions(values));
    let s = max(1, size.y / 200);
    let box = vec2<i32>(15 * s, 9 * s);
    let stride = box.x + s;
    let origin = vec2<i32>(6 * s, size.y - 6 * s - box.y);
    let q = pixel - origin;
    if q.x < -s || q.y < -s || q.x >= boxes * stride || q.y > box.y {
        return colour;
    }
    let i = q.x / stride;
    let inside = vec2<i32>(q.x - i * stride, q.y);
    if q.x < 0 || q.y < 0 || q.y >= box.y || inside.x >= box.x {
        return vec4<f32>(0.009, 0.009, 0.015, 1.0);
    }
    let fill = palette.colours[i];
    // The label: one or two digits, and "+" on the last box.
    var chars = array<u32, 3>(u32(i), 0u, 0u);
    var count = 1;
    if i >= 10 {
        chars[0] = u32(i) / 10u;
        chars[1] = u32(i) % 10u;
        count = 2;
    }
    if i == boxes - 1 {
        chars[count] = 10u;
        count += 1;
    }
    let width = count * 4 * s - s;
    let text = inside - vec2<i32>((box.x - width) / 2, (box.y - 5 * s) / 2);
    let cell = text / s;
    if text.x >= 0 && text.y >= 0 && cell.x / 4 < count && cell.x % 4 < 3 && cell.y < 5 {
        if lit(chars[cell.x / 4], vec2<i32>(cell.x % 4, cell.y)) {
            let luminance = dot(fill.rgb, vec3<f32>(0.2126, 0.7152, 0.0722));
            return select(vec4<f32>(1.0, 1.0, 1.0, 1.0), vec4<f32>(0.0, 0.0, 0.0, 1.0), luminance > 0.2);
        }
    }
    return fill;
}

// Whether the cell (column 0-2, row 0-4 from the top) of a glyph is lit: the digits 0-9 and "+"
// (10) in a 3x5 font, each row three bits, the top row in the lowest.
fn lit(glyph: u32, cell: vec2<i32>) -> bool {
    var glyphs = array<u32, 11>(31599u, 29850u, 29671u, 31207u, 18925u, 31183u, 31695u, 9511u, 31727u, 31215u, 1488u);
    return ((glyphs[glyph] >> u32(cell.y * 3 + cell.x)) & 1u) == 1u;
}
