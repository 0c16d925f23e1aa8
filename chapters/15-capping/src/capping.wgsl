// Lesson 15's entries, appended to the room's shader: the cap, a square in the cut plane, its points
// given as vec4 (w = 1), drawn where the stencil says the plane lies inside the solid.

struct CapOut {
    @builtin(position) clip: vec4<f32>,
};

@vertex
fn vs_cap(@location(0) point: vec4<f32>) -> CapOut {
    return CapOut(frame.view_projection * point);
}

// ANCHOR: cap
// The colour of the cut: bone's inside, red, so that the cap stands out from the skull's white.
const CUT = vec3<f32>(0.72, 0.2, 0.16);

// The cap is flat: lit by the frame's directional lights as a surface facing the part cut away
// (the kept side is where n·p + d >= 0, so the cut faces −n).
@fragment
fn fs_cap(in: CapOut) -> @location(0) vec4<f32> {
    let n = -normalize(frame.clip_plane.xyz);
    var light = vec3<f32>(0.0);
    for (var i = 0; i < 3; i += 1) {
        let source = frame.lights[i];
        let lambert = max(dot(n, -normalize(source.position.xyz)), 0.0);
        light += source.ambient.rgb + lambert * source.diffuse.rgb;
    }
    return vec4<f32>(CUT * light, 1.0);
}
// ANCHOR_END: cap
