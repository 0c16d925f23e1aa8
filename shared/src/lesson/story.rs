//! One pixel's story: what each step and each draw of a frame did to one pixel's colour, depth and
//! stencil, with the tests written out in that pixel's numbers.
//!
//! The numbers are the GPU's: the values before and after every draw are read back from the GPU,
//! and so is what each fragment brought (its *twin*, the same draw with no tests, left its colour
//! and depth in the pixel). The CPU model of the tests ([`crate::math::stencil`] and the depth
//! comparison beside it) only writes out why: [`DrawStory::predicted`] says what the written-out
//! tests make of the values before, and a test checks that it is what the GPU stored.

use std::fmt::Write as _;

use wgpu::{BlendFactor, BlendOperation, CompareFunction, StencilOperation};

use crate::gpu::srgb_to_linear;
use crate::gpu::states::Recipe;
use crate::lesson::knobs::Knobs;
use crate::math::stencil;
use crate::room::camera::Camera;

/// A pixel's three values, as the buffers hold them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Texel {
    /// The colour as stored: sRGB-encoded bytes, and alpha.
    pub color: [u8; 4],
    /// The depth, 0 (near) to 1 (far).
    pub depth: f32,
    pub stencil: u8,
}

/// A whole frame at one pixel.
#[derive(Debug, Clone)]
pub struct Story {
    /// The lesson's package name.
    pub lesson: &'static str,
    pub pixel: (u32, u32),
    pub size: (u32, u32),
    /// The knob settings and options that made the frame, as a command line gives them.
    pub settings: String,
    pub steps: Vec<StepStory>,
}

/// One step at the pixel.
#[derive(Debug, Clone)]
pub struct StepStory {
    pub name: &'static str,
    /// The pixel after the step (read back from the GPU).
    pub after: Texel,
    /// Whether the step drew into a target of the lesson's own (a reflection texture), leaving the
    /// frame's buffers alone.
    pub into_own_target: bool,
    pub draws: Vec<DrawStory>,
}

/// One draw of a step at the pixel.
#[derive(Debug, Clone)]
pub struct DrawStory {
    /// The recipe of the draw's pipeline, and the object drawn.
    pub recipe: Option<Recipe>,
    pub object: Option<&'static str>,
    pub reference: u32,
    pub blend_constant: wgpu::Color,
    /// The pixel before the draw and after it (both read back from the GPU).
    pub before: Texel,
    pub after: Texel,
    /// What each of the draw's fragments at the pixel brought, in the order the GPU met them
    /// (read from the draw's twin): none where the draw does not cover the pixel, more than one
    /// where its triangles overlap there (a flattened skull, a box drawn with both faces).
    pub fragments: Vec<Fragment>,
    /// Whether the step's scissor rectangle leaves the pixel out: the draw is not rasterized there.
    pub outside_scissor: bool,
    /// Whether a fragment passed both tests, by the GPU's own count (an occlusion query).
    pub passed: bool,
}

/// What a fragment brings to its pixel: its colour (as the twin stored it) and its depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fragment {
    pub color: [u8; 4],
    pub depth: f32,
    /// Whether it lies on its triangle's front face; read only for a recipe whose two faces
    /// have stencil states of their own (`None` otherwise: the front face's state serves both).
    pub front: Option<bool>,
}

/// Whether a recipe's stencil treats front and back faces differently, so that a fragment's
/// story must know which face it lies on.
pub fn two_sided(recipe: &Recipe) -> bool {
    recipe.stencil.front != recipe.stencil.back
}

/// How far the stored depth may lie from the predicted one: 16 steps of the 24-bit buffer. The twin
/// is another pipeline with the same vertex shader; a GPU need not compute the very same depth in
/// both to the last bit (WGSL's `@invariant` would promise it, and the lessons do not need it).
pub const DEPTH_TOLERANCE: f32 = 16.0 / (1 << 24) as f32;

/// Which test stopped a fragment, if one did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    StencilFails,
    DepthFails,
    Passes,
}

/// One fragment met by the tests, in the model: the verdict, the stencil operation it chose
/// with the value it stores, and the pixel after it.
#[derive(Debug, Clone, Copy)]
pub struct Outcome {
    pub before: Texel,
    pub verdict: Verdict,
    pub operation: Option<(StencilOperation, u8)>,
    pub after: Texel,
}

impl DrawStory {
    /// Each fragment in turn through the written-out tests, from the pixel before the draw (`None`
    /// for a draw of a pipeline the workbook did not bake: no recipe to read).
    pub fn outcomes(&self) -> Option<Vec<Outcome>> {
        let recipe = self.recipe.as_ref()?;
        let mut pixel = self.before;
        let mut outcomes = Vec::new();
        for fragment in &self.fragments {
            let outcome = self.meet(recipe, pixel, fragment);
            pixel = outcome.after;
            outcomes.push(outcome);
        }
        Some(outcomes)
    }

    /// Whether any fragment passed both tests, by the model.
    pub fn any_passes(&self) -> bool {
        let outcomes = self.outcomes().unwrap_or_default();
        outcomes.iter().any(|o| o.verdict == Verdict::Passes)
    }

    /// Whether any fragment was stopped by `verdict`'s test, by the model.
    pub fn any(&self, verdict: Verdict) -> bool {
        let outcomes = self.outcomes().unwrap_or_default();
        outcomes.iter().any(|o| o.verdict == verdict)
    }

    /// One fragment against the pixel as it is: the stencil test `(reference & read mask) CMP
    /// (stored & read mask)`, then the depth test `fragment CMP stored`, the stencil operation
    /// they choose (through the write mask), the depth write, and the colour written or blended.
    fn meet(&self, recipe: &Recipe, pixel: Texel, fragment: &Fragment) -> Outcome {
        let state = &recipe.stencil;
        let face = match fragment.front {
            Some(false) => &state.back,
            _ => &state.front,
        };
        let reference = self.reference as u8;
        let verdict = if !stencil::passes(
            face.compare,
            reference,
            state.read_mask as u8,
            pixel.stencil,
        ) {
            Verdict::StencilFails
        } else if !compares(recipe.depth_compare, fragment.depth, pixel.depth) {
            Verdict::DepthFails
        } else {
            Verdict::Passes
        };
        let operation = match verdict {
            Verdict::StencilFails => face.fail_op,
            Verdict::DepthFails => face.depth_fail_op,
            Verdict::Passes => face.pass_op,
        };
        let new = stencil::apply(operation, pixel.stencil, reference);
        let stored = stencil::write(pixel.stencil, new, state.write_mask as u8);
        let mut after = Texel {
            stencil: stored,
            ..pixel
        };
        if verdict == Verdict::Passes {
            if recipe.depth_write {
                after.depth = fragment.depth;
            }
            let blended = blend(recipe, fragment.color, pixel.color, self.blend_constant);
            let channels = [
                wgpu::ColorWrites::RED,
                wgpu::ColorWrites::GREEN,
                wgpu::ColorWrites::BLUE,
                wgpu::ColorWrites::ALPHA,
            ];
            for (channel, bit) in channels.into_iter().enumerate() {
                if recipe.color_writes.contains(bit) {
                    after.color[channel] = blended[channel];
                }
            }
        }
        let writes = state.write_mask != 0 && operation != StencilOperation::Keep;
        Outcome {
            before: pixel,
            verdict,
            operation: writes.then_some((operation, stored)),
            after,
        }
    }

    /// The pixel after the draw, as the written-out tests predict it.
    pub fn predicted(&self) -> Option<Texel> {
        let outcomes = self.outcomes()?;
        Some(outcomes.last().map_or(self.before, |o| o.after))
    }

    /// Whether the GPU stored what the model predicts (colours within 3 of 255: the GPU blends the
    /// fragment's colour before it is rounded to the 8 bits the twin stored), and counted a passing
    /// fragment where the model has one. A draw of a pipeline the workbook did not bake has no
    /// recipe to predict from: it does not agree (its story says it cannot be checked).
    pub fn agrees(&self) -> bool {
        let Some(predicted) = self.predicted() else {
            return false;
        };
        let colours = predicted
            .color
            .iter()
            .zip(self.after.color)
            .all(|(a, b)| a.abs_diff(b) <= 3);
        colours
            && (predicted.depth - self.after.depth).abs() <= DEPTH_TOLERANCE
            && predicted.stencil == self.after.stencil
            && self.any_passes() == self.passed
    }

    /// The draw's lines in the story: what it is, and for each fragment each test with this
    /// pixel's numbers.
    pub fn describe(&self) -> Vec<String> {
        let name = match (&self.recipe, self.object) {
            (Some(recipe), Some(object)) => format!("{} · {object}", recipe.name),
            (Some(recipe), None) => recipe.name.to_string(),
            (None, Some(object)) => format!("(a pipeline of its own) · {object}"),
            (None, None) => "(a pipeline of its own)".to_string(),
        };
        let count = self.fragments.len();
        if count == 0 && self.outside_scissor {
            return vec![format!(
                "{name}: not drawn here, outside the step's scissor rectangle"
            )];
        }
        if count == 0 {
            return vec![format!("{name}: does not reach this pixel")];
        }
        let (Some(recipe), Some(outcomes)) = (&self.recipe, self.outcomes()) else {
            return vec![format!(
                "{name}: {count} fragment(s) reach this pixel; with no recipe to read, its tests \
                 cannot be written out or checked"
            )];
        };
        let mut lines = vec![name];
        for (index, (fragment, outcome)) in self.fragments.iter().zip(&outcomes).enumerate() {
            let mut which = match count {
                1 => "a fragment".to_string(),
                _ => format!("fragment {} of {count}", index + 1),
            };
            if let Some(front) = fragment.front {
                which += if front {
                    " (front face)"
                } else {
                    " (back face)"
                };
            }
            lines.push(format!(
                "{which}: {} at depth {:.5}",
                hex(fragment.color),
                fragment.depth
            ));
            lines.extend(
                self.describe_outcome(recipe, fragment, outcome)
                    .into_iter()
                    .map(|l| format!("  {l}")),
            );
        }
        if !self.agrees() {
            let predicted = self.predicted().expect("a recipe");
            lines.push(format!(
                "the GPU stored {} {:.5} {}, the tests above predict {} {:.5} {}",
                hex(self.after.color),
                self.after.depth,
                self.after.stencil,
                hex(predicted.color),
                predicted.depth,
                predicted.stencil
            ));
        }
        lines
    }

    fn describe_outcome(
        &self,
        recipe: &Recipe,
        fragment: &Fragment,
        outcome: &Outcome,
    ) -> Vec<String> {
        let (pixel, mut lines) = (outcome.before, Vec::new());
        let stencil = &recipe.stencil;
        let tests_stencil = stencil.front.compare != CompareFunction::Always;
        let stencil_passes = outcome.verdict != Verdict::StencilFails;
        if tests_stencil {
            let (reference, mask) = (self.reference as u8, stencil.read_mask as u8);
            lines.push(format!(
                "stencil test ({reference} & {mask:#04X}) {:?} ({} & {mask:#04X}) → {}",
                stencil.front.compare,
                pixel.stencil,
                pass_fail(stencil_passes)
            ));
        } else {
            lines.push("stencil test: none (Always)".to_string());
        }
        if !stencil_passes {
            lines.push("depth test: not reached".to_string());
        } else if recipe.depth_compare == CompareFunction::Always {
            lines.push("depth test: none (Always)".to_string());
        } else {
            lines.push(format!(
                "depth test {:.5} {:?} {:.5} → {}",
                fragment.depth,
                recipe.depth_compare,
                pixel.depth,
                pass_fail(outcome.verdict == Verdict::Passes)
            ));
        }
        match outcome.operation {
            Some((operation, stored)) => {
                let mask = match stencil.write_mask {
                    0xff => String::new(),
                    mask => format!(", write mask {mask:#04X}"),
                };
                lines.push(format!(
                    "stencil {operation:?} {} → {stored}{mask}",
                    pixel.stencil
                ));
            }
            None if tests_stencil || stencil.write_mask != 0 => {
                lines.push("stencil Keep".to_string())
            }
            None => {}
        }
        if outcome.verdict == Verdict::Passes {
            lines.push(self.describe_colour(recipe, fragment, outcome));
        } else {
            lines.push("colour: not written (the fragment was rejected)".to_string());
        }
        lines
    }

    fn describe_colour(&self, recipe: &Recipe, fragment: &Fragment, outcome: &Outcome) -> String {
        if recipe.color_writes.is_empty() {
            return "colour: none written (write mask empty)".to_string();
        }
        let Some(blend) = recipe.blend else {
            return format!("colour written {}", hex(fragment.color));
        };
        let (src, dst) = (fragment.color, outcome.before.color);
        let factor = |factor| factor_text(factor, src, dst, self.blend_constant);
        let (s, d) = (
            factor(blend.color.src_factor),
            factor(blend.color.dst_factor),
        );
        let operation = match blend.color.operation {
            BlendOperation::Add => "+",
            BlendOperation::Subtract => "−",
            BlendOperation::ReverseSubtract => "(reversed) −",
            BlendOperation::Min => "min",
            BlendOperation::Max => "max",
        };
        format!(
            "colour blended {s}·src {operation} {d}·dst = {s}·{} {operation} {d}·{} → {}",
            hex(src),
            hex(dst),
            hex(outcome.after.color)
        )
    }
}

impl Story {
    /// What a story's header says it was told with: the knobs changed from their defaults, and the
    /// camera where it is not the lesson's own (`lesson_camera`), as `--pixel` and the page tell it.
    pub fn settings(knobs: &Knobs, camera: Camera, lesson_camera: Camera) -> String {
        let mut settings = Vec::new();
        if !knobs.changed().is_empty() {
            settings.push(knobs.changed());
        }
        if camera != lesson_camera {
            settings.push(format!("camera {camera}"));
        }
        settings.join(", ")
    }

    /// The story as text: a header, then each step with its draws and the pixel after it.
    pub fn text(&self) -> String {
        let (x, y) = self.pixel;
        let (width, height) = self.size;
        let mut text = format!(
            "Pixel ({x}, {y}) of {} at {width}×{height}{}\n",
            self.lesson,
            match self.settings.as_str() {
                "" => String::new(),
                settings => format!(", {settings}"),
            }
        );
        text.push_str("colour is sRGB #rrggbb (alpha after the slash), depth 0 near to 1 far\n\n");
        for (index, step) in self.steps.iter().enumerate() {
            let after = step.after;
            let _ = writeln!(
                text,
                "{:>2} {:<40} {}  depth {:.5}  stencil {}",
                index + 1,
                step.name,
                hex(after.color),
                after.depth,
                after.stencil,
            );
            if step.into_own_target {
                text.push_str("     drawn into the lesson's own target: this pixel is untouched\n");
            }
            for draw in &step.draws {
                for (line, words) in draw.describe().into_iter().enumerate() {
                    let bullet = if line == 0 { "   · " } else { "       " };
                    let _ = writeln!(text, "{bullet}{words}");
                }
            }
        }
        text
    }
}

/// `fragment CMP stored`, the depth test.
pub fn compares(compare: CompareFunction, fragment: f32, stored: f32) -> bool {
    match compare {
        CompareFunction::Never => false,
        CompareFunction::Less => fragment < stored,
        CompareFunction::Equal => fragment == stored,
        CompareFunction::LessEqual => fragment <= stored,
        CompareFunction::Greater => fragment > stored,
        CompareFunction::NotEqual => fragment != stored,
        CompareFunction::GreaterEqual => fragment >= stored,
        CompareFunction::Always => true,
    }
}

fn pass_fail(passes: bool) -> &'static str {
    if passes { "pass" } else { "fail" }
}

/// A colour as `#rrggbb`, with `/aa` where alpha is not opaque.
pub fn hex([r, g, b, a]: [u8; 4]) -> String {
    match a {
        255 => format!("#{r:02x}{g:02x}{b:02x}"),
        _ => format!("#{r:02x}{g:02x}{b:02x}/{a:02x}"),
    }
}

/// The blend of a fragment's colour over the stored one, as the GPU does it: in linear light for
/// the colour channels (the target is sRGB), alpha as it is.
fn blend(recipe: &Recipe, src: [u8; 4], dst: [u8; 4], constant: wgpu::Color) -> [u8; 4] {
    let Some(state) = recipe.blend else {
        return src;
    };
    let linear = |[r, g, b, a]: [u8; 4]| {
        [
            srgb_to_linear(r),
            srgb_to_linear(g),
            srgb_to_linear(b),
            a as f32 / 255.0,
        ]
    };
    let (s, d) = (linear(src), linear(dst));
    let k = [constant.r, constant.g, constant.b, constant.a].map(|v| v as f32);
    let mut out = [0.0; 4];
    for channel in 0..4 {
        let component = if channel < 3 {
            state.color
        } else {
            state.alpha
        };
        let f = |factor| factor_value(factor, channel, &s, &d, &k);
        let (a, b) = (
            s[channel] * f(component.src_factor),
            d[channel] * f(component.dst_factor),
        );
        out[channel] = match component.operation {
            BlendOperation::Add => a + b,
            BlendOperation::Subtract => a - b,
            BlendOperation::ReverseSubtract => b - a,
            BlendOperation::Min => s[channel].min(d[channel]),
            BlendOperation::Max => s[channel].max(d[channel]),
        }
        .clamp(0.0, 1.0);
    }
    let encode = |v: f32| (v * 255.0).round() as u8;
    [
        encode(linear_to_srgb(out[0])),
        encode(linear_to_srgb(out[1])),
        encode(linear_to_srgb(out[2])),
        encode(out[3]),
    ]
}

/// A blend factor's value for one channel (0–2 colour, 3 alpha).
fn factor_value(
    factor: BlendFactor,
    channel: usize,
    s: &[f32; 4],
    d: &[f32; 4],
    k: &[f32; 4],
) -> f32 {
    match factor {
        BlendFactor::Zero => 0.0,
        BlendFactor::One => 1.0,
        BlendFactor::Src => s[channel],
        BlendFactor::OneMinusSrc => 1.0 - s[channel],
        BlendFactor::SrcAlpha => s[3],
        BlendFactor::OneMinusSrcAlpha => 1.0 - s[3],
        BlendFactor::Dst => d[channel],
        BlendFactor::OneMinusDst => 1.0 - d[channel],
        BlendFactor::DstAlpha => d[3],
        BlendFactor::OneMinusDstAlpha => 1.0 - d[3],
        BlendFactor::SrcAlphaSaturated if channel < 3 => s[3].min(1.0 - d[3]),
        BlendFactor::SrcAlphaSaturated => 1.0,
        BlendFactor::Constant => k[channel],
        BlendFactor::OneMinusConstant => 1.0 - k[channel],
        // Dual-source factors: no recipe of the workbook uses them.
        _ => f32::NAN,
    }
}

/// A colour blend factor as the story writes it: its value where it is the same for red, green and
/// blue, its name where it is not.
fn factor_text(factor: BlendFactor, src: [u8; 4], dst: [u8; 4], constant: wgpu::Color) -> String {
    let to_f32 = |c: [u8; 4]| c.map(|v| v as f32 / 255.0);
    let (s, d) = (to_f32(src), to_f32(dst));
    let k = [constant.r, constant.g, constant.b, constant.a].map(|v| v as f32);
    let values = [0, 1, 2].map(|channel| factor_value(factor, channel, &s, &d, &k));
    let per_channel = matches!(
        factor,
        BlendFactor::Src | BlendFactor::OneMinusSrc | BlendFactor::Dst | BlendFactor::OneMinusDst
    );
    if !per_channel && values.iter().all(|v| *v == values[0]) {
        format!("{:.3}", values[0])
            .trim_end_matches('0')
            .trim_end_matches('.')
            .to_string()
    } else {
        format!("{factor:?}")
    }
}

fn linear_to_srgb(c: f32) -> f32 {
    if c <= 0.003_130_8 {
        c * 12.92
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gpu::states;

    fn texel(color: [u8; 4], depth: f32, stencil: u8) -> Texel {
        Texel {
            color,
            depth,
            stencil,
        }
    }

    fn draw(
        recipe: Recipe,
        reference: u32,
        before: Texel,
        fragments: &[([u8; 4], f32)],
    ) -> DrawStory {
        DrawStory {
            recipe: Some(recipe),
            object: Some("the mirror"),
            reference,
            blend_constant: wgpu::Color::TRANSPARENT,
            before,
            after: before,
            fragments: fragments
                .iter()
                .map(|&(color, depth)| Fragment {
                    color,
                    depth,
                    front: None,
                })
                .collect(),
            outside_scissor: false,
            passed: false,
        }
    }

    fn verdicts(draw: &DrawStory) -> Vec<Verdict> {
        draw.outcomes().unwrap().iter().map(|o| o.verdict).collect()
    }

    #[test]
    fn the_mark_writes_the_reference_where_the_mirror_is_in_front() {
        let before = texel([10, 20, 30, 255], 0.99, 0);
        let mark = draw(states::MARK_MIRROR, 1, before, &[([200, 0, 0, 255], 0.95)]);
        assert_eq!(verdicts(&mark), [Verdict::Passes]);
        let after = mark.predicted().unwrap();
        assert_eq!(after.stencil, 1);
        assert_eq!(after.color, before.color, "the mark writes no colour");
        let text = mark.describe().join("\n");
        assert!(
            text.contains("depth test 0.95000 Less 0.99000 → pass"),
            "{text}"
        );
        assert!(text.contains("stencil Replace 0 → 1"), "{text}");
    }

    #[test]
    fn a_mark_behind_the_crate_fails_the_depth_test_and_keeps_zero() {
        let before = texel([10, 20, 30, 255], 0.90, 0);
        let mark = draw(states::MARK_MIRROR, 1, before, &[([200, 0, 0, 255], 0.95)]);
        assert_eq!(verdicts(&mark), [Verdict::DepthFails]);
        assert_eq!(mark.predicted().unwrap(), before);
    }

    #[test]
    fn the_reflection_is_rejected_where_the_stencil_holds_zero() {
        let before = texel([10, 20, 30, 255], 0.90, 0);
        let reflection = draw(states::DRAW_REFLECTION, 1, before, &[([1, 2, 3, 255], 0.5)]);
        assert_eq!(verdicts(&reflection), [Verdict::StencilFails]);
        let text = reflection.describe().join("\n");
        assert!(
            text.contains("(1 & 0xFF) Equal (0 & 0xFF) → fail"),
            "{text}"
        );
        assert!(text.contains("depth test: not reached"), "{text}");
    }

    #[test]
    fn the_second_fragment_of_a_shadow_meets_the_first_one_s_stencil() {
        let before = texel([100, 100, 100, 255], 0.99, 0);
        let shadow = [([0, 0, 0, 128], 0.5), ([0, 0, 0, 128], 0.4)];
        let draw = draw(states::NO_DOUBLE_BLEND, 0, before, &shadow);
        assert_eq!(verdicts(&draw), [Verdict::Passes, Verdict::StencilFails]);
        let text = draw.describe().join("\n");
        assert!(text.contains("fragment 2 of 2"), "{text}");
    }

    #[test]
    fn blending_is_written_out_with_its_factors() {
        let recipe = Recipe {
            blend: Some(wgpu::BlendState::ALPHA_BLENDING),
            ..states::OPAQUE
        };
        let before = texel([0, 0, 0, 255], 1.0, 0);
        let glass = draw(recipe, 0, before, &[([255, 255, 255, 64], 0.5)]);
        let text = glass.describe().join("\n");
        assert!(text.contains("0.251·src + 0.749·dst"), "{text}");
        // A quarter of white over black, in linear light, is sRGB 137.
        assert_eq!(glass.predicted().unwrap().color[0], 137);
    }

    // Each rule on its own, against numbers worked by hand (the suite checks the same model
    // against the GPU, in tests/suite/pixel.rs).

    const FAR: Texel = Texel {
        color: [10, 20, 30, 255],
        depth: 1.0,
        stencil: 0,
    };

    fn fragment(depth: f32) -> Fragment {
        Fragment {
            color: [200, 100, 50, 255],
            depth,
            front: None,
        }
    }

    /// A draw of `recipe` at reference `reference` over `before`, with these fragments; what the
    /// GPU stored is set to the model's prediction (or to `after`, if given).
    fn story_of(
        recipe: Recipe,
        reference: u32,
        before: Texel,
        fragments: &[Fragment],
    ) -> DrawStory {
        let mut story = DrawStory {
            recipe: Some(recipe),
            object: Some("a box"),
            reference,
            blend_constant: wgpu::Color::BLACK,
            before,
            after: before,
            fragments: fragments.to_vec(),
            outside_scissor: false,
            passed: false,
        };
        story.after = story.predicted().unwrap();
        story.passed = story.any_passes();
        story
    }

    #[test]
    fn an_opaque_fragment_in_front_writes_its_colour_and_depth() {
        let story = story_of(states::OPAQUE, 0, FAR, &[fragment(0.5)]);
        let outcome = story.outcomes().unwrap()[0];
        assert_eq!(outcome.verdict, Verdict::Passes);
        assert_eq!(outcome.operation, None);
        assert_eq!(story.after.color, [200, 100, 50, 255]);
        assert_eq!((story.after.depth, story.after.stencil), (0.5, 0));
        assert!(story.agrees() && story.any_passes());
        assert!(!story.any(Verdict::DepthFails) && !story.any(Verdict::StencilFails));
        let lines = story.describe();
        assert_eq!(lines[0], "OPAQUE · a box");
        assert_eq!(lines[1], "a fragment: #c86432 at depth 0.50000");
        assert_eq!(lines[2], "  stencil test: none (Always)");
        assert_eq!(lines[3], "  depth test 0.50000 Less 1.00000 → pass");
        assert_eq!(lines[4], "  colour written #c86432");
        assert_eq!(lines.len(), 5);
    }

    #[test]
    fn a_fragment_behind_fails_the_depth_test_and_writes_nothing() {
        let near = Texel { depth: 0.25, ..FAR };
        let story = story_of(states::OPAQUE, 0, near, &[fragment(0.5)]);
        assert_eq!(story.outcomes().unwrap()[0].verdict, Verdict::DepthFails);
        assert_eq!(story.after, near);
        assert!(!story.any_passes() && story.any(Verdict::DepthFails));
        let lines = story.describe();
        assert_eq!(lines[3], "  depth test 0.50000 Less 0.25000 → fail");
        assert_eq!(
            lines[4],
            "  colour: not written (the fragment was rejected)"
        );
        // An equal depth fails Less too.
        let equal = story_of(states::OPAQUE, 0, near, &[fragment(0.25)]);
        assert_eq!(equal.outcomes().unwrap()[0].verdict, Verdict::DepthFails);
    }

    #[test]
    fn the_mark_replaces_the_stencil_and_writes_no_colour_or_depth() {
        let story = story_of(states::MARK_MIRROR, 1, FAR, &[fragment(0.5)]);
        let outcome = story.outcomes().unwrap()[0];
        assert_eq!(outcome.operation, Some((StencilOperation::Replace, 1)));
        assert_eq!(story.after, Texel { stencil: 1, ..FAR });
        let lines = story.describe();
        assert_eq!(lines[4], "  stencil Replace 0 → 1");
        assert_eq!(lines[5], "  colour: none written (write mask empty)");
    }

    #[test]
    fn the_reflection_passes_only_where_the_mark_is() {
        let marked = Texel { stencil: 1, ..FAR };
        let story = story_of(states::DRAW_REFLECTION, 1, marked, &[fragment(0.5)]);
        assert_eq!(story.outcomes().unwrap()[0].verdict, Verdict::Passes);
        assert_eq!(
            story.describe()[2],
            "  stencil test (1 & 0xFF) Equal (1 & 0xFF) → pass"
        );
        assert_eq!(story.describe()[4], "  stencil Keep");
        let unmarked = story_of(states::DRAW_REFLECTION, 1, FAR, &[fragment(0.5)]);
        let outcome = unmarked.outcomes().unwrap()[0];
        assert_eq!(outcome.verdict, Verdict::StencilFails);
        assert!(unmarked.any(Verdict::StencilFails));
        assert_eq!(unmarked.after, FAR);
        let lines = unmarked.describe();
        assert_eq!(
            lines[2],
            "  stencil test (1 & 0xFF) Equal (0 & 0xFF) → fail"
        );
        assert_eq!(lines[3], "  depth test: not reached");
    }

    #[test]
    fn no_double_blend_blends_the_first_of_two_fragments_only() {
        let story = story_of(
            states::NO_DOUBLE_BLEND,
            0,
            FAR,
            &[fragment(0.5), fragment(0.5)],
        );
        let outcomes = story.outcomes().unwrap();
        assert_eq!(outcomes[0].verdict, Verdict::Passes);
        assert_eq!(
            outcomes[0].operation,
            Some((StencilOperation::IncrementClamp, 1))
        );
        assert_eq!(outcomes[1].verdict, Verdict::StencilFails);
        assert_eq!(outcomes[1].before, outcomes[0].after);
        assert_eq!(story.after.stencil, 1);
        let lines = story.describe();
        assert_eq!(lines[1], "fragment 1 of 2: #c86432 at depth 0.50000");
        assert!(lines.iter().any(|l| l.starts_with("fragment 2 of 2")));
        // No depth write: the shadow leaves the depth as it was.
        assert_eq!(story.after.depth, 1.0);
    }

    #[test]
    fn a_write_mask_keeps_the_bits_outside_it() {
        let recipe = states::REFLECTED_NO_DOUBLE_BLEND;
        let marked = Texel { stencil: 1, ..FAR };
        let story = story_of(recipe, 1, marked, &[fragment(0.5)]);
        let outcome = story.outcomes().unwrap()[0];
        assert_eq!(outcome.verdict, Verdict::Passes);
        assert_eq!(
            story.after.stencil, 3,
            "1 + 1 through mask 0b10, the mark kept"
        );
        let line = story
            .describe()
            .into_iter()
            .find(|l| l.contains("write mask"));
        assert_eq!(
            line.unwrap(),
            "  stencil IncrementClamp 1 → 3, write mask 0x02"
        );
    }

    #[test]
    fn alpha_blending_mixes_in_linear_light() {
        let half = Fragment {
            color: [255, 255, 255, 128],
            depth: 0.5,
            front: None,
        };
        let black = Texel {
            color: [0, 0, 0, 255],
            ..FAR
        };
        let story = story_of(states::TRANSPARENT, 0, black, &[half]);
        // 128/255 of white over black in linear light, then encoded: 188, not 128.
        let expected = crate::gpu::linear_to_srgb(128.0 / 255.0);
        assert_eq!(story.after.color[..3], [expected; 3]);
        assert_eq!(
            story.after.color[3],
            128 + ((1.0 - 128.0 / 255.0) * 255.0f32).round() as u8
        );
        let line = &story.describe()[4];
        assert!(
            line.starts_with("  colour blended 0.502·src + 0.498·dst"),
            "{line}"
        );
        assert!(line.ends_with(&hex(story.after.color)), "{line}");
    }

    #[test]
    fn blend_operations_and_factors_as_the_gpu_defines_them() {
        let (src, dst) = ([255, 0, 0, 255], [0, 255, 0, 0]);
        let with = |color: wgpu::BlendComponent| Recipe {
            blend: Some(wgpu::BlendState {
                color,
                alpha: wgpu::BlendComponent::REPLACE,
            }),
            ..states::OPAQUE
        };
        let component = |src_factor, dst_factor, operation| wgpu::BlendComponent {
            src_factor,
            dst_factor,
            operation,
        };
        let k = wgpu::Color {
            r: 0.5,
            g: 0.5,
            b: 0.5,
            a: 1.0,
        };
        use BlendFactor as F;
        use BlendOperation as O;
        let cases = [
            (component(F::One, F::One, O::Add), [255, 255, 0]),
            (component(F::One, F::One, O::Subtract), [255, 0, 0]),
            (component(F::One, F::One, O::ReverseSubtract), [0, 255, 0]),
            (component(F::Zero, F::Zero, O::Min), [0, 0, 0]),
            (component(F::Zero, F::Zero, O::Max), [255, 255, 0]),
            (component(F::Dst, F::Src, O::Add), [0, 0, 0]),
            (
                component(F::OneMinusDst, F::OneMinusSrc, O::Add),
                [255, 255, 0],
            ),
            (
                component(F::DstAlpha, F::OneMinusDstAlpha, O::Add),
                [0, 255, 0],
            ),
            (
                component(F::SrcAlpha, F::OneMinusSrcAlpha, O::Add),
                [255, 0, 0],
            ),
            (
                component(F::SrcAlphaSaturated, F::Zero, O::Add),
                [255, 0, 0],
            ),
            (
                component(F::Constant, F::OneMinusConstant, O::Add),
                [188, 188, 0],
            ),
        ];
        for (blend, rgb) in cases {
            let mixed = super::blend(&with(blend), src, dst, k);
            assert_eq!(mixed[..3], rgb, "{blend:?}");
            assert_eq!(mixed[3], 255, "alpha replaced: {blend:?}");
        }
        assert_eq!(
            super::blend(&states::OPAQUE, src, dst, k),
            src,
            "no blend replaces"
        );
    }

    #[test]
    fn a_factor_is_written_as_a_number_where_the_channels_agree() {
        let (src, dst, k) = ([255, 0, 0, 51], [0, 0, 0, 255], wgpu::Color::WHITE);
        assert_eq!(factor_text(BlendFactor::SrcAlpha, src, dst, k), "0.2");
        assert_eq!(
            factor_text(BlendFactor::OneMinusSrcAlpha, src, dst, k),
            "0.8"
        );
        assert_eq!(factor_text(BlendFactor::One, src, dst, k), "1");
        assert_eq!(factor_text(BlendFactor::Zero, src, dst, k), "0");
        assert_eq!(factor_text(BlendFactor::Src, src, dst, k), "Src");
        assert_eq!(
            factor_text(BlendFactor::OneMinusDst, src, dst, k),
            "OneMinusDst"
        );
    }

    #[test]
    fn every_depth_compare_function() {
        use CompareFunction as C;
        let cases = [
            (C::Never, [false, false, false]),
            (C::Less, [true, false, false]),
            (C::Equal, [false, true, false]),
            (C::LessEqual, [true, true, false]),
            (C::Greater, [false, false, true]),
            (C::NotEqual, [true, false, true]),
            (C::GreaterEqual, [false, true, true]),
            (C::Always, [true, true, true]),
        ];
        for (compare, expected) in cases {
            let got = [0.25, 0.5, 0.75].map(|fragment| compares(compare, fragment, 0.5));
            assert_eq!(got, expected, "{compare:?}");
        }
    }

    #[test]
    fn a_story_that_disagrees_with_the_gpu_says_so() {
        let mut story = story_of(states::OPAQUE, 0, FAR, &[fragment(0.5)]);
        assert!(story.agrees());
        let predicted = story.after;
        for wrong in [
            Texel {
                color: [204, 100, 50, 255],
                ..predicted
            },
            Texel {
                depth: 0.5 + 2.0 * DEPTH_TOLERANCE,
                ..predicted
            },
            Texel {
                stencil: 1,
                ..predicted
            },
        ] {
            story.after = wrong;
            assert!(!story.agrees(), "{wrong:?}");
            let last = story.describe().pop().unwrap();
            assert!(last.starts_with("the GPU stored"), "{last}");
        }
        story.after = Texel {
            color: [203, 100, 50, 255],
            depth: 0.5 + DEPTH_TOLERANCE,
            ..predicted
        };
        assert!(story.agrees(), "within 3 of 255 and the depth tolerance");
        story.after = predicted;
        story.passed = false;
        assert!(
            !story.agrees(),
            "the GPU counted no passing fragment where the model has one"
        );
    }

    #[test]
    fn a_draw_that_misses_the_pixel_or_has_no_recipe() {
        let missed = story_of(states::OPAQUE, 0, FAR, &[]);
        assert_eq!(
            missed.describe(),
            ["OPAQUE · a box: does not reach this pixel"]
        );
        assert!(missed.agrees() && !missed.any_passes());
        let mut own = story_of(states::OPAQUE, 0, FAR, &[fragment(0.5)]);
        own.recipe = None;
        assert!(!own.agrees());
        assert!(own.outcomes().is_none() && own.predicted().is_none());
        let line = &own.describe()[0];
        assert!(
            line.starts_with("(a pipeline of its own) · a box: 1 fragment(s)"),
            "{line}"
        );
        assert!(line.contains("cannot be written out or checked"), "{line}");
        own.object = None;
        assert!(own.describe()[0].starts_with("(a pipeline of its own): 1"));
    }

    #[test]
    fn a_stencil_that_could_write_says_it_kept_its_value() {
        let near = Texel { depth: 0.25, ..FAR };
        let behind = story_of(states::MARK_MIRROR, 1, near, &[fragment(0.5)]);
        let lines = behind.describe();
        assert_eq!(lines[2], "  stencil test: none (Always)");
        assert_eq!(
            lines[4], "  stencil Keep",
            "the mark may write, and kept: {lines:?}"
        );
        assert_eq!(behind.after.stencil, 0);
    }

    #[test]
    fn a_story_s_settings_are_the_changed_knobs_and_a_camera_of_its_own() {
        use crate::lesson::knobs::{Knob, ON_OFF};
        use crate::room::camera::BOOK_POSE;
        const KNOBS: &[Knob] = &[Knob {
            name: "stencil",
            values: ON_OFF,
            default: "on",
            meaning: "the test",
        }];
        let defaults = Knobs::defaults(KNOBS);
        let off = Knobs::from_settings(KNOBS, &["stencil=off"]).unwrap();
        let other = Camera {
            yaw: 140.0,
            ..BOOK_POSE
        };
        assert_eq!(Story::settings(&defaults, BOOK_POSE, BOOK_POSE), "");
        assert_eq!(Story::settings(&off, BOOK_POSE, BOOK_POSE), "stencil=off");
        assert_eq!(
            Story::settings(&defaults, other, BOOK_POSE),
            "camera 140,14,11.0"
        );
        assert_eq!(
            Story::settings(&off, other, BOOK_POSE),
            "stencil=off, camera 140,14,11.0"
        );
    }

    #[test]
    fn a_factor_that_differs_by_channel_is_named() {
        let (grey, k) = ([128, 128, 128, 255], wgpu::Color::WHITE);
        // Src is per channel even where the channels happen to agree.
        assert_eq!(factor_text(BlendFactor::Src, grey, grey, k), "Src");
        let k = wgpu::Color {
            r: 0.25,
            g: 0.5,
            b: 0.5,
            a: 1.0,
        };
        assert_eq!(
            factor_text(BlendFactor::Constant, grey, grey, k),
            "Constant"
        );
        let k = wgpu::Color {
            r: 0.25,
            g: 0.25,
            b: 0.25,
            a: 1.0,
        };
        assert_eq!(factor_text(BlendFactor::Constant, grey, grey, k), "0.25");
    }

    #[test]
    fn a_dark_colour_blends_through_the_linear_toe() {
        // sRGB 1-3 lie on the encoding's linear part (below 0.0031308 in linear light).
        let replace = Recipe {
            blend: Some(wgpu::BlendState::REPLACE),
            ..states::OPAQUE
        };
        let dark = [1, 2, 3, 255];
        assert_eq!(
            super::blend(&replace, dark, [200; 4], wgpu::Color::BLACK),
            dark
        );
    }

    /// Each blend factor's value, per channel (0-2 colour, 3 alpha), as WebGPU defines it.
    #[test]
    fn every_blend_factor_s_value() {
        let (s, d, k) = (
            [0.1, 0.2, 0.3, 0.4],
            [0.5, 0.6, 0.7, 0.8],
            [0.25, 0.5, 0.75, 1.0],
        );
        use BlendFactor as F;
        let cases: [(F, [f32; 4]); 14] = [
            (F::Zero, [0.0; 4]),
            (F::One, [1.0; 4]),
            (F::Src, s),
            (F::OneMinusSrc, [0.9, 0.8, 0.7, 0.6]),
            (F::SrcAlpha, [0.4; 4]),
            (F::OneMinusSrcAlpha, [0.6; 4]),
            (F::Dst, d),
            (F::OneMinusDst, [0.5, 0.4, 0.3, 0.2]),
            (F::DstAlpha, [0.8; 4]),
            (F::OneMinusDstAlpha, [0.2; 4]),
            // min(source alpha, 1 - destination alpha) for colour, 1 for alpha.
            (F::SrcAlphaSaturated, [0.2, 0.2, 0.2, 1.0]),
            (F::Constant, k),
            (F::OneMinusConstant, [0.75, 0.5, 0.25, 0.0]),
            (F::Src1, [f32::NAN; 4]),
        ];
        for (factor, expected) in cases {
            for (channel, want) in expected.into_iter().enumerate() {
                let value = factor_value(factor, channel, &s, &d, &k);
                let same = (value - want).abs() < 1e-6 || (value.is_nan() && want.is_nan());
                assert!(same, "{factor:?}, channel {channel}: {value}, not {want}");
            }
        }
    }

    #[test]
    fn subtracting_blends_take_one_side_from_the_other() {
        let with = |operation| Recipe {
            blend: Some(wgpu::BlendState {
                color: wgpu::BlendComponent {
                    src_factor: BlendFactor::One,
                    dst_factor: BlendFactor::One,
                    operation,
                },
                alpha: wgpu::BlendComponent::REPLACE,
            }),
            ..states::OPAQUE
        };
        // sRGB 225 and 137 are about 0.75 and 0.25 in linear light: 0.5 between them is sRGB 188.
        let (light, dark, k) = ([225; 4], [137; 4], wgpu::Color::BLACK);
        let subtract = super::blend(&with(BlendOperation::Subtract), light, dark, k);
        let reverse = super::blend(&with(BlendOperation::ReverseSubtract), dark, light, k);
        for mixed in [subtract, reverse] {
            assert!(mixed[0].abs_diff(188) <= 1, "{mixed:?}");
        }
    }

    #[test]
    fn the_depth_tolerance_is_sixteen_steps_of_the_24_bit_buffer() {
        let mut story = story_of(states::OPAQUE, 0, FAR, &[fragment(0.5)]);
        story.after.depth = 0.5 + 5e-7; // about 8 steps
        assert!(story.agrees());
        story.after.depth = 0.5 + 2e-6; // about 34 steps
        assert!(!story.agrees());
        assert_eq!(DEPTH_TOLERANCE * (1 << 24) as f32, 16.0);
    }

    #[test]
    fn colours_are_written_as_hex_with_alpha_where_not_opaque() {
        assert_eq!(hex([255, 0, 16, 255]), "#ff0010");
        assert_eq!(hex([255, 0, 16, 128]), "#ff0010/80");
    }

    #[test]
    fn the_story_s_text_heads_each_step_with_its_pixel() {
        let story = Story {
            lesson: "a-lesson",
            pixel: (3, 4),
            size: (32, 18),
            settings: "stencil=off".into(),
            steps: vec![
                StepStory {
                    name: "clear",
                    after: FAR,
                    into_own_target: false,
                    draws: Vec::new(),
                },
                StepStory {
                    name: "draw into a texture",
                    after: FAR,
                    into_own_target: true,
                    draws: vec![story_of(states::OPAQUE, 0, FAR, &[fragment(0.5)])],
                },
            ],
        };
        let text = story.text();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "Pixel (3, 4) of a-lesson at 32×18, stencil=off");
        assert!(lines[3].starts_with(" 1 clear "), "{}", lines[3]);
        assert!(
            lines[3].ends_with("#0a141e  depth 1.00000  stencil 0"),
            "{}",
            lines[3]
        );
        assert!(lines[4].starts_with(" 2 draw into a texture"));
        assert_eq!(
            lines[5],
            "     drawn into the lesson's own target: this pixel is untouched"
        );
        assert_eq!(lines[6], "   · OPAQUE · a box");
        assert_eq!(lines[7], "       a fragment: #c86432 at depth 0.50000");
        let plain = Story {
            settings: String::new(),
            ..story
        };
        assert!(
            plain
                .text()
                .starts_with("Pixel (3, 4) of a-lesson at 32×18\n")
        );
    }
}
