// view=tests: a step's draw painted over the picture by its fragments' fates. The map was cleared
// to white, and each fate's twin wrote 0 into the fate's channel where it had a fragment (red:
// culled, green: failed the stencil test, blue: failed the depth test, alpha: passed both). A pixel
// shows the best fate its fragments met: passed, else failed depth, else failed stencil, else culled;
// a pixel the draw does not reach shows the picture, dimmed.

struct Fates {
    // Passed, failed depth, failed stencil, culled (linear), and the dimming of the rest.
    colours: array<vec4<f32>, 5>,
};

@group(0) @binding(0) var map: texture_2d<f32>;
@group(0) @binding(1) var<uniform> fates: Fates;

@fragment
fn fs_fates(@builtin(position) position: vec4<f32>) -> @location(0) vec4<f32> {
    let marks = textureLoad(map, vec2<i32>(position.xy), 0);
    if marks.a < 0.5 {
        return fates.colours[0];
    }
    if marks.b < 0.5 {
        return fates.colours[1];
    }
    if marks.g < 0.5 {
        return fates.colours[2];
    }
    if marks.r < 0.5 {
        return fates.colours[3];
    }
    return fates.colours[4];
}
