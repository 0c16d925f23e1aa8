// Lesson 12's other way (way=screen-space): the band found on the screen, in a mask of what is
// selected, by looking around each pixel. Red marks the skull, green its image in the mirror.

@group(0) @binding(0) var mask: texture_2d<f32>;

// The outline's width, as in outline.wgsl: a fraction of the picture's height.
const OUTLINE_WIDTH: f32 = 5.0 / 720.0;

// One triangle over the whole screen.
@vertex
fn vs_screen(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0);
}

// ANCHOR: edge
// Amber where this pixel is not in the mask's `channel` but a pixel within the outline's width is:
// every pixel looks at the (2r + 1)² pixels around it and keeps those in a disc of radius r.
fn edge(position: vec4<f32>, channel: u32) -> vec4<f32> {
    let size = vec2<i32>(textureDimensions(mask));
    let here = vec2<i32>(position.xy);
    if textureLoad(mask, here, 0)[channel] > 0.5 {
        discard;
    }
    let radius = OUTLINE_WIDTH * f32(size.y);
    let r = i32(ceil(radius));
    for (var dy = -r; dy <= r; dy += 1) {
        for (var dx = -r; dx <= r; dx += 1) {
            let there = clamp(here + vec2<i32>(dx, dy), vec2<i32>(0), size - 1);
            let near = f32(dx * dx + dy * dy) <= radius * radius;
            if near && textureLoad(mask, there, 0)[channel] > 0.5 {
                return vec4<f32>(1.0, 0.45, 0.0, 1.0);
            }
        }
    }
    discard;
    return vec4<f32>(0.0);
}
// ANCHOR_END: edge

@fragment
fn fs_edge_skull(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return edge(position, 0u);
}

@fragment
fn fs_edge_image(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    return edge(position, 1u);
}
