// Appended to scene.wgsl (after `enable clip_distances;`) where the device has user clip distances.

struct ClippedVertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
    @builtin(clip_distances) clip_distances: array<f32, 1>,
};

// ANCHOR: clip_distances
// Clip with a user clip distance: the rasterizer keeps the part of each triangle where the
// interpolated distance is >= 0, so triangles are cut exactly at the plane (glClipPlane's way).
@vertex
fn vs_clip_distances(in: VertexIn) -> ClippedVertexOut {
    let plain = transform(in);
    var out: ClippedVertexOut;
    out.clip = plain.clip;
    out.world_position = plain.world_position;
    out.normal = plain.normal;
    out.uv = plain.uv;
    out.clip_distances[0] = dot(frame.clip_plane, vec4<f32>(plain.world_position, 1.0));
    return out;
}
// ANCHOR_END: clip_distances
