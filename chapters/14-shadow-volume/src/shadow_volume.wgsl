// Lesson 14's entries, appended to the room's shader. Light 0 is the key light, the one that casts
// the shadows; lights 1 and 2 are Luna's fill lights, which cast none.

// ANCHOR: light
// DRAW_IN_SHADOW: the room as it looks where the key light does not reach it: every light's
// ambient term, and what the fill lights add.
@fragment
fn fs_in_shadow(in: VertexOut) -> @location(0) vec4<f32> {
    let s = surface_at(in);
    var colour = vec3<f32>(0.0);
    for (var i = 0; i < 3; i += 1) {
        colour += ambient_of(frame.lights[i], s);
    }
    colour += direct_of(frame.lights[1], s, false) + direct_of(frame.lights[2], s, false);
    return vec4<f32>(colour, s.alpha);
}

// ADD_KEY_LIGHT: what the key light adds where it reaches (light adds up: in shadow + this = lit).
@fragment
fn fs_key_light(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(direct_of(frame.lights[0], surface_at(in), true), 1.0);
}
// ANCHOR_END: light

// ANCHOR: volume
// A shadow volume's points come in homogeneous coordinates: w = 1 on the solid, w = 0 at infinity.
// The projection takes both as they are (its far plane is at infinity).
@vertex
fn vs_volume(@location(0) point: vec4<f32>) -> @builtin(position) vec4<f32> {
    return frame.view_projection * point;
}
// ANCHOR_END: volume

// SEE_VOLUMES: the volumes made visible, a faint amber over the picture.
@fragment
fn fs_volume() -> @location(0) vec4<f32> {
    return vec4<f32>(1.0, 0.7, 0.1, 0.2);
}
