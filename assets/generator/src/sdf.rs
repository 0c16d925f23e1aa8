//! Signed-distance primitives and blending operators.
//!
//! Every function returns a signed distance: negative inside, positive
//! outside. Most are exact; `ellipsoid` and `round_cone` are the usual
//! close approximations, which is all the mesher needs.

use glam::{Vec2, Vec3};

/// Ellipsoid centred at `c` with semi-axes `r` (Inigo Quilez's bound).
pub fn ellipsoid(p: Vec3, c: Vec3, r: Vec3) -> f32 {
    let q = p - c;
    let k1 = (q / (r * r)).length();
    if k1 == 0.0 {
        return -r.min_element();
    }
    let k0 = (q / r).length();
    k0 * (k0 - 1.0) / k1
}

/// Sphere centred at `c`.
pub fn sphere(p: Vec3, c: Vec3, r: f32) -> f32 {
    (p - c).length() - r
}

/// Capsule (swept sphere) from `a` to `b`.
pub fn capsule(p: Vec3, a: Vec3, b: Vec3, r: f32) -> f32 {
    round_cone(p, a, b, r, r)
}

/// Capsule whose radius goes linearly from `ra` at `a` to `rb` at `b`.
pub fn round_cone(p: Vec3, a: Vec3, b: Vec3, ra: f32, rb: f32) -> f32 {
    let pa = p - a;
    let ba = b - a;
    let h = (pa.dot(ba) / ba.dot(ba)).clamp(0.0, 1.0);
    (pa - ba * h).length() - (ra + (rb - ra) * h)
}

/// Box with half extents `half` and edge radius `r`, in local coordinates.
pub fn round_box(q: Vec3, half: Vec3, r: f32) -> f32 {
    let d = q.abs() - half + Vec3::splat(r);
    d.max(Vec3::ZERO).length() + d.max_element().min(0.0) - r
}

/// 2-D rounded rectangle with half extents `half` and corner radius `r`.
pub fn round_rect(q: Vec2, half: Vec2, r: f32) -> f32 {
    let d = q.abs() - half + Vec2::splat(r);
    d.max(Vec2::ZERO).length() + d.max_element().min(0.0) - r
}

/// Polynomial smooth minimum (smooth union) with blend radius `k`.
pub fn smin(a: f32, b: f32, k: f32) -> f32 {
    let h = (k - (a - b).abs()).max(0.0) / k;
    a.min(b) - h * h * k * 0.25
}

/// Smooth maximum (smooth intersection).
pub fn smax(a: f32, b: f32, k: f32) -> f32 {
    -smin(-a, -b, k)
}

/// Smoothly carves `cut` out of `d`.
pub fn ssub(d: f32, cut: f32, k: f32) -> f32 {
    smax(d, -cut, k)
}

/// Mirrors across the sagittal plane so bilateral parts are modelled once.
pub fn mirror_x(p: Vec3) -> Vec3 {
    Vec3::new(p.x.abs(), p.y, p.z)
}

/// Rounded bar from `a` to `b` with a rectangular cross-section: `half_h`
/// measured in the vertical plane through the bar, `half_w` horizontally
/// across it, edges rounded by `r`. Good for flat struts of bone.
pub fn bar(p: Vec3, a: Vec3, b: Vec3, half_h: f32, half_w: f32, r: f32) -> f32 {
    let axis = b - a;
    let len = axis.length();
    let u = axis / len;
    let w = u.cross(Vec3::Y).normalize();
    let v = w.cross(u);
    let d = p - 0.5 * (a + b);
    round_box(
        Vec3::new(d.dot(u), d.dot(v), d.dot(w)),
        Vec3::new(0.5 * len, half_h, half_w),
        r,
    )
}

/// Signed distance to a simple polygon (Inigo Quilez's winding test).
pub fn polygon(p: Vec2, v: &[Vec2]) -> f32 {
    let mut d = (p - v[0]).length_squared();
    let mut s = 1.0;
    let mut j = v.len() - 1;
    for i in 0..v.len() {
        let e = v[j] - v[i];
        let w = p - v[i];
        let b = w - e * (w.dot(e) / e.dot(e)).clamp(0.0, 1.0);
        d = d.min(b.dot(b));
        let c = [p.y >= v[i].y, p.y < v[j].y, e.x * w.y > e.y * w.x];
        if c.iter().all(|&x| x) || c.iter().all(|&x| !x) {
            s = -s;
        }
        j = i;
    }
    s * d.sqrt()
}

/// Extrudes a 2-D distance `d2` along a third axis: `h` is the distance
/// from the mid-plane, `half` the half thickness.
pub fn extrude(d2: f32, h: f32, half: f32) -> f32 {
    let w = Vec2::new(d2, h.abs() - half);
    w.max_element().min(0.0) + w.max(Vec2::ZERO).length()
}

/// Distance from `p` to the box `lo..hi` (zero inside). Anything inside
/// the box is at least this far away, so parts use it to skip work.
pub fn box_bound(p: Vec3, lo: Vec3, hi: Vec3) -> f32 {
    (lo - p).max(p - hi).max(Vec3::ZERO).length()
}
