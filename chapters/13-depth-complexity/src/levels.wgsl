// Lesson 13's paint: one triangle over the screen per level, coloured by the level it paints (the
// draw's instance index). The stencil test decides where each is drawn.

// ANCHOR: palette
// Level 0 black, then dark blue through green and yellow to red, and white for 8 or more.
const LEVELS = array<vec3<f32>, 9>(
    vec3<f32>(0.0, 0.0, 0.0),
    vec3<f32>(0.0, 0.02, 0.25),
    vec3<f32>(0.0, 0.12, 1.0),
    vec3<f32>(0.0, 0.6, 0.35),
    vec3<f32>(0.25, 0.85, 0.0),
    vec3<f32>(1.0, 0.8, 0.0),
    vec3<f32>(1.0, 0.3, 0.0),
    vec3<f32>(0.8, 0.0, 0.05),
    vec3<f32>(1.0, 1.0, 1.0),
);
// ANCHOR_END: palette

struct Level {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) level: u32,
};

@vertex
fn vs_level(@builtin(vertex_index) index: u32, @builtin(instance_index) level: u32) -> Level {
    let uv = vec2<f32>(f32((index << 1u) & 2u), f32(index & 2u));
    return Level(vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0), level);
}

@fragment
fn fs_level(in: Level) -> @location(0) vec4<f32> {
    var levels = LEVELS;
    return vec4<f32>(levels[in.level], 1.0);
}

// COUNT's fragment shader, appended to the room's shader: nothing to colour (COUNT writes no
// colour), and nothing thrown away. The room's shader throws away the wire fence's holes (its alpha
// test), but only after it ran for them: they cost as much as the wires, and count as they cost.
// (Which fragments of the holes pass an alpha test is also the GPU's own choice of filtering.)
@fragment
fn fs_count(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(0.0);
}

// ANCHOR: count
// The additive way (way=blend), appended to the room's shader: every fragment adds an eighth of
// white, so a pixel is as bright as its count, white at 8 or more (in linear light).
@fragment
fn fs_eighth(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(vec3<f32>(1.0 / 8.0), 1.0);
}
// ANCHOR_END: count
