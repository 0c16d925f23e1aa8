//! The stencil truth table: the GPU's stencil test and operations, checked case by case against the
//! CPU model in `workbook::math::stencil`.
//!
//! One Depth24PlusStencil8 target holds every case, one pixel each:
//!
//! - **x** = `reference index × 256 + stored`: the target is [`REFERENCES`]`.len()` blocks of 256
//!   columns. Within a block the column is the stencil value the pixel holds before the draw (every
//!   value 0..=255, so clamping and wrapping at 0 and 255 always happen somewhere); the block picks the
//!   stencil reference.
//! - **y** = one row per (compare, mask pair, rotation, depth outcome), in that order of nesting (the
//!   depth outcome varies fastest). Rotation `r` is the face with `pass_op = OPERATIONS[r]`,
//!   `fail_op = OPERATIONS[r + 3]` and `depth_fail_op = OPERATIONS[r + 5]` (indices mod 8): over the
//!   8 rotations every operation lands in every slot, and the three branches always run different
//!   operations, so taking the wrong branch shows.
//!
//! The stored values are written into the stencil aspect with `write_texture`. One pass clears depth to
//! 0.5; each draw is a full-screen triangle cut to one row and one reference block by the scissor, at
//! depth 0.25 (passes the `Less` depth test) or 0.75 (fails it), with depth writes off so every row
//! sees 0.5. The stencil aspect is then read back and every pixel compared with [`Case::outcome`].
//!
//! Time goes into pipelines, not pixels: a software GPU (llvmpipe) compiles a shader variant for every
//! stencil state, 15–20 ms each when its shader cache is cold. So the masks come in pairs rather
//! than a full cross, and each pipeline carries two rotations: `r` on its front face and `r + 4` on its
//! back face, drawn with a clockwise triangle. 8 compares × 4 × 6 pairs = 192 pipelines.

use std::collections::HashMap;

use workbook::Gpu;
use workbook::app::headless::read_texture;
use workbook::gpu::DEPTH_STENCIL_FORMAT;
use workbook::math::stencil::{COMPARISONS, Case, OPERATIONS, passes};
use workbook::wgpu;

/// Stencil references: the ends of the range, single bits, values that straddle the masks' bits.
const REFERENCES: [u8; 16] = [
    0x00, 0x01, 0x02, 0x0f, 0x10, 0x3c, 0x42, 0x5a, 0x7f, 0x80, 0x81, 0xa5, 0xc3, 0xf0, 0xfe, 0xff,
];
/// (read mask, write mask): each of 0xff, 0x0f, 0xf0, 0x3c and 0x00 appears in both roles.
const MASKS: [(u8, u8); 6] = [
    (0xff, 0xff), // nothing cut
    (0x0f, 0xff), // the test sees the low bits only; the whole result is written
    (0xf0, 0x0f), // the test sees the high bits; the low bits are written
    (0x3c, 0xf0), // the middle bits are tested; the high bits are written
    (0x00, 0x3c), // every test is 0 CMP 0
    (0xff, 0x00), // nothing is written
];
/// Whether the fragment passes the depth test (drawn at 0.25 or 0.75 against a cleared 0.5).
const DEPTH_OUTCOMES: [bool; 2] = [true, false];
/// Every stored value, one per column of a reference block.
const STORED_VALUES: u32 = 256;
/// Rotations of the operations; a pipeline holds two, `r` (front face) and `r + HALF` (back face).
const ROTATIONS: usize = OPERATIONS.len();
const HALF: usize = ROTATIONS / 2;

const WIDTH: u32 = REFERENCES.len() as u32 * STORED_VALUES;
const HEIGHT: u32 = (COMPARISONS.len() * MASKS.len() * ROTATIONS * DEPTH_OUTCOMES.len()) as u32;

/// How many rows the failure message shows a wrong case of.
const REPORTED: usize = 20;

/// A full-screen triangle in four versions, three vertices each: counter-clockwise (the front face)
/// at depth 0.25, then at 0.75; clockwise (the back face) at 0.25, then at 0.75.
const SHADER: &str = "
@vertex
fn vs_main(@builtin(vertex_index) index: u32) -> @builtin(position) vec4<f32> {
    var corner = index % 3u;
    if index >= 6u && corner != 0u {
        corner = 3u - corner;
    }
    let x = select(-1.0, 3.0, corner == 1u);
    let y = select(-1.0, 3.0, corner == 2u);
    let z = select(0.25, 0.75, (index / 3u) % 2u == 1u);
    return vec4<f32>(x, y, z, 1.0);
}
";

/// The branch a fragment takes, which picks the operation.
const BRANCHES: [&str; 3] = ["pass", "fail", "depth-fail"];
/// Where each branch's operation sits in [`OPERATIONS`], relative to the rotation.
const OFFSETS: [usize; 3] = [0, 3, 5];

/// What one row of the target tests: everything but the reference and the stored value.
#[derive(Debug, Clone, Copy)]
struct Row {
    compare: usize,
    masks: usize,
    rotation: usize,
    depth_passes: bool,
}

impl Row {
    /// The row at `y` (the nesting order of the module doc).
    fn at(y: u32) -> Self {
        let mut rest = y as usize;
        let mut digit = |base: usize| {
            let value = rest % base;
            rest /= base;
            value
        };
        let depth = digit(DEPTH_OUTCOMES.len());
        let rotation = digit(ROTATIONS);
        let masks = digit(MASKS.len());
        let compare = digit(COMPARISONS.len());
        Self {
            compare,
            masks,
            rotation,
            depth_passes: DEPTH_OUTCOMES[depth],
        }
    }

    /// The pipeline that draws this row: rotations `r` and `r + HALF` share one.
    fn pipeline_key(&self) -> PipelineKey {
        PipelineKey {
            compare: self.compare,
            masks: self.masks,
            rotation: self.rotation % HALF,
        }
    }

    /// The first of the three vertices that draw this row (see [`SHADER`]).
    fn first_vertex(&self) -> u32 {
        let back = u32::from(self.rotation >= HALF);
        let behind = u32::from(!self.depth_passes);
        3 * (2 * back + behind)
    }

    /// The case of the pixel in column `x` of this row.
    fn case(&self, x: u32) -> Case {
        let (read_mask, write_mask) = MASKS[self.masks];
        Case {
            face: face(self.compare, self.rotation),
            reference: REFERENCES[(x / STORED_VALUES) as usize],
            read_mask,
            write_mask,
            stored: (x % STORED_VALUES) as u8,
            depth_passes: self.depth_passes,
        }
    }
}

/// What a pipeline fixes: all of the stencil state but the reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
struct PipelineKey {
    compare: usize,
    masks: usize,
    /// The front face's rotation; the back face has the one `HALF` further on.
    rotation: usize,
}

/// The stencil face of one compare function and one rotation of the operations.
fn face(compare: usize, rotation: usize) -> wgpu::StencilFaceState {
    let op = |offset: usize| OPERATIONS[(rotation + offset) % ROTATIONS];
    wgpu::StencilFaceState {
        compare: COMPARISONS[compare],
        pass_op: op(OFFSETS[0]),
        fail_op: op(OFFSETS[1]),
        depth_fail_op: op(OFFSETS[2]),
    }
}

/// The index into [`BRANCHES`] of the branch `case` takes.
fn branch(case: &Case) -> usize {
    if !passes(
        case.face.compare,
        case.reference,
        case.read_mask,
        case.stored,
    ) {
        1
    } else if case.depth_passes {
        0
    } else {
        2
    }
}

/// One line about a case the GPU got wrong.
fn describe(case: &Case, got: u8) -> String {
    let face = &case.face;
    format!(
        "compare {:?}, pass/fail/depth-fail ops {:?}/{:?}/{:?}, ref {:#04x}, read mask {:#04x}, \
         write mask {:#04x}, stored {:#04x}, depth {} ({} branch): expected {:#04x}, got {:#04x}",
        face.compare,
        face.pass_op,
        face.fail_op,
        face.depth_fail_op,
        case.reference,
        case.read_mask,
        case.write_mask,
        case.stored,
        if case.depth_passes { "passes" } else { "fails" },
        BRANCHES[branch(case)],
        case.outcome(),
        got,
    )
}

/// The GPU's stencil values compared with the CPU model's, case by case.
struct Findings {
    checked: usize,
    /// Cases run, by operation (index into [`OPERATIONS`]) and branch (index into [`BRANCHES`]).
    ran: [[usize; BRANCHES.len()]; OPERATIONS.len()],
    /// Cases the GPU got wrong, likewise.
    wrong: [[usize; BRANCHES.len()]; OPERATIONS.len()],
    /// The first wrong case of each row, for the first [`REPORTED`] rows that have one.
    examples: Vec<String>,
}

impl Findings {
    /// Checks `stencil`, the target read back (rows top to bottom), against [`Case::outcome`].
    fn of(stencil: &[u8]) -> Self {
        let mut findings = Self {
            checked: 0,
            ran: Default::default(),
            wrong: Default::default(),
            examples: Vec::new(),
        };
        for (y, values) in (0u32..).zip(stencil.chunks(WIDTH as usize)) {
            let row = Row::at(y);
            let mut row_reported = false;
            for (x, &got) in (0u32..).zip(values) {
                let case = row.case(x);
                let taken = branch(&case);
                let operation = (row.rotation + OFFSETS[taken]) % ROTATIONS;
                findings.checked += 1;
                findings.ran[operation][taken] += 1;
                if got != case.outcome() {
                    findings.wrong[operation][taken] += 1;
                    if !row_reported && findings.examples.len() < REPORTED {
                        findings
                            .examples
                            .push(format!("  {}", describe(&case, got)));
                        row_reported = true;
                    }
                }
            }
        }
        findings
    }

    /// One line per (operation, branch) with wrong cases.
    fn summary(&self) -> String {
        let mut lines = Vec::new();
        for (o, operation) in OPERATIONS.iter().enumerate() {
            for (b, branch) in BRANCHES.iter().enumerate() {
                let (wrong, ran) = (self.wrong[o][b], self.ran[o][b]);
                if wrong > 0 {
                    lines.push(format!("  {operation:?} on {branch}: {wrong} of {ran}"));
                }
            }
        }
        lines.join("\n")
    }
}

fn target(gpu: &Gpu) -> wgpu::Texture {
    // Written by the initial copy, read back after the draws.
    let usage = wgpu::TextureUsages::COPY_SRC | wgpu::TextureUsages::COPY_DST;
    let size = (WIDTH, HEIGHT);
    workbook::gpu::target_texture(
        &gpu.device,
        "truth table target",
        DEPTH_STENCIL_FORMAT,
        size,
        usage,
    )
}

/// Writes the stored values: column x of every row holds `x % 256`. (A copy into a depth-stencil
/// texture must cover all of it.)
fn write_stored_values(gpu: &Gpu, texture: &wgpu::Texture) {
    let row: Vec<u8> = (0..WIDTH).map(|x| (x % STORED_VALUES) as u8).collect();
    gpu.queue.write_texture(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::StencilOnly,
        },
        &row.repeat(HEIGHT as usize),
        wgpu::TexelCopyBufferLayout {
            offset: 0,
            bytes_per_row: Some(WIDTH),
            rows_per_image: Some(HEIGHT),
        },
        texture.size(),
    );
}

/// The pipeline of one key: depth test `Less` without writes, the key's stencil state, no fragment
/// shader (nothing but the depth-stencil attachment).
fn pipeline(
    gpu: &Gpu,
    layout: &wgpu::PipelineLayout,
    shader: &wgpu::ShaderModule,
    key: PipelineKey,
) -> wgpu::RenderPipeline {
    let (read_mask, write_mask) = MASKS[key.masks];
    let label = format!(
        "truth table {:?}, rotations {} and {}, read mask {read_mask:#04x}, write mask {write_mask:#04x}",
        COMPARISONS[key.compare],
        key.rotation,
        key.rotation + HALF,
    );
    gpu.device
        .create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(&label),
            layout: Some(layout),
            vertex: wgpu::VertexState {
                module: shader,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[],
            },
            fragment: None,
            primitive: wgpu::PrimitiveState {
                front_face: wgpu::FrontFace::Ccw,
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_STENCIL_FORMAT,
                depth_write_enabled: Some(false),
                depth_compare: Some(wgpu::CompareFunction::Less),
                stencil: wgpu::StencilState {
                    front: face(key.compare, key.rotation),
                    back: face(key.compare, key.rotation + HALF),
                    read_mask: read_mask.into(),
                    write_mask: write_mask.into(),
                },
                bias: wgpu::DepthBiasState::default(),
            }),
            multisample: wgpu::MultisampleState::default(),
            multiview_mask: None,
            cache: None,
        })
}

/// Draws every case in one pass: one scissored draw per row and reference, pipelines made once per
/// key and cached. Returns how many pipelines were made.
fn draw_cases(gpu: &Gpu, texture: &wgpu::Texture) -> usize {
    let device = &gpu.device;
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("truth table shader"),
        source: wgpu::ShaderSource::Wgsl(SHADER.into()),
    });
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some("truth table pipeline layout"),
        bind_group_layouts: &[],
        immediate_size: 0,
    });
    let view = texture.create_view(&wgpu::TextureViewDescriptor {
        label: Some("truth table view"),
        ..Default::default()
    });
    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
        label: Some("truth table encoder"),
    });
    let mut pipelines = HashMap::new();
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("truth table pass"),
            color_attachments: &[],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(0.5),
                    store: wgpu::StoreOp::Store,
                }),
                // `None` would make stencil read-only: load the stored values, keep the results.
                stencil_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Load,
                    store: wgpu::StoreOp::Store,
                }),
            }),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        for y in 0..HEIGHT {
            let row = Row::at(y);
            let pipeline = pipelines
                .entry(row.pipeline_key())
                .or_insert_with_key(|&key| pipeline(gpu, &layout, &shader, key));
            pass.set_pipeline(pipeline);
            let first = row.first_vertex();
            for (block, reference) in (0u32..).zip(REFERENCES) {
                pass.set_scissor_rect(block * STORED_VALUES, y, STORED_VALUES, 1);
                pass.set_stencil_reference(reference.into());
                pass.draw(first..first + 3, 0..1);
            }
        }
    }
    gpu.queue.submit([encoder.finish()]);
    pipelines.len()
}

#[test]
fn every_stencil_case_matches_the_cpu_model() -> anyhow::Result<()> {
    let gpu = Gpu::shared_headless(None, false)?;
    assert!(
        gpu.can_copy_depth_stencil(),
        "the truth table reads the stencil buffer back, which this backend ({:?}) cannot do; use Vulkan",
        gpu.adapter.get_info().backend
    );
    // Any wgpu error while setting up and drawing fails the test.
    let (texture, pipelines) = gpu.scoped(|| {
        let texture = target(&gpu);
        write_stored_values(&gpu, &texture);
        let pipelines = draw_cases(&gpu, &texture);
        Ok((texture, pipelines))
    })?;
    let stencil = read_texture(&gpu, &texture, wgpu::TextureAspect::StencilOnly, 1)?;
    assert_eq!(pipelines, COMPARISONS.len() * HALF * MASKS.len());
    assert_eq!(stencil.len(), (WIDTH * HEIGHT) as usize);

    let findings = Findings::of(&stencil);

    let cases = COMPARISONS.len()
        * MASKS.len()
        * ROTATIONS
        * DEPTH_OUTCOMES.len()
        * REFERENCES.len()
        * STORED_VALUES as usize;
    assert_eq!(
        findings.checked, cases,
        "the table should hold {cases} cases"
    );
    for (operation, ran) in OPERATIONS.iter().zip(findings.ran) {
        for (branch, ran) in BRANCHES.iter().zip(ran) {
            assert!(ran > 0, "{operation:?} never ran on the {branch} branch");
        }
    }
    let wrong: usize = findings.wrong.iter().flatten().sum();
    assert!(
        wrong == 0,
        "{wrong} of {cases} stencil cases differ from the CPU model.\n\
         Wrong cases by the operation that ran:\n{}\n\
         The first wrong case of each row (up to {REPORTED} rows):\n{}",
        findings.summary(),
        findings.examples.join("\n")
    );
    Ok(())
}
