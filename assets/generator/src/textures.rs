//! Procedural RGBA8 textures (sRGB colour values), 256 x 256.
//!
//! All randomness comes from an integer hash of (x, y, seed), so every run
//! produces the same pixels. Noise lattices wrap around the image edges,
//! which makes the repeating textures tile seamlessly.

use std::f32::consts::TAU;

use anyhow::Context;
use glam::{Vec2, Vec3, vec2, vec3};
use image::ImageEncoder;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};

const SIZE: u32 = 256;

/// An RGBA8 image in row-major order, top row first.
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub rgba: Vec<u8>,
}

impl Image {
    /// Fills a `SIZE` x `SIZE` image by calling `f(x, y)` for each pixel,
    /// which returns colour (0..1, sRGB-encoded) and alpha (0..1).
    fn from_fn(mut f: impl FnMut(u32, u32) -> (Vec3, f32)) -> Image {
        let mut rgba = Vec::with_capacity((SIZE * SIZE * 4) as usize);
        for y in 0..SIZE {
            for x in 0..SIZE {
                let (c, a) = f(x, y);
                rgba.extend(c.to_array().into_iter().chain([a]).map(to_u8));
            }
        }
        Image {
            width: SIZE,
            height: SIZE,
            rgba,
        }
    }
}

fn to_u8(v: f32) -> u8 {
    (v.clamp(0.0, 1.0) * 255.0 + 0.5) as u8
}

/// Every texture with its file name.
pub fn all() -> Vec<(&'static str, Image)> {
    vec![
        ("checker.png", checker()),
        ("bricks.png", bricks()),
        ("ice.png", ice()),
        ("wirefence.png", wire_fence()),
        ("crate.png", crate_face()),
        ("water.png", water()),
    ]
}

/// Encodes `image` as an 8-bit RGBA PNG.
pub fn encode_png(image: &Image) -> anyhow::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    PngEncoder::new_with_quality(&mut bytes, CompressionType::Best, FilterType::Adaptive)
        .write_image(
            &image.rgba,
            image.width,
            image.height,
            image::ExtendedColorType::Rgba8,
        )
        .context("PNG encoder failed")?;
    Ok(bytes)
}

// ---------------------------------------------------------------------------
// Noise

/// 32-bit integer hash (a "lowbias32" style mixer) of a lattice point.
fn hash(x: u32, y: u32, seed: u32) -> u32 {
    let mut h =
        x.wrapping_mul(0x8da6_b343) ^ y.wrapping_mul(0xd816_3841) ^ seed.wrapping_mul(0xcb1a_b31f);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^ (h >> 16)
}

/// Uniform random number in [0, 1) for a lattice point.
fn rand(x: u32, y: u32, seed: u32) -> f32 {
    (hash(x, y, seed) >> 8) as f32 / (1u32 << 24) as f32
}

/// Per-texel white noise in [-1, 1).
fn grain(x: u32, y: u32, seed: u32) -> f32 {
    2.0 * rand(x, y, seed) - 1.0
}

fn smoothstep(e0: f32, e1: f32, x: f32) -> f32 {
    let t = ((x - e0) / (e1 - e0)).clamp(0.0, 1.0);
    t * t * (3.0 - 2.0 * t)
}

/// Value noise in [0, 1] over texture coordinates `uv` (1 = one image),
/// with `period` lattice cells per image in both directions, so it tiles.
fn value_noise(uv: Vec2, period: u32, seed: u32) -> f32 {
    let p = uv * period as f32;
    let i = p.floor();
    let f = p - i;
    let w = f * f * (Vec2::splat(3.0) - 2.0 * f);
    let wrap = |v: f32| (v as i64).rem_euclid(period as i64) as u32;
    let (x0, y0) = (wrap(i.x), wrap(i.y));
    let (x1, y1) = ((x0 + 1) % period, (y0 + 1) % period);
    let a = rand(x0, y0, seed);
    let b = rand(x1, y0, seed);
    let c = rand(x0, y1, seed);
    let d = rand(x1, y1, seed);
    let top = a + (b - a) * w.x;
    let bottom = c + (d - c) * w.x;
    top + (bottom - top) * w.y
}

/// Fractal sum of `octaves` value noises starting at `period`, in [0, 1].
fn fbm(uv: Vec2, period: u32, octaves: u32, seed: u32) -> f32 {
    let (mut sum, mut amp, mut total) = (0.0, 1.0, 0.0);
    for o in 0..octaves {
        sum += amp * value_noise(uv, period << o, seed.wrapping_add(o * 7919));
        total += amp;
        amp *= 0.5;
    }
    sum / total
}

/// Tileable cellular noise: distances (in cells) to the nearest and second
/// nearest feature point, one random point per cell of a `period` grid.
fn worley(uv: Vec2, period: u32, seed: u32) -> (f32, f32) {
    let p = uv * period as f32;
    let cell = p.floor();
    let (mut f1, mut f2) = (f32::MAX, f32::MAX);
    for dy in -1..=1 {
        for dx in -1..=1 {
            let c = cell + vec2(dx as f32, dy as f32);
            let wx = (c.x as i64).rem_euclid(period as i64) as u32;
            let wy = (c.y as i64).rem_euclid(period as i64) as u32;
            let feature = c + vec2(rand(wx, wy, seed), rand(wx, wy, seed ^ 0x5bd1));
            let d = feature.distance(p);
            if d < f1 {
                f2 = f1;
                f1 = d;
            } else if d < f2 {
                f2 = d;
            }
        }
    }
    (f1, f2)
}

fn uv(x: u32, y: u32) -> Vec2 {
    (vec2(x as f32, y as f32) + 0.5) / SIZE as f32
}

// ---------------------------------------------------------------------------
// Textures

/// Floor tiles: 8 x 8 cream and slate squares with grout lines, a slight
/// bevel, per-tile tint, mottling and per-texel grain.
fn checker() -> Image {
    const TILE: u32 = SIZE / 8;
    let light = vec3(0.84, 0.81, 0.74);
    let dark = vec3(0.28, 0.31, 0.35);
    let grout = vec3(0.50, 0.49, 0.46);
    Image::from_fn(|x, y| {
        let (tx, ty) = (x / TILE, y / TILE);
        let mut c = if (tx + ty) % 2 == 0 { light } else { dark };
        c *= 0.96 + 0.08 * rand(tx, ty, 11);
        c *= 0.92 + 0.16 * fbm(uv(x, y), 8, 4, 12);
        // Distance to the tile edge, in texels.
        let (lx, ly) = ((x % TILE) as f32 + 0.5, (y % TILE) as f32 + 0.5);
        let (ex, ey) = (lx.min(TILE as f32 - lx), ly.min(TILE as f32 - ly));
        // Bevel: lit along the top-left edges, shaded along the bottom-right.
        let bevel = smoothstep(3.0, 1.0, ex.min(ey));
        let lit = if lx < TILE as f32 / 2.0 || ly < TILE as f32 / 2.0 {
            1.06
        } else {
            0.9
        };
        c *= 1.0 + (lit - 1.0) * bevel;
        let g = smoothstep(1.6, 0.6, ex.min(ey));
        c = c.lerp(grout * (0.9 + 0.2 * rand(x, y, 13)), g);
        c += Vec3::splat(0.02 * grain(x, y, 14));
        (c, 1.0)
    })
}

/// Brick wall in running bond: 8 courses of 4 bricks, each brick with its
/// own tint, light mortar joints, soft shading at the brick edges and noise.
fn bricks() -> Image {
    const W: u32 = 64;
    const H: u32 = 32;
    let mortar = vec3(0.76, 0.73, 0.68);
    Image::from_fn(|x, y| {
        let row = y / H;
        let sx = (x + if row % 2 == 1 { W / 2 } else { 0 }) % SIZE;
        let (bx, lx, ly) = (sx / W, (sx % W) as f32 + 0.5, (y % H) as f32 + 0.5);
        let t = rand(bx, row, 21);
        let base = vec3(0.56, 0.24, 0.17).lerp(vec3(0.46, 0.27, 0.2), rand(bx, row, 22));
        let mut c = base * (0.78 + 0.4 * t);
        let p = uv(x, y);
        c *= 0.85 + 0.3 * fbm(p, 16, 4, 23);
        // Dark speckles of fired clay.
        if rand(x, y, 24) > 0.985 {
            c *= 0.7;
        }
        c += Vec3::splat(0.035 * grain(x, y, 25));
        let (ex, ey) = (lx.min(W as f32 - lx), ly.min(H as f32 - ly));
        let edge = ex.min(ey);
        // Edges of a brick are a little darker, the lower edge most.
        c *= 1.0
            - 0.18 * smoothstep(5.0, 1.5, edge)
            - 0.1 * smoothstep(H as f32 - 6.0, H as f32, ly);
        let m = smoothstep(3.2, 1.8, edge + 0.8 * (fbm(p, 32, 2, 26) - 0.5));
        let mortar_c =
            mortar * (0.9 + 0.15 * fbm(p, 64, 2, 27)) + Vec3::splat(0.03 * grain(x, y, 28));
        (c.lerp(mortar_c, m), 1.0)
    })
}

/// Pale blue-white ice: soft diagonal frost streaks and faint crack lines.
fn ice() -> Image {
    Image::from_fn(|x, y| {
        let p = uv(x, y);
        let cloud = fbm(p, 4, 5, 31);
        // Diagonal coordinates keep the pattern periodic on the image.
        let d = vec2(p.x + p.y, p.x - p.y);
        let streak = fbm(vec2(d.x * 0.5, d.y * 0.5), 2, 2, 32) * 0.3
            + fbm(vec2(d.y * 0.5, d.x * 0.5) * vec2(1.0, 1.0), 24, 3, 33) * 0.7;
        let streak_dir = value_noise(vec2(p.x * 0.5 + p.y * 0.5, p.y), 2, 34);
        let mut c = vec3(0.70, 0.84, 0.94).lerp(vec3(0.93, 0.97, 1.0), cloud);
        c = c.lerp(
            vec3(0.98, 0.99, 1.0),
            0.35 * smoothstep(0.45, 0.8, streak) * streak_dir,
        );
        let (f1, f2) = worley(p, 6, 35);
        let crack = smoothstep(0.06, 0.0, f2 - f1) * smoothstep(0.35, 0.65, fbm(p, 8, 3, 36));
        c = c.lerp(vec3(1.0, 1.0, 1.0), 0.6 * crack);
        c += Vec3::splat(0.012 * grain(x, y, 37));
        (c, 1.0)
    })
}

/// Chain-link fence: two families of diagonal wires, opaque on the wires,
/// transparent in the holes, with antialiased (partial alpha) edges.
fn wire_fence() -> Image {
    const PERIOD: f32 = 32.0;
    const HALF_WIDTH: f32 = 1.9;
    let metal = vec3(0.62, 0.64, 0.67);
    Image::from_fn(|x, y| {
        let p = vec2(x as f32, y as f32) + 0.5;
        // Distance (in texels) to the nearest wire of each family.
        let dist = |s: f32| {
            let m = s.rem_euclid(PERIOD);
            m.min(PERIOD - m) / std::f32::consts::SQRT_2
        };
        let (da, db) = (dist(p.x + p.y), dist(p.x - p.y));
        let coverage = |d: f32| (HALF_WIDTH - d + 0.5).clamp(0.0, 1.0);
        let alpha = coverage(da).max(coverage(db));
        // Which wire passes over at a crossing alternates like a weave.
        let ia = ((p.x + p.y) / PERIOD).round() as i32;
        let ib = ((p.x - p.y) / PERIOD).round() as i32;
        let a_on_top = (ia + ib).rem_euclid(2) == 0;
        let reach = HALF_WIDTH + 0.5;
        // Draw the upper wire where both cover the texel, else the nearer;
        // the lower wire is shaded where it passes under the upper one.
        let draw_a = if da < reach && db < reach {
            a_on_top
        } else {
            da < db
        };
        let (d, other, under) = if draw_a {
            (da, db, !a_on_top)
        } else {
            (db, da, a_on_top)
        };
        let under = under && other < HALF_WIDTH + 2.5;
        // Round wire: bright along its middle, darker toward its edges.
        let across = (d / (HALF_WIDTH + 0.5)).min(1.0);
        let shade = (1.0 - across * across).sqrt();
        let mut c = metal * (0.45 + 0.55 * shade) + Vec3::splat(0.25 * shade.powi(8));
        if under {
            c *= 0.6;
        }
        c *= 0.92 + 0.16 * value_noise(uv(x, y), 16, 41);
        // Holes keep the mean wire colour so filtering does not darken edges.
        let c = c.lerp(metal * 0.8, 1.0 - alpha);
        (c, alpha)
    })
}

/// Wood grain along `along`, with ring spacing varied by noise.
fn wood(x: u32, y: u32, along_x: bool, seed: u32) -> Vec3 {
    let p = uv(x, y);
    let (a, b) = if along_x { (p.x, p.y) } else { (p.y, p.x) };
    let warp = fbm(vec2(b * 2.0, a * 0.25), 8, 3, seed);
    let rings = (b * 90.0 + 7.0 * warp).fract();
    let line = smoothstep(0.0, 0.15, rings) * smoothstep(1.0, 0.6, rings);
    let fibre = value_noise(vec2(b, a * 0.06), 128, seed + 1);
    let light = vec3(0.72, 0.52, 0.31);
    let darker = vec3(0.55, 0.36, 0.19);
    darker.lerp(light, 0.35 + 0.5 * line + 0.15 * fibre)
}

/// Wooden crate face: vertical planks, a darker frame border, a diagonal
/// brace with its drop shadow, and nails. Not tileable (it is one face).
fn crate_face() -> Image {
    const FRAME: f32 = 24.0;
    const PLANKS: f32 = 4.0;
    const BRACE_HALF: f32 = 15.0;
    let s = SIZE as f32;
    let inner = s - 2.0 * FRAME;
    // The brace runs from the bottom-left to the top-right inner corner.
    let a = vec2(FRAME, s - FRAME);
    let b = vec2(s - FRAME, FRAME);
    let dir = (b - a).normalize();
    let normal = vec2(-dir.y, dir.x);
    let nails = [
        vec2(12.0, 12.0),
        vec2(s - 12.0, 12.0),
        vec2(12.0, s - 12.0),
        vec2(s - 12.0, s - 12.0),
        a + dir * 14.0,
        b - dir * 14.0,
    ];
    Image::from_fn(|x, y| {
        let p = vec2(x as f32, y as f32) + 0.5;
        let in_frame = p.x < FRAME || p.x > s - FRAME || p.y < FRAME || p.y > s - FRAME;
        let c = if in_frame {
            // Top and bottom boards run across, the sides run up and down.
            let horizontal = p.y < FRAME || p.y > s - FRAME;
            let board = if horizontal {
                (p.y > s / 2.0) as u32
            } else {
                2 + (p.x > s / 2.0) as u32
            };
            let mut c = wood(x, y, horizontal, 51 + board) * vec3(0.62, 0.6, 0.58);
            // Seams between frame boards and a bevel on their inner edge.
            let edge_dist = if horizontal {
                (p.y.min(s - p.y) - FRAME).abs()
            } else {
                (p.x.min(s - p.x) - FRAME).abs()
            };
            let seam = if horizontal {
                f32::INFINITY
            } else {
                (p.y.min(s - p.y) - FRAME).abs()
            };
            c *= 1.0 - 0.5 * smoothstep(2.0, 0.0, edge_dist.min(seam));
            let outer = p.x.min(p.y).min(s - p.x).min(s - p.y);
            c *= 1.0 - 0.35 * smoothstep(3.0, 0.0, outer);
            c
        } else {
            let q = p - FRAME;
            let plank = ((q.x / inner * PLANKS) as u32).min(PLANKS as u32 - 1);
            let mut c = wood(x, y, false, 61 + plank) * (0.9 + 0.2 * rand(plank, 0, 62));
            let local = (q.x / inner * PLANKS).fract() * inner / PLANKS;
            let gap = local.min(inner / PLANKS - local);
            c *= 1.0 - 0.6 * smoothstep(2.0, 0.0, gap);
            // Shadow of the frame on the planks.
            let from_frame = q.x.min(q.y).min(inner - q.x).min(inner - q.y);
            c *= 1.0 - 0.3 * smoothstep(6.0, 0.0, from_frame);
            // Brace (diagonal board) on top, and its drop shadow.
            let across = (p - a).dot(normal);
            let along = (p - a).dot(dir);
            let length = (b - a).length();
            let on_brace = across.abs() < BRACE_HALF && along > 0.0 && along < length;
            if on_brace {
                let dx = across.abs();
                let mut brace = diagonal_wood(p, dir, 71) * vec3(0.8, 0.78, 0.76);
                brace *= 1.0 - 0.45 * smoothstep(2.5, 0.0, BRACE_HALF - dx);
                brace
            } else {
                let shadow_across = (p - a - vec2(3.0, 4.0)).dot(normal);
                let shadowed = shadow_across.abs() < BRACE_HALF + 1.0;
                if shadowed { c * 0.6 } else { c }
            }
        };
        let mut c = c + Vec3::splat(0.025 * grain(x, y, 52));
        for n in nails {
            let d = p.distance(n);
            if d < 3.6 {
                let hi = (1.0 - (p - n + vec2(1.0, 1.0)).length() / 2.5).max(0.0);
                c = vec3(0.22, 0.22, 0.23) + Vec3::splat(0.5 * hi);
            } else if d < 5.0 {
                c *= 0.75;
            }
        }
        (c, 1.0)
    })
}

/// Wood with its grain running along `dir` (used by the diagonal brace).
fn diagonal_wood(p: Vec2, dir: Vec2, seed: u32) -> Vec3 {
    let along = p.dot(dir) / SIZE as f32;
    let across = p.dot(vec2(-dir.y, dir.x)) / SIZE as f32;
    let warp = fbm(vec2(across * 2.0, along * 0.25), 8, 3, seed);
    let rings = (across * 90.0 + 7.0 * warp).fract();
    let line = smoothstep(0.0, 0.15, rings) * smoothstep(1.0, 0.6, rings);
    vec3(0.55, 0.36, 0.19).lerp(vec3(0.74, 0.54, 0.33), 0.35 + 0.55 * line)
}

/// Blue-green water: a sum of waves whose wave vectors are whole numbers of
/// cycles per image (so it tiles), warped by noise, lit by a fixed sun.
fn water() -> Image {
    // (cycles in x, cycles in y, amplitude, phase)
    const WAVES: [(f32, f32, f32, f32); 6] = [
        (3.0, 1.0, 1.0, 0.0),
        (-2.0, 3.0, 0.8, 1.7),
        (5.0, -2.0, 0.5, 4.1),
        (1.0, 6.0, 0.4, 2.3),
        (-7.0, -4.0, 0.25, 5.2),
        (9.0, 5.0, 0.18, 0.9),
    ];
    let height = |p: Vec2| -> f32 {
        let warp = fbm(p, 4, 3, 81) - 0.5;
        WAVES
            .iter()
            .map(|&(kx, ky, amp, phase)| {
                amp * (TAU * (kx * p.x + ky * p.y) + phase + 3.0 * warp).sin()
            })
            .sum::<f32>()
            + 0.3 * fbm(p, 8, 3, 82)
    };
    let sun = vec3(0.4, -0.5, 0.77).normalize();
    Image::from_fn(|x, y| {
        let p = uv(x, y);
        let e = 1.0 / SIZE as f32;
        let h = height(p);
        let gx = height(p + vec2(e, 0.0)) - h;
        let gy = height(p + vec2(0.0, e)) - h;
        let n = vec3(-gx * 12.0, -gy * 12.0, 1.0).normalize();
        let diffuse = n.dot(sun).max(0.0);
        let spec = n.dot((sun + Vec3::Z).normalize()).max(0.0).powi(24);
        let deep = vec3(0.05, 0.3, 0.38);
        let shallow = vec3(0.16, 0.54, 0.55);
        let mut c = deep.lerp(shallow, smoothstep(-2.0, 2.2, h));
        c *= 0.75 + 0.35 * diffuse;
        c += vec3(0.25, 0.33, 0.32) * spec;
        c += Vec3::splat(0.01 * grain(x, y, 83));
        (c, 1.0)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn noise_wraps_around_the_image() {
        for i in 0..50 {
            let p = vec2(i as f32 * 0.0173, i as f32 * 0.0291);
            for q in [p + vec2(1.0, 0.0), p + vec2(0.0, 1.0)] {
                assert!((fbm(p, 4, 4, 9) - fbm(q, 4, 4, 9)).abs() < 1e-4);
                let (a, b) = (worley(p, 6, 3), worley(q, 6, 3));
                assert!((a.0 - b.0).abs() < 1e-3 && (a.1 - b.1).abs() < 1e-3);
            }
        }
    }

    #[test]
    fn fence_has_holes_wires_and_soft_edges() {
        let img = wire_fence();
        let alpha: Vec<u8> = img.rgba.chunks(4).map(|p| p[3]).collect();
        assert!(alpha.contains(&0));
        assert!(alpha.contains(&255));
        assert!(alpha.iter().any(|&a| a > 0 && a < 255));
    }

    #[test]
    fn png_round_trips() {
        let img = checker();
        let bytes = encode_png(&img).unwrap();
        let back = image::load_from_memory(&bytes).unwrap().to_rgba8();
        assert_eq!(back.dimensions(), (256, 256));
        assert_eq!(back.as_raw(), &img.rgba);
    }
}
