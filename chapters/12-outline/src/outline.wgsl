// Lesson 12's two entry points, appended to the room's shader (scene.wgsl): its `frame`, `object`
// and `transform` are in scope.

// ANCHOR: grow
// The outline's width, as a fraction of the picture's height: 5 pixels in a 1280x720 picture.
const OUTLINE_WIDTH: f32 = 5.0 / 720.0;

// The skull grown along its normals as the screen sees them: each vertex moved sideways on the
// screen, away from the skull, by OUTLINE_WIDTH — the same width near and far, since the move is
// made after the perspective divide (multiplied back by w).
@vertex
fn vs_grown(in: VertexIn) -> VertexOut {
    var out = transform(in);
    // Where the normal points on the screen: the vertex and a point a little along its normal,
    // both projected, in normalized device coordinates (x stretched by the aspect ratio, so that a
    // unit is as long across as up).
    let aspect = vec2<f32>(frame.eye.w, 1.0);
    let ahead = frame.view_projection * vec4<f32>(out.world_position + 0.01 * normalize(out.normal), 1.0);
    let on_screen = (ahead.xy / ahead.w - out.clip.xy / out.clip.w) * aspect;
    // A normal that points straight at the camera has no direction on the screen: such a vertex
    // is inside the silhouette, and stays.
    if length(on_screen) > 1e-7 {
        // The picture is 2 units high in these coordinates.
        let offset = normalize(on_screen) / aspect * 2.0 * OUTLINE_WIDTH;
        out.clip = vec4<f32>(out.clip.xy + offset * out.clip.w, out.clip.zw);
    }
    return out;
}
// ANCHOR_END: grow

// ANCHOR: colour
// The outline's one colour, unlit: the selection's orange.
@fragment
fn fs_outline(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(1.0, 0.45, 0.0, 1.0);
}
// ANCHOR_END: colour

// The screen-space way's mask (way=screen-space): white, through the recipe's colour write mask
// (red for the skull, green for its image).
@fragment
fn fs_mask(in: VertexOut) -> @location(0) vec4<f32> {
    return vec4<f32>(1.0);
}
