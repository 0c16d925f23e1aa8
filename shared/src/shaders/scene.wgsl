// The room's one shader: Blinn-Phong lighting from three lights (directional, point or spot), as in
// Luna's demos.

struct Light {
    // w = 0: xyz is the direction the light travels (a directional light); w = 1: xyz is where the
    // light is (a point or spot light), in world space.
    position: vec4<f32>,
    ambient: vec4<f32>,
    diffuse: vec4<f32>,
    specular: vec4<f32>,
    // A spot light's axis (xyz) and the cosine of its cut-off angle (w); w = -2 for other lights.
    spot: vec4<f32>,
};

struct Frame {
    view_projection: mat4x4<f32>,
    // xyz: the eye; w: the target's aspect ratio.
    eye: vec4<f32>,
    lights: array<Light, 3>,
    // (n, d): clipping recipes keep the points p with n·p + d >= 0 (lesson 8).
    clip_plane: vec4<f32>,
};

struct Object {
    world: mat4x4<f32>,
    // The inverse transpose of `world`: it carries normals (see the reflection chapter).
    normal_matrix: mat4x4<f32>,
    ambient: vec4<f32>,
    // rgb: diffuse colour; a: the material's alpha.
    diffuse: vec4<f32>,
    // rgb: specular colour; a: shininess.
    specular: vec4<f32>,
    // xy: texture repeat; z: alpha-test cut-off (0 = none).
    params: vec4<f32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;
@group(1) @binding(0) var<uniform> object: Object;
@group(1) @binding(1) var base_texture: texture_2d<f32>;
@group(1) @binding(2) var base_sampler: sampler;

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world_position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
};

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    return transform(in);
}

fn transform(in: VertexIn) -> VertexOut {
    let world = object.world * vec4<f32>(in.position, 1.0);
    var out: VertexOut;
    out.clip = frame.view_projection * world;
    out.world_position = world.xyz;
    out.normal = (object.normal_matrix * vec4<f32>(in.normal, 0.0)).xyz;
    out.uv = in.uv * object.params.xy;
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
    return shade(in);
}

// ANCHOR: discard
// Clip by discarding: a fragment behind the frame's clip plane is thrown away.
@fragment
fn fs_discard(in: VertexOut) -> @location(0) vec4<f32> {
    if dot(frame.clip_plane, vec4<f32>(in.world_position, 1.0)) < 0.0 {
        discard;
    }
    return shade(in);
}
// ANCHOR_END: discard

// Lit by points and spots as well as directional lights (lesson 10's key light).
@fragment
fn fs_any_light(in: VertexOut) -> @location(0) vec4<f32> {
    return shade_lit_by(in, true);
}

// Lit by directional lights only: Luna's three, as every lesson but lesson 10 lights the room.
fn shade(in: VertexOut) -> vec4<f32> {
    return shade_lit_by(in, false);
}

// `points`: whether the frame's lights may be point or spot lights. Where it is `false` the
// compiler leaves their code out, and it costs nothing: a software GPU runs both sides of every
// branch, and that code took a seventh of its frame.
fn shade_lit_by(in: VertexOut, points: bool) -> vec4<f32> {
    let surface = surface_at(in);
    var colour = vec3<f32>(0.0);
    for (var i = 0; i < 3; i += 1) {
        colour += ambient_of(frame.lights[i], surface) + direct_of(frame.lights[i], surface, points);
    }
    return vec4<f32>(colour, surface.alpha);
}

// A point of a surface as the lights see it: its texel, normal, position and the way to the eye.
struct Surface {
    texel: vec4<f32>,
    alpha: f32,
    n: vec3<f32>,
    position: vec3<f32>,
    to_eye: vec3<f32>,
};

// The surface at a fragment (discarded where the texture's alpha is under the cut-off).
fn surface_at(in: VertexOut) -> Surface {
    let texel = textureSample(base_texture, base_sampler, in.uv);
    if object.params.z > 0.0 && texel.a < object.params.z {
        discard;
    }
    let to_eye = normalize(frame.eye.xyz - in.world_position);
    return Surface(texel, texel.a * object.diffuse.a, normalize(in.normal), in.world_position, to_eye);
}

// What a light's ambient term adds to the surface.
fn ambient_of(light: Light, s: Surface) -> vec3<f32> {
    return s.texel.rgb * object.ambient.rgb * light.ambient.rgb;
}

// What a light adds to the surface where it reaches it: diffuse and specular (Blinn-Phong). Light
// adds up: the colour of a point is the sum of these over the lights.
fn direct_of(light: Light, s: Surface, points: bool) -> vec3<f32> {
    var to_light = -normalize(light.position.xyz);
    var strength = 1.0;
    if points && light.position.w > 0.5 {
        // A point light: from where it is, fading with the distance (Luna's 1 / (a0 + a2 d²)).
        let offset = light.position.xyz - s.position;
        to_light = normalize(offset);
        strength = 1.0 / (1.0 + 0.01 * dot(offset, offset));
        // A spot light: only inside its cone, the edge softened over a few degrees.
        let cut_off = light.spot.w;
        if cut_off > -1.5 {
            let along = dot(-to_light, normalize(light.spot.xyz));
            strength *= smoothstep(cut_off, cut_off + 0.03, along);
        }
    }
    let lambert = max(dot(s.n, to_light), 0.0);
    if lambert <= 0.0 {
        return vec3<f32>(0.0);
    }
    let diffuse = strength * lambert * object.diffuse.rgb * light.diffuse.rgb;
    let halfway = normalize(to_light + s.to_eye);
    let highlight = pow(max(dot(s.n, halfway), 0.0), object.specular.a);
    let specular = strength * highlight * object.specular.rgb * light.specular.rgb;
    return s.texel.rgb * diffuse + specular;
}
