//! Fuzzing the model loader: mutated and random OBJ text must give a mesh that `--model` can place, or
//! an error of one line; never a panic, a hang or numbers that are not finite.
//!
//! Every input goes through [`load`], which runs `MeshData::parse_obj` on a thread of its own (a hang
//! fails after [`LIMIT`]), catches a panic, and checks what came out with [`placeable`]. The same
//! check runs on four kinds of input: mutations of two small valid files, random files from a small
//! OBJ grammar (both with proptest, a new random seed each run), fixed edge cases, and the corpus in
//! `tests/fuzz-corpus/`, where every input that ever failed is kept (and some nasty ones made by hand).
//!
//! A failure prints the input, escaped; to keep it, save it as `tests/fuzz-corpus/NAME.obj` with a
//! first line `# why: ...`. Proptest's own failure files are switched off: the corpus replaces them.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use glam::Vec3;
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use workbook::room::mesh::MeshData;

/// The longest one case may take before it counts as a hang.
const LIMIT: Duration = Duration::from_secs(2);

/// What every input is called in the loader's messages.
const NAME: &str = "fuzzed.obj";

/// A cube with texture coordinates and normals: quads, two triangles, an object name and smoothing.
const CUBE: &str = "# a cube, counter-clockwise from outside
mtllib cube.mtl
o cube
v -1 -1 1
v 1 -1 1
v 1 1 1
v -1 1 1
v -1 -1 -1
v 1 -1 -1
v 1 1 -1
v -1 1 -1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 0 1
vn 0 0 -1
vn 1 0 0
vn -1 0 0
vn 0 1 0
vn 0 -1 0
usemtl stone
s off
f 1/1/1 2/2/1 3/3/1 4/4/1
f 6/1/2 5/2/2 8/3/2 7/4/2
f 2/1/3 6/2/3 7/3/3 3/4/3
f 5/1/4 1/2/4 4/3/4 8/4/4
f 4/1/5 3/2/5 7/3/5 8/4/5
f 5/1/6 6/2/6 2/3/6
f 5/1/6 2/3/6 1/4/6
";

/// A triangle without normals or texture coordinates: the loader computes its normals.
const TRIANGLE: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

/// What the loader made of an input that it handled properly.
#[derive(Debug)]
enum Outcome {
    Loaded(MeshData),
    /// The error, with its causes, on one line.
    Refused(String),
}

/// Runs the loader on `bytes` on a thread of its own; `Err` says what went wrong (a panic, a hang, a
/// mesh that cannot be placed, an error message of several lines), with the input.
fn load(bytes: &[u8], limit: Duration) -> Result<Outcome, String> {
    let (sender, receiver) = mpsc::channel();
    let input = bytes.to_vec();
    std::thread::Builder::new()
        .name("obj-loader".into())
        .spawn(move || {
            let result = catch_unwind(AssertUnwindSafe(|| MeshData::parse_obj(NAME, &input)));
            let _ = sender.send(result);
        })
        .expect("a thread for the loader");
    let problem = match receiver.recv_timeout(limit) {
        Ok(Ok(Ok(mesh))) => match placeable(&mesh) {
            Ok(()) => return Ok(Outcome::Loaded(mesh)),
            Err(problem) => format!("loaded a mesh that cannot be placed: {problem}"),
        },
        Ok(Ok(Err(error))) => {
            let message = format!("{error:#}");
            if !message.contains('\n') && message.contains(NAME) {
                return Ok(Outcome::Refused(message));
            }
            format!("refused it with a message that is not one line naming the model: {message:?}")
        }
        Ok(Err(payload)) => {
            let message = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            format!("panicked: {message}")
        }
        // The thread is left running: there is no way to stop it, and the test fails anyway.
        Err(mpsc::RecvTimeoutError::Timeout) => format!("did not finish in {limit:?}"),
        Err(mpsc::RecvTimeoutError::Disconnected) => "the loader's thread died".to_string(),
    };
    Err(format!("the loader {problem}\ninput: {}", escaped(bytes)))
}

/// The input as a Rust byte string would spell it, cut short when long.
fn escaped(bytes: &[u8]) -> String {
    const SHOWN: usize = 4000;
    let text = bytes[..bytes.len().min(SHOWN)].escape_ascii().to_string();
    if bytes.len() > SHOWN {
        format!("b\"{text}\"... ({} bytes in all)", bytes.len())
    } else {
        format!("b\"{text}\"")
    }
}

/// What `--model` needs: whole triangles, indices in range, finite numbers, unit normals, and a box of
/// finite, non-zero size; and what `load_obj` promises: that box centred, its largest side 1.
fn placeable(mesh: &MeshData) -> Result<(), String> {
    let count = mesh.vertices.len();
    if mesh.indices.len() < 3 || !mesh.indices.len().is_multiple_of(3) {
        return Err(format!(
            "{} indices are no whole triangles",
            mesh.indices.len()
        ));
    }
    if let Some(index) = mesh.indices.iter().find(|&&i| i as usize >= count) {
        return Err(format!("index {index} of {count} vertices"));
    }
    for (k, vertex) in mesh.vertices.iter().enumerate() {
        let numbers = vertex
            .position
            .iter()
            .chain(&vertex.normal)
            .chain(&vertex.uv);
        if !numbers.into_iter().all(|c| c.is_finite()) {
            return Err(format!("vertex {k} is not finite: {vertex:?}"));
        }
        let length = Vec3::from(vertex.normal).length();
        if (length - 1.0).abs() > 1e-3 {
            return Err(format!(
                "vertex {k}'s normal has length {length}: {vertex:?}"
            ));
        }
    }
    let (min, max) = mesh.bounds();
    let size = (max - min).max_element();
    if !(min.is_finite() && max.is_finite() && size > 0.0) {
        return Err(format!("its box is {min} to {max}"));
    }
    let centre = (min + max) * 0.5;
    if (size - 1.0).abs() > 1e-3 || centre.abs().max_element() > 1e-3 {
        return Err(format!(
            "its box {min} to {max} is not centred with a largest side of 1"
        ));
    }
    Ok(())
}

/// An input, shown escaped in proptest's reports.
#[derive(Clone)]
struct Input(Vec<u8>);

impl std::fmt::Debug for Input {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&escaped(&self.0))
    }
}

/// Runs `cases` inputs from `inputs` through [`load`]; fails with the smallest failing input proptest
/// finds. Returns how many were loaded and how many refused.
fn fuzz(cases: u32, inputs: impl Strategy<Value = Vec<u8>>) -> (usize, usize) {
    let config = Config {
        cases,
        // Failures go to tests/fuzz-corpus by hand, with a reason, not to proptest-regressions/.
        failure_persistence: None,
        ..Config::default()
    };
    let loaded = AtomicUsize::new(0);
    let refused = AtomicUsize::new(0);
    let inputs = inputs.prop_map(Input);
    let result = TestRunner::new(config).run(&inputs, |Input(bytes)| {
        match load(&bytes, LIMIT).map_err(TestCaseError::fail)? {
            Outcome::Loaded(_) => loaded.fetch_add(1, Ordering::Relaxed),
            Outcome::Refused(_) => refused.fetch_add(1, Ordering::Relaxed),
        };
        Ok(())
    });
    if let Err(error) = result {
        panic!("{error}");
    }
    (loaded.into_inner(), refused.into_inner())
}

// ---- Mutations of valid files ----

/// Lines to insert: the ways OBJ files go wrong, and the edges of tobj's parser.
fn nasty_lines() -> Vec<Vec<u8>> {
    let mut lines: Vec<Vec<u8>> = [
        "f 1 2 999999",
        "f -1 -2 -3",
        "f -9 -9 -9",
        "f 0 0 0",
        "f 1 1 1",
        "f 1 2",
        "f 1",
        "f",
        "f 1/1/1 2/-99/1 3/1/1",
        "f 1/1/-99 2/1/1 3/1/1",
        "f 1//-9223372036854775808 2//1 3//1",
        "f 1/9223372036854775807/1 2/1/1 3/1/1",
        "f 1//6148914691236517206 2//1 3//1",
        "f 1/18446744073709551615/1 2/1/1 3/1/1",
        "f 1/2/3/4 2 3",
        "f 1.5 2 3",
        "v nan nan nan",
        "v inf 0 0",
        "v -inf 0 0",
        "v 1e39 0 0",
        "v 3e38 3e38 3e38",
        "v -3e38 -3e38 -3e38",
        "v 1e-45 1e-45 1e-45",
        "v 0 0 0 0",
        "v 1 1 1 1e-40",
        "v 1 2 3 0.5 0.5 0.5",
        "v 1 2 3 0.5 0.5",
        "v 1 2",
        "v",
        "vn 0 0 0",
        "vn nan 0 0",
        "vn inf inf inf",
        "vn 1e30 1e30 1e30",
        "vn 0 0 7",
        "vt nan nan",
        "vt inf 0",
        "vt 0",
        "l 1 2",
        "p 1",
        "mtllib missing.mtl",
        "mtllib",
        "usemtl nothing",
        "usemtl",
        "o",
        "o thing",
        "g",
        "g one two",
        "s off",
        "s 1",
        "#",
        "\\",
        "",
        "\r",
        "\t v 0 0 0",
        "\u{feff}v 0 0 0",
    ]
    .iter()
    .map(|line| line.as_bytes().to_vec())
    .collect();
    lines.push(b"\xff\xfe not UTF-8".to_vec());
    lines.push(b"v 0 0 \xc3".to_vec());
    lines.push(format!("# {}", "x".repeat(100_000)).into_bytes());
    lines.push(format!("v{}", " 1".repeat(10_000)).into_bytes());
    lines.push(format!("f{}", " 1 2 3".repeat(10_000)).into_bytes());
    lines.push(format!("f{}", " -1".repeat(10_000)).into_bytes());
    lines
}

#[derive(Debug, Clone)]
enum Mutation {
    Flip {
        at: Index,
        bit: u8,
    },
    Set {
        at: Index,
        byte: u8,
    },
    Delete {
        at: Index,
        len: usize,
    },
    Duplicate {
        from: Index,
        len: usize,
        to: Index,
    },
    Truncate {
        at: Index,
    },
    /// A line inserted at the start of a line.
    Insert {
        at: Index,
        line: Vec<u8>,
    },
}

impl Mutation {
    fn apply(&self, text: &mut Vec<u8>) {
        let len = text.len();
        match self {
            _ if len == 0 && !matches!(self, Mutation::Insert { .. }) => {}
            Mutation::Flip { at, bit } => text[at.index(len)] ^= 1 << bit,
            Mutation::Set { at, byte } => text[at.index(len)] = *byte,
            Mutation::Delete { at, len: n } => {
                let start = at.index(len);
                text.drain(start..(start + n).min(len));
            }
            Mutation::Duplicate { from, len: n, to } => {
                let start = from.index(len);
                let copy = text[start..(start + n).min(len)].to_vec();
                let to = to.index(len + 1);
                text.splice(to..to, copy);
            }
            Mutation::Truncate { at } => text.truncate(at.index(len)),
            Mutation::Insert { at, line } => {
                let starts: Vec<usize> = std::iter::once(0)
                    .chain(
                        text.iter()
                            .enumerate()
                            .filter(|(_, b)| **b == b'\n')
                            .map(|(i, _)| i + 1),
                    )
                    .collect();
                let start = starts[at.index(starts.len())];
                let mut line = line.clone();
                line.push(b'\n');
                text.splice(start..start, line);
            }
        }
    }
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let line = prop_oneof![
        2 => prop::sample::select(nasty_lines()),
        1 => grammar_line(true).prop_map(String::into_bytes),
    ];
    prop_oneof![
        2 => (any::<Index>(), 0..8u8).prop_map(|(at, bit)| Mutation::Flip { at, bit }),
        2 => (any::<Index>(), any::<u8>()).prop_map(|(at, byte)| Mutation::Set { at, byte }),
        2 => (any::<Index>(), 1..64usize).prop_map(|(at, len)| Mutation::Delete { at, len }),
        1 => (any::<Index>(), 1..64usize, any::<Index>())
            .prop_map(|(from, len, to)| Mutation::Duplicate { from, len, to }),
        1 => any::<Index>().prop_map(|at| Mutation::Truncate { at }),
        4 => (any::<Index>(), line).prop_map(|(at, line)| Mutation::Insert { at, line }),
    ]
}

fn mutated_file() -> impl Strategy<Value = Vec<u8>> {
    (
        prop::sample::select(vec![CUBE, TRIANGLE]),
        prop::collection::vec(mutation(), 1..5),
    )
        .prop_map(|(seed, mutations)| {
            let mut text = seed.as_bytes().to_vec();
            for mutation in &mutations {
                mutation.apply(&mut text);
            }
            text
        })
}

#[test]
fn fuzz_mutations_of_valid_files() {
    let (loaded, refused) = fuzz(2000, mutated_file());
    // Neither all loaded nor all refused: the mutations reach past the first checks.
    assert!(loaded > 100, "only {loaded} of 2000 loaded");
    assert!(refused > 100, "only {refused} of 2000 refused");
}

// ---- Random files from a small grammar ----

/// A number for `v`, `vt` or `vn`: usually an ordinary one, at times a huge or tiny one; when `wild`,
/// also one that is not finite or not a number.
fn number(wild: bool) -> BoxedStrategy<String> {
    let sane = prop_oneof![
        4 => (-3i32..4).prop_map(|n| n.to_string()),
        4 => (-100.0f32..100.0).prop_map(|x| x.to_string()),
        // Finite, but huge or tiny: sizes, centres and cross products that overflow or vanish.
        1 => (-3.4f32..3.4, -45i32..=38).prop_map(|(m, e)| format!("{m}e{e}")),
    ];
    if !wild {
        return sane.boxed();
    }
    prop_oneof![
        4 => sane,
        1 => any::<f32>().prop_map(|x| format!("{x:e}")),
        1 => any::<f64>().prop_map(|x| x.to_string()),
        1 => prop::sample::select(vec![
            "nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e39", "-1e39", "3.4e38", "-3.4e38",
            "1e-45", "-0", "1e-30", "1e30", "0x10", "1,5", "x", "",
        ])
        .prop_map(str::to_string),
    ]
    .boxed()
}

/// An index in a face: usually one of the first or last four; when `wild`, also zero, negative (relative),
/// huge, or not a number.
fn index(wild: bool) -> BoxedStrategy<String> {
    // Every file starts with at least 4 of each (see `grammar_file`).
    let sane = prop_oneof![1i64..=4, -4i64..=-1].prop_map(|n| n.to_string());
    if !wild {
        return sane.boxed();
    }
    prop_oneof![
        4 => sane,
        2 => (-12i64..0).prop_map(|n| n.to_string()),
        1 => (-1_000_000i64..1_000_000).prop_map(|n| n.to_string()),
        1 => any::<i64>().prop_map(|n| n.to_string()),
        1 => prop::sample::select(vec![
            "0",
            "9223372036854775807",
            "-9223372036854775808",
            "18446744073709551615",
            "4294967296",
            "6148914691236517206",
            "-6148914691236517206",
            "99999999999999999999",
            "1.5",
            "a",
            "",
        ])
        .prop_map(str::to_string),
    ]
    .boxed()
}

/// One corner of a face: `v`, `v/vt`, `v//vn` or `v/vt/vn`.
fn corner(wild: bool) -> impl Strategy<Value = String> {
    prop_oneof![
        index(wild),
        (index(wild), index(wild)).prop_map(|(v, t)| format!("{v}/{t}")),
        (index(wild), index(wild)).prop_map(|(v, n)| format!("{v}//{n}")),
        (index(wild), index(wild), index(wild)).prop_map(|(v, t, n)| format!("{v}/{t}/{n}")),
    ]
}

/// One line of an OBJ file. When not `wild`, a file of such lines loads when its faces name no more
/// vertices, texture coordinates and normals than it has; `wild` adds all the rest.
fn grammar_line(wild: bool) -> BoxedStrategy<String> {
    let n = || number(wild);
    let corners = if wild { 0..9 } else { 3..7 };
    let sane = prop_oneof![
        8 => (n(), n(), n()).prop_map(|(x, y, z)| format!("v {x} {y} {z}")),
        2 => (n(), n()).prop_map(|(u, v)| format!("vt {u} {v}")),
        2 => (n(), n(), n()).prop_map(|(x, y, z)| format!("vn {x} {y} {z}")),
        6 => prop::collection::vec(corner(wild), corners)
            .prop_map(|c| format!("f {}", c.join(" "))),
        1 => (index(wild), index(wild)).prop_map(|(a, b)| format!("l {a} {b}")),
        1 => index(wild).prop_map(|a| format!("p {a}")),
        1 => prop::sample::select(vec![
            "", "# comment", "o", "o thing", "g", "g group", "s off", "s 1", "mtllib missing.mtl",
            "usemtl stone",
        ])
        .prop_map(str::to_string),
    ];
    if !wild {
        return sane.boxed();
    }
    prop_oneof![
        8 => sane,
        1 => (n(), n(), n(), n()).prop_map(|(x, y, z, w)| format!("v {x} {y} {z} {w}")),
        1 => (n(), n(), n(), n(), n(), n())
            .prop_map(|(x, y, z, r, g, b)| format!("v {x} {y} {z} {r} {g} {b}")),
        1 => prop::collection::vec(index(true), 0..6).prop_map(|i| format!("l {}", i.join(" "))),
    ]
    .boxed()
}

/// At least four of each of `v`, `vt` and `vn` for the faces to name, up to 200 ordinary lines, and up
/// to 3 wild ones among them.
fn grammar_file() -> impl Strategy<Value = Vec<u8>> {
    let n = || number(false);
    let prelude = (
        prop::collection::vec(
            (n(), n(), n()).prop_map(|(x, y, z)| format!("v {x} {y} {z}")),
            4..8,
        ),
        prop::collection::vec((n(), n()).prop_map(|(u, v)| format!("vt {u} {v}")), 4..6),
        prop::collection::vec(
            (n(), n(), n()).prop_map(|(x, y, z)| format!("vn {x} {y} {z}")),
            4..6,
        ),
    )
        .prop_map(|(v, vt, vn)| [v, vt, vn].concat());
    (
        prelude,
        prop::collection::vec(grammar_line(false), 0..200),
        prop::collection::vec((any::<Index>(), grammar_line(true)), 0..4),
        prop::sample::select(vec!["\n", "\r\n"]),
    )
        .prop_map(|(prelude, body, wild, end)| {
            let mut lines = [prelude, body].concat();
            for (at, line) in wild {
                let at = at.index(lines.len() + 1);
                lines.insert(at, line);
            }
            let mut text = lines.join(end);
            text.push_str(end);
            text.into_bytes()
        })
}

#[test]
fn fuzz_random_files_from_a_grammar() {
    let (loaded, refused) = fuzz(1000, grammar_file());
    assert!(loaded > 50, "only {loaded} of 1000 loaded");
    assert!(refused > 50, "only {refused} of 1000 refused");
}

// ---- Fixed edge cases ----

fn loads(text: impl AsRef<[u8]>) -> MeshData {
    match load(text.as_ref(), LIMIT).unwrap_or_else(|problem| panic!("{problem}")) {
        Outcome::Loaded(mesh) => mesh,
        Outcome::Refused(message) => panic!("refused a good file: {message}"),
    }
}

fn refuses(text: impl AsRef<[u8]>, expected: &str) {
    match load(text.as_ref(), LIMIT).unwrap_or_else(|problem| panic!("{problem}")) {
        Outcome::Refused(message) => assert!(
            message.contains(expected),
            "expected {expected:?} in {message:?}"
        ),
        Outcome::Loaded(mesh) => panic!(
            "loaded {} triangles from {}, expected an error",
            mesh.triangle_count(),
            escaped(text.as_ref())
        ),
    }
}

#[test]
fn fuzz_seeds_load() {
    assert_eq!(loads(CUBE).triangle_count(), 12);
    assert_eq!(loads(TRIANGLE).triangle_count(), 1);
}

#[test]
fn fuzz_empty_and_comment_only_files_have_no_triangles() {
    refuses("", "no triangles");
    refuses("# nothing\n#\n   # still nothing\n\n", "no triangles");
}

#[test]
fn fuzz_lines_and_points_are_no_triangles() {
    // Two points each: tobj reads an `l` of three or more points as a face.
    refuses("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\n", "no triangles");
    refuses("v 0 0 0\nv 1 0 0\nv 0 1 0\np 1\np 2 3\n", "no triangles");
    refuses("v 0 0 0\nv 1 0 0\nf 1 2\nf 2\n", "no triangles");
}

#[test]
fn fuzz_a_face_with_a_huge_index_is_refused() {
    refuses(format!("{TRIANGLE}f 1 2 999999\n"), "not a valid OBJ");
    refuses(
        format!("{TRIANGLE}f 1 2 9223372036854775807\n"),
        "not a valid OBJ",
    );
    refuses(format!("{TRIANGLE}f 1 2 -99\n"), "not a valid OBJ");
}

#[test]
fn fuzz_vertices_that_are_not_numbers_are_refused() {
    refuses("v nan nan nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "not finite");
    refuses("v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n", "not finite");
    refuses("v 0 0 0\nv 1e39 0 0\nv 0 1 0\nf 1 2 3\n", "not finite");
}

#[test]
fn fuzz_a_truncated_file_is_refused_or_loads_what_it_has() {
    let cut = CUBE.find("f 5/1/6 2/3/6").unwrap() + "f 5/1/6 2/".len();
    let mesh = loads(&CUBE[..cut]);
    assert_eq!(
        mesh.triangle_count(),
        11,
        "the cut face has two corners: a line, ignored"
    );
    let cut = CUBE.find("f 1/1/1").unwrap() + "f 1/1".len();
    refuses(&CUBE[..cut], "no triangles");
    let cut = CUBE.find("v 1 1 -1").unwrap() + "v 1 1".len();
    refuses(&CUBE[..cut], "not a valid OBJ");
}

#[test]
fn fuzz_a_degenerate_mesh_is_at_one_point() {
    refuses(
        "v 2 2 2\nv 2 2 2\nv 2 2 2\nv 2 2 2\nf 1 2 3\nf 1 3 4\n",
        "one point",
    );
}

#[test]
fn fuzz_huge_coordinates_are_placed() {
    // Far from the origin: the sum of the box's corners is past the largest f32.
    let far = loads("v 3e38 3e38 3e38\nv 3.2e38 3e38 3e38\nv 3e38 3.2e38 3e38\nf 1 2 3\n");
    // Wider than the largest f32: so is the box's size.
    let wide = loads("v -3e38 0 0\nv 3e38 0 0\nv 0 3e38 0\nf 1 2 3\n");
    for mesh in [far, wide] {
        for vertex in &mesh.vertices {
            // Computed from the faces, which a cross product of huge edges must not spoil.
            assert!(
                Vec3::from(vertex.normal).abs_diff_eq(Vec3::Z, 1e-6),
                "{vertex:?}"
            );
        }
    }
}

#[test]
fn fuzz_a_million_vertices_load_within_seconds() {
    use std::fmt::Write;
    const SIDE: usize = 1000;
    let mut text = String::with_capacity(48 << 20);
    for j in 0..SIDE {
        for i in 0..SIDE {
            writeln!(text, "v {i} {} {j}", (i * j) % 7).unwrap();
        }
    }
    // A quad over every cell of the grid: 998,001 quads, twice as many triangles.
    for j in 0..SIDE - 1 {
        for i in 0..SIDE - 1 {
            let a = j * SIDE + i + 1;
            writeln!(text, "f {a} {} {} {}", a + SIDE, a + SIDE + 1, a + 1).unwrap();
        }
    }
    let limit = Duration::from_secs(10);
    let start = Instant::now();
    let outcome = load(text.as_bytes(), limit).unwrap_or_else(|problem| panic!("{problem}"));
    let took = start.elapsed();
    let Outcome::Loaded(mesh) = outcome else {
        panic!("a million vertices were refused: {outcome:?}");
    };
    assert_eq!(mesh.vertices.len(), SIDE * SIDE);
    assert_eq!(mesh.triangle_count(), 2 * (SIDE - 1) * (SIDE - 1));
    assert!(took < limit, "loading a million vertices took {took:?}");
}

// ---- The corpus ----

/// Every file in tests/fuzz-corpus: the inputs that once failed, and nasty ones made by hand.
#[test]
fn fuzz_corpus_replays() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("fuzz-corpus");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|e| e == "obj"))
        .collect();
    files.sort();
    assert!(files.len() >= 5, "the corpus has {} files", files.len());
    let mut failures = Vec::new();
    for file in &files {
        let bytes = std::fs::read(file).unwrap();
        let name = file.file_name().unwrap().to_string_lossy();
        if !bytes.starts_with(b"# why: ") {
            failures.push(format!("{name}: the first line is not `# why: ...`"));
        }
        if let Err(problem) = load(&bytes, LIMIT) {
            failures.push(format!("{name}: {problem}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

/// The most the loader may hold, as a multiple of the file's size: the test's own figure, not the
/// loader's constant (a loader that held more and raised its constant would pass a test that read
/// it). Measured: 4.15 for the skull, 6.46 for the grid (`MAX_MEMORY_MULTIPLE`'s comment in
/// `room/mesh.rs` accounts for every part of it); a loader that keeps one more copy of the text
/// holds 7.5 for the grid, and fails.
const MEMORY_MULTIPLE: f64 = 7.0;

/// The loader holds a bounded multiple of the file's size: measured by the suite's counting
/// allocator in a child process of its own (other tests' allocations would blur the peak), on the
/// repository's skull (1.7 MB) and on a generated 1,000×1,000-vertex grid (a 71 MB OBJ, as dense as
/// a scan and larger than most). The child reports each load's time too (`--nocapture` shows it).
#[test]
fn loading_a_model_holds_a_bounded_multiple_of_its_size() {
    let output = std::process::Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "fuzz::model_memory_child",
            "--ignored",
            "--nocapture",
        ])
        .env("MODEL_MEMORY_CHILD", "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "the child failed:\n{stdout}");
    let lines: Vec<&str> = stdout
        .lines()
        .filter_map(|line| line.find("model memory: ").map(|at| &line[at..]))
        .collect();
    assert_eq!(lines.len(), 2, "no report for each model in:\n{stdout}");
    for line in lines {
        println!("{line}");
        let number = |key: &str| -> f64 {
            let field = line.split_whitespace().find_map(|f| f.strip_prefix(key));
            field.and_then(|n| n.parse().ok()).unwrap()
        };
        let multiple = number("peak_bytes=") / number("file_bytes=");
        assert!(
            multiple <= MEMORY_MULTIPLE,
            "loading held {multiple:.2} times the file's size: {line}"
        );
    }
}

/// Run by the test above in a process of its own.
#[test]
#[ignore = "run by loading_a_model_holds_a_bounded_multiple_of_its_size in a child process"]
fn model_memory_child() {
    if std::env::var_os("MODEL_MEMORY_CHILD").is_none() {
        return;
    }
    let skull = workbook::room::scene::default_assets().join("skull.obj");
    measure_model("skull", &skull, 5);
    let n = 1000;
    let mut text = String::new();
    for i in 0..n {
        for j in 0..n {
            let y = ((i as f32 * 0.1).sin() * (j as f32 * 0.1).cos() * 0.1).to_string();
            text += &format!("v {} {y} {}\n", i as f32 / n as f32, j as f32 / n as f32);
        }
    }
    for i in 0..n - 1 {
        for j in 0..n - 1 {
            let (a, c) = (i * n + j + 1, (i + 1) * n + j + 1);
            text += &format!("f {a} {c} {}\nf {} {c} {}\n", a + 1, a + 1, c + 1);
        }
    }
    let path = std::env::temp_dir().join(format!("model-memory-{}.obj", std::process::id()));
    std::fs::write(&path, &text).unwrap();
    drop(text);
    measure_model("grid", &path, 1);
    let _ = std::fs::remove_file(&path);
}

/// Loads a model `times` times and prints one line: its size, the most heap one load held above
/// what was held before it, and the fastest load's time.
fn measure_model(name: &str, path: &std::path::Path, times: usize) {
    let file_bytes = std::fs::metadata(path).unwrap().len();
    let (mut peak, mut fastest) = (0, Duration::MAX);
    let mut mesh = MeshData::default();
    for _ in 0..times {
        drop(mesh);
        crate::heap::reset_peak();
        let base = crate::heap::live_bytes();
        let started = Instant::now();
        mesh = MeshData::load_obj(path).unwrap();
        fastest = fastest.min(started.elapsed());
        peak = peak.max(crate::heap::peak_bytes() - base);
    }
    println!(
        "model memory: {name} file_bytes={file_bytes} peak_bytes={peak} multiple={:.2} \
         load_ms={:.1} vertices={} triangles={}",
        peak as f64 / file_bytes as f64,
        fastest.as_secs_f64() * 1e3,
        mesh.vertices.len(),
        mesh.triangle_count()
    );
}
