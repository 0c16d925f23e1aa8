//! The skull as one signed-distance function.
//!
//! Each bone (or group of bones) is a small function below, built from the
//! primitives in [`crate::sdf`] and blended with smooth minimum / smooth
//! subtraction. Convention: right-handed, +Y up, the face looks toward +Z,
//! about 2 units from the top of the cranium to the chin. Bilateral parts are
//! modelled for +X only and mirrored with [`mirror_x`].

use glam::{Vec2, Vec3, vec2, vec3};

use crate::sdf::{
    bar, box_bound, capsule, ellipsoid, extrude, mirror_x, polygon, round_box, round_cone,
    round_rect, smax, smin, sphere, ssub,
};

/// Scale applied to the finished mesh: a slightly broader, deeper skull
/// than the anatomical proportions the parts below are modelled in.
pub const PROPORTIONS: Vec3 = vec3(1.08, 1.0, 1.05);

/// How far the mandible is rotated open about the jaw joints, in radians.
const JAW_OPEN: f32 = 0.06;
/// Point on the axis through both jaw joints (the condyles).
const JAW_PIVOT: Vec3 = vec3(0.0, -0.3, -0.12);

/// A planar curve in the horizontal (x, z) plane, as a dense polyline.
struct Path {
    points: Vec<Vec2>,
    /// Arc length from the first point to each point.
    lengths: Vec<f32>,
}

impl Path {
    /// Catmull-Rom spline through `ctrl` (x, z), starting on the midline
    /// (x = 0) with a tangent perpendicular to it, so mirroring is seamless.
    fn spline(ctrl: &[Vec2], per_span: usize) -> Path {
        let n = ctrl.len();
        let get = |i: isize| -> Vec2 {
            if i < 0 {
                vec2(-ctrl[1].x, ctrl[1].y)
            } else if i as usize >= n {
                2.0 * ctrl[n - 1] - ctrl[n - 2]
            } else {
                ctrl[i as usize]
            }
        };
        let mut points = Vec::new();
        for span in 0..n - 1 {
            let i = span as isize;
            let (p0, p1, p2, p3) = (get(i - 1), get(i), get(i + 1), get(i + 2));
            for s in 0..per_span {
                let t = s as f32 / per_span as f32;
                let t2 = t * t;
                let t3 = t2 * t;
                points.push(
                    0.5 * ((2.0 * p1)
                        + (p2 - p0) * t
                        + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t2
                        + (3.0 * p1 - p0 - 3.0 * p2 + p3) * t3),
                );
            }
        }
        points.push(ctrl[n - 1]);
        let mut lengths = vec![0.0];
        for w in points.windows(2) {
            lengths.push(lengths.last().copied().unwrap_or(0.0) + (w[1] - w[0]).length());
        }
        Path { points, lengths }
    }

    fn length(&self) -> f32 {
        self.lengths.last().copied().unwrap_or(0.0)
    }

    /// Position and unit tangent at arc length `s`.
    fn at(&self, s: f32) -> (Vec2, Vec2) {
        let i = self
            .lengths
            .partition_point(|&l| l <= s)
            .clamp(1, self.points.len() - 1);
        let (a, b) = (self.points[i - 1], self.points[i]);
        let seg = self.lengths[i] - self.lengths[i - 1];
        let t = ((s - self.lengths[i - 1]) / seg).clamp(0.0, 1.0);
        (a.lerp(b, t), (b - a) / seg)
    }

    /// Distance from `q` to the curve and the arc length of the closest point.
    fn closest(&self, q: Vec2) -> (f32, f32) {
        let mut best = (f32::MAX, 0.0);
        for i in 1..self.points.len() {
            let (a, b) = (self.points[i - 1], self.points[i]);
            let ab = b - a;
            let t = ((q - a).dot(ab) / ab.length_squared()).clamp(0.0, 1.0);
            let d2 = (q - a - ab * t).length_squared();
            if d2 < best.0 {
                best = (
                    d2,
                    self.lengths[i - 1] + t * (self.lengths[i] - self.lengths[i - 1]),
                );
            }
        }
        (best.0.sqrt(), best.1)
    }
}

/// One tooth crown (plus a stub of root sunk into the jaw bone).
struct Tooth {
    centre: Vec3,
    /// Unit vectors: along the dental arch, and outward (toward the lips).
    along: Vec3,
    out: Vec3,
    half: Vec3,
    /// +1 when the biting edge is below the centre (upper teeth), -1 otherwise.
    tip_dir: f32,
    bound: f32,
    /// The root, as a tapered capsule from the gum line into the jaw bone;
    /// it shows as a low ridge on the bone (the alveolar yokes).
    root: (Vec3, Vec3, f32, f32),
}

impl Tooth {
    fn distance(&self, p: Vec3) -> f32 {
        let d = p - self.centre;
        let far = d.length() - self.bound;
        if far > 0.05 {
            return far;
        }
        // Crowns narrow toward the biting edge (chisel-shaped incisors).
        let v = -d.y * self.tip_dir;
        let taper = 1.0 + 0.35 * (v / self.half.y).max(0.0);
        let q = vec3(d.dot(self.along), d.y, d.dot(self.out) * taper);
        let r = self.half.x.min(self.half.z) * 0.5;
        round_box(q, self.half, r) / taper.sqrt()
    }

    fn root_distance(&self, p: Vec3) -> f32 {
        let (a, b, ra, rb) = self.root;
        let far = (p - 0.5 * (a + b)).length() - 0.5 * (b - a).length() - ra;
        if far > 0.05 {
            return far;
        }
        round_cone(p, a, b, ra, rb)
    }
}

/// Places the teeth of one half jaw along `arch`, from the midline back.
/// `widths` are crown widths along the arch, `depths` labio-lingual half
/// thicknesses; crowns span from `gum` to the biting plane `tip[i]`.
fn place_teeth(arch: &Path, widths: &[f32], depths: &[f32], tips: &[f32], gum: f32) -> Vec<Tooth> {
    let mut s = 0.0;
    let mut teeth = Vec::new();
    let root = 0.06 * (gum - tips[0]).signum();
    for i in 0..widths.len() {
        let w = widths[i];
        let (pos, tangent) = arch.at(s + 0.5 * w);
        s += w;
        let along = vec3(tangent.x, 0.0, tangent.y);
        let out = vec3(-tangent.y, 0.0, tangent.x);
        let top = gum + root;
        let half = vec3(0.5 * w - 0.004, 0.5 * (top - tips[i]).abs(), depths[i]);
        let base =
            vec3(pos.x, gum + 0.03 * (gum - tips[i]).signum(), pos.y) + out * (0.45 * depths[i]);
        let lower = gum < tips[i];
        let root_len = if lower {
            0.08
        } else if i == 2 {
            0.2
        } else {
            0.14
        };
        teeth.push(Tooth {
            root: (
                base,
                base + vec3(0.0, root_len * (gum - tips[i]).signum(), 0.0) - out * 0.02,
                0.27 * w,
                0.12 * w,
            ),
            centre: vec3(pos.x, 0.5 * (top + tips[i]), pos.y),
            along,
            out,
            half,
            tip_dir: (top - tips[i]).signum(),
            bound: half.length(),
        });
    }
    teeth
}

/// The whole skull: cranium with the upper face and teeth, plus the
/// mandible, which stays a separate closed piece.
pub struct Skull {
    upper_arch: Path,
    mandible_path: Path,
    upper_teeth: Vec<Tooth>,
    lower_teeth: Vec<Tooth>,
}

impl Default for Skull {
    fn default() -> Self {
        Self::new()
    }
}

impl Skull {
    pub fn new() -> Skull {
        let upper_arch = Path::spline(
            &[
                vec2(0.0, 0.735),
                vec2(0.125, 0.705),
                vec2(0.21, 0.615),
                vec2(0.255, 0.48),
                vec2(0.275, 0.34),
                vec2(0.29, 0.2),
            ],
            12,
        );
        let lower_arch = Path::spline(
            &[
                vec2(0.0, 0.705),
                vec2(0.115, 0.675),
                vec2(0.195, 0.59),
                vec2(0.24, 0.46),
                vec2(0.26, 0.32),
                vec2(0.275, 0.18),
            ],
            12,
        );
        let mandible_path = Path::spline(
            &[
                vec2(0.0, 0.70),
                vec2(0.115, 0.67),
                vec2(0.195, 0.585),
                vec2(0.24, 0.455),
                vec2(0.27, 0.3),
                vec2(0.32, 0.14),
                vec2(0.38, 0.03),
                vec2(0.43, -0.04),
            ],
            10,
        );
        // Central incisor .. third molar.
        let upper_teeth = place_teeth(
            &upper_arch,
            &[0.074, 0.057, 0.066, 0.061, 0.058, 0.085, 0.078, 0.07],
            &[0.03, 0.028, 0.036, 0.04, 0.04, 0.048, 0.046, 0.044],
            &[-0.70, -0.695, -0.705, -0.69, -0.688, -0.686, -0.684, -0.68],
            -0.605,
        );
        let lower_teeth = place_teeth(
            &lower_arch,
            &[0.046, 0.05, 0.06, 0.06, 0.06, 0.095, 0.09, 0.085],
            &[0.026, 0.027, 0.033, 0.037, 0.038, 0.045, 0.045, 0.043],
            &[
                -0.665, -0.668, -0.675, -0.688, -0.69, -0.692, -0.694, -0.696,
            ],
            -0.775,
        );
        Skull {
            upper_arch,
            mandible_path,
            upper_teeth,
            lower_teeth,
        }
    }

    /// Signed distance to the skull surface.
    pub fn distance(&self, p: Vec3) -> f32 {
        let (s, c) = JAW_OPEN.sin_cos();
        let r = p - JAW_PIVOT;
        // Undo the jaw opening (a rotation about the X axis) to evaluate the
        // mandible in its closed pose.
        let closed = JAW_PIVOT + vec3(r.x, r.y * c + r.z * s, -r.y * s + r.z * c);
        let mandible = self.mandible(closed);
        // Keep a thin gap around the mandible so it stays a separate piece.
        let upper = self.cranium_and_face(p).max(JAW_GAP - mandible);
        upper.min(mandible)
    }

    /// Cranium, upper face and upper teeth: one piece of bone.
    fn cranium_and_face(&self, p: Vec3) -> f32 {
        let q = mirror_x(p);
        let mut d = braincase(p);
        d = smin(d, skull_base(q), 0.15);
        d = smin(d, orbital_block(p), 0.16);
        d = smin(d, brow_ridge(q), 0.08);
        d = smin(d, maxilla(p), 0.12);
        d = smin(d, self.upper_jaw(q), 0.08);
        d = smin(d, roots(&self.upper_teeth, q), 0.02);
        d = smin(d, zygomatic_bone(q), 0.08);
        d = temporal_fossa(d, q);
        d = smin(d, zygomatic_arch(q), 0.04);
        d = smin(d, nasal_bones(p), 0.06);
        d = ssub(d, orbit(q), 0.025);
        d = ssub(d, nasal_aperture(q), 0.02);
        d = d.min(nasal_septum(p));
        d = ssub(d, ear_canal(q), 0.02);
        d.min(teeth(&self.upper_teeth, q))
    }

    /// Alveolar process and lateral wall of the maxilla: a horseshoe of
    /// bone holding the upper teeth, widening toward the cheekbones above
    /// the molars.
    fn upper_jaw(&self, q: Vec3) -> f32 {
        let bound = box_bound(q, vec3(0.0, -0.7, 0.05), vec3(0.45, -0.22, 0.85));
        if bound > 0.1 {
            return bound;
        }
        let (dh, s) = self.upper_arch.closest(vec2(q.x, q.z));
        let f = s / self.upper_arch.length();
        let (bottom, top) = (-0.61, -0.3);
        let up = ((q.y - bottom) / (top - bottom)).clamp(0.0, 1.0);
        let half_t = 0.036 + 0.02 * f + (0.02 + 0.05 * f) * up;
        round_rect(
            vec2(dh, q.y - 0.5 * (top + bottom)),
            vec2(half_t, 0.5 * (top - bottom)),
            0.035,
        )
    }

    /// Mandible (lower jaw) with its teeth, in the closed-jaw pose.
    fn mandible(&self, p: Vec3) -> f32 {
        // Cheap lower bound far from the jaw (its top is below y = -0.25).
        let bound = box_bound(p, vec3(-0.62, -1.15, -0.3), vec3(0.62, -0.2, 0.85));
        if bound > 0.1 {
            return bound;
        }
        let q = mirror_x(p);
        let mut d = self.mandible_body(q);
        d = smin(d, mandible_ramus(q), 0.05);
        d = smin(d, chin(q), 0.05);
        d = smin(d, roots(&self.lower_teeth, q), 0.02);
        d.min(teeth(&self.lower_teeth, q))
    }

    /// Body of the mandible: a rounded band swept along the jaw line,
    /// tall at the chin and lower toward the angle of the jaw.
    fn mandible_body(&self, q: Vec3) -> f32 {
        let bound = box_bound(q, vec3(0.0, -1.05, -0.15), vec3(0.5, -0.7, 0.8));
        if bound > 0.1 {
            return bound;
        }
        let (dh, s) = self.mandible_path.closest(vec2(q.x, q.z));
        let f = s / self.mandible_path.length();
        let top = -0.765;
        let bottom = -1.0 + 0.17 * f;
        let half_t = 0.05 - 0.018 * f;
        round_rect(
            vec2(dh, q.y - 0.5 * (top + bottom)),
            vec2(half_t, 0.5 * (top - bottom)),
            0.035,
        )
    }
}

/// Clearance kept between the mandible and the rest of the skull.
const JAW_GAP: f32 = 0.045;

/// Roots of one jaw's teeth, to be blended into the bone that holds them.
fn roots(row: &[Tooth], q: Vec3) -> f32 {
    let bound = box_bound(q, vec3(0.0, -0.95, 0.05), vec3(0.4, -0.35, 0.85));
    if bound > 0.1 {
        return bound;
    }
    row.iter()
        .map(|t| t.root_distance(q))
        .fold(f32::MAX, f32::min)
}

/// Teeth of one jaw (union of crowns), with a cheap bound around the row.
fn teeth(row: &[Tooth], q: Vec3) -> f32 {
    let bound = box_bound(q, vec3(0.0, -0.85, 0.05), vec3(0.4, -0.5, 0.85));
    if bound > 0.1 {
        return bound;
    }
    row.iter().map(|t| t.distance(q)).fold(f32::MAX, f32::min)
}

/// Neurocranium: frontal, parietal and occipital bones as blended
/// ellipsoids, broader and fuller toward the back.
fn braincase(p: Vec3) -> f32 {
    let main = ellipsoid(p, vec3(0.0, 0.30, -0.06), vec3(0.58, 0.70, 0.79));
    let back = ellipsoid(p, vec3(0.0, 0.28, -0.24), vec3(0.63, 0.62, 0.6));
    let front = ellipsoid(p, vec3(0.0, 0.32, 0.22), vec3(0.50, 0.62, 0.56));
    // Occipital bone curving down under the back toward the skull base.
    let occiput = ellipsoid(p, vec3(0.0, -0.02, -0.45), vec3(0.42, 0.32, 0.38));
    smin(smin(smin(main, back, 0.2), front, 0.2), occiput, 0.15)
}

/// Cranial base with the temporal bones and mastoid processes, so the
/// skull has a floor for the jaw joints to sit under.
fn skull_base(q: Vec3) -> f32 {
    let base = ellipsoid(q, vec3(0.0, -0.1, -0.22), vec3(0.46, 0.26, 0.44));
    let temporal = ellipsoid(q, vec3(0.36, -0.14, -0.16), vec3(0.16, 0.16, 0.24));
    let mastoid = round_cone(
        q,
        vec3(0.42, -0.22, -0.3),
        vec3(0.44, -0.4, -0.28),
        0.07,
        0.03,
    );
    smin(smin(base, temporal, 0.12), mastoid, 0.08)
}

/// Frontal bone around the orbits and the upper maxilla: the solid block
/// the orbits are carved from.
fn orbital_block(p: Vec3) -> f32 {
    ellipsoid(p, vec3(0.0, -0.1, 0.45), vec3(0.48, 0.3, 0.33))
}

/// Temporal fossa: the hollow at the temple, behind the orbit and above
/// the zygomatic arch, continuing below the arch (infratemporal fossa).
fn temporal_fossa(d: f32, q: Vec3) -> f32 {
    let temple = ellipsoid(q, vec3(0.7, 0.0, 0.15), vec3(0.2, 0.3, 0.28));
    let below = ellipsoid(q, vec3(0.58, -0.45, 0.12), vec3(0.18, 0.2, 0.25));
    ssub(d, smin(temple, below, 0.1), 0.1)
}

/// Supraorbital ridge of the frontal bone (the brow): a soft bulge.
fn brow_ridge(q: Vec3) -> f32 {
    let arch = ellipsoid(q, vec3(0.2, 0.09, 0.69), vec3(0.24, 0.07, 0.1));
    let glabella = ellipsoid(q, vec3(0.0, 0.06, 0.73), vec3(0.1, 0.08, 0.07));
    smin(arch, glabella, 0.06)
}

/// Nasal bones: the bridge of the nose between the orbits.
fn nasal_bones(p: Vec3) -> f32 {
    bar(
        p,
        vec3(0.0, 0.02, 0.76),
        vec3(0.0, -0.17, 0.8),
        0.04,
        0.045,
        0.035,
    )
}

/// Maxilla: the upper jaw block below the orbits and around the nose.
fn maxilla(p: Vec3) -> f32 {
    ellipsoid(p, vec3(0.0, -0.4, 0.44), vec3(0.28, 0.2, 0.3))
}

/// Zygomatic bone: the cheekbone body and its frontal process, which forms
/// the outer rim of the orbit.
fn zygomatic_bone(q: Vec3) -> f32 {
    let body = bar(
        q,
        vec3(0.32, -0.28, 0.63),
        vec3(0.55, -0.27, 0.42),
        0.065,
        0.05,
        0.045,
    );
    let rim = round_cone(
        q,
        vec3(0.48, -0.22, 0.5),
        vec3(0.47, 0.06, 0.6),
        0.045,
        0.05,
    );
    // Zygomatic buttress down to the maxilla above the first molar.
    let buttress = round_cone(
        q,
        vec3(0.5, -0.3, 0.46),
        vec3(0.36, -0.47, 0.42),
        0.05,
        0.04,
    );
    smin(smin(body, rim, 0.08), buttress, 0.08)
}

/// Zygomatic arch: the flat bar of bone running back from the cheekbone to
/// the temporal bone in front of the ear.
fn zygomatic_arch(q: Vec3) -> f32 {
    let front = bar(
        q,
        vec3(0.53, -0.26, 0.43),
        vec3(0.57, -0.24, 0.06),
        0.045,
        0.022,
        0.02,
    );
    let back = bar(
        q,
        vec3(0.57, -0.24, 0.06),
        vec3(0.47, -0.22, -0.05),
        0.04,
        0.022,
        0.02,
    );
    smin(front, back, 0.04)
}

/// Orbit (eye socket): a rounded-square opening, tilted down at the outer
/// side, narrowing to a deep funnel.
fn orbit(q: Vec3) -> f32 {
    let (s, c) = 0.12f32.sin_cos();
    let d = q - vec3(0.27, -0.085, 0.74);
    let tilted = vec3(c * d.x + s * d.y, -s * d.x + c * d.y, d.z);
    let rim = round_box(tilted, vec3(0.17, 0.165, 0.1), 0.09);
    let funnel = round_cone(
        q,
        vec3(0.26, -0.085, 0.68),
        vec3(0.14, -0.065, 0.2),
        0.15,
        0.02,
    );
    smin(rim, funnel, 0.05)
}

/// Piriform aperture (nasal opening): narrow at the top, two lobes at the
/// bottom (the inverted heart), tapering into the nasal cavity.
fn nasal_aperture(q: Vec3) -> f32 {
    // The outline shrinks with depth, so the walls lean inward.
    let depth = (0.8 - q.z).max(0.0);
    let scale = 1.0 - 1.1 * depth;
    let centre = vec2(0.0, -0.31);
    let xy = (vec2(q.x, q.y) - centre) / scale + centre;
    let pear = round_cone(
        vec3(xy.x, xy.y, 0.0),
        vec3(0.0, -0.19, 0.0),
        vec3(0.0, -0.36, 0.0),
        0.025,
        0.09,
    );
    let lobe = sphere(vec3(xy.x, xy.y, 0.0), vec3(0.055, -0.39, 0.0), 0.07);
    let outline = smin(pear, lobe, 0.04) * scale;
    smax(outline, 0.3 - q.z, 0.05)
}

/// Nasal septum (vomer), set back inside the aperture, and the anterior
/// nasal spine at its bottom edge.
fn nasal_septum(p: Vec3) -> f32 {
    let septum = round_box(p - vec3(0.0, -0.345, 0.46), vec3(0.008, 0.08, 0.14), 0.006);
    let spine = round_cone(
        p,
        vec3(0.0, -0.455, 0.7),
        vec3(0.0, -0.45, 0.79),
        0.022,
        0.006,
    );
    septum.min(spine)
}

/// External acoustic meatus: the ear hole in the temporal bone.
fn ear_canal(q: Vec3) -> f32 {
    capsule(q, vec3(0.7, -0.21, -0.24), vec3(0.4, -0.21, -0.24), 0.035)
}

/// Ramus of the mandible, an upright plate whose outline has the condylar
/// neck behind and the coronoid process in front, with the mandibular notch
/// between, topped by the condyle (the jaw joint).
fn mandible_ramus(q: Vec3) -> f32 {
    let bound = box_bound(q, vec3(0.3, -0.95, -0.25), vec3(0.6, -0.22, 0.3));
    if bound > 0.1 {
        return bound;
    }
    // Outline in the (z, y) plane: angle, anterior border, coronoid
    // process, mandibular notch, condylar neck, posterior border.
    const OUTLINE: [Vec2; 17] = [
        vec2(0.0, -0.855),
        vec2(0.24, -0.88),
        vec2(0.2, -0.74),
        vec2(0.15, -0.58),
        vec2(0.13, -0.42),
        vec2(0.12, -0.35),
        vec2(0.09, -0.39),
        vec2(0.04, -0.46),
        vec2(-0.01, -0.48),
        vec2(-0.05, -0.42),
        vec2(-0.08, -0.34),
        vec2(-0.14, -0.34),
        vec2(-0.13, -0.5),
        vec2(-0.11, -0.68),
        vec2(-0.095, -0.77),
        vec2(-0.07, -0.82),
        vec2(-0.04, -0.845),
    ];
    // The plate carries on from the end of the jaw line (the rami diverge
    // toward the back) and flares outward toward the top.
    let mid_x = 0.43 - 0.2 * (q.z + 0.04) + 0.025 * ((q.y + 0.85) / 0.45).clamp(0.0, 1.0);
    let across = (q.x - mid_x) * 0.98;
    let plate = extrude(polygon(vec2(q.z, q.y), &OUTLINE) - 0.015, across, 0.01) - 0.016;
    // Thickened borders: posterior (angle to condyle) and anterior
    // (body to coronoid tip).
    let back = round_cone(
        q,
        vec3(0.43, -0.83, -0.06),
        vec3(0.46, -0.36, -0.11),
        0.038,
        0.03,
    );
    let front = round_cone(
        q,
        vec3(0.39, -0.8, 0.21),
        vec3(0.42, -0.37, 0.12),
        0.032,
        0.014,
    );
    let condyle = ellipsoid(q, vec3(0.48, -0.3, -0.12), vec3(0.09, 0.045, 0.06));
    let d = smin(smin(plate, back, 0.04), front, 0.04);
    smin(d, condyle, 0.04)
}

/// Mental protuberance: the chin.
fn chin(q: Vec3) -> f32 {
    let centre = ellipsoid(q, vec3(0.0, -0.94, 0.70), vec3(0.12, 0.07, 0.05));
    let tubercle = sphere(q, vec3(0.08, -0.96, 0.68), 0.05);
    smin(centre, tubercle, 0.04)
}
