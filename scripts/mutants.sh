#!/usr/bin/env bash
# Mutation testing of the framework's pure code, the code tested without a GPU: cargo-mutants makes
# each small change a bug could be (`<` for `<=`, `true` for a function's result, a deleted `!`),
# builds, and runs the workbook crate's own unit tests; a change they do not notice is "missed".
#
#   scripts/mutants.sh [ARGS...]    extra ARGS go to cargo mutants (e.g. -f shared/src/math/clip.rs)
#
# The modules: math/ (reflection, clip planes, shadow, the stencil model), lesson/ knobs, steps and
# a pixel's story (its CPU model of the tests), book/flip.rs (the screenshots' judge), and the OBJ
# pre-pass of room/mesh.rs (the checks before tobj reads a model). The suite's GPU tests are not
# run (each mutant would cost minutes): what the unit tests miss here is a gap they must close, or
# a mutant that changes nothing a test could see (say which in the closing note).
#
# Not in CI: it takes about 40 minutes on two cores (a build of the workbook's dependencies, then
# a few seconds a mutant; a mutant that loops forever waits out the timeout). The report is in
# target/mutants/mutants.out (caught.txt, missed.txt, timeout.txt, unviable.txt).
set -euo pipefail
cd "$(dirname "$0")/.."

version=27.1.0
if ! cargo mutants --version 2>/dev/null | grep -q "$version"; then
  cargo install --locked cargo-mutants --version "$version"
fi

pre_pass='mesh\.rs.*(check_faces|is_space|FaceChecker|parse_i64|read_models)'
cargo mutants -p workbook --output target/mutants --timeout 30 \
  -f 'shared/src/math/*.rs' -f shared/src/lesson/knobs.rs -f shared/src/lesson/steps.rs \
  -f shared/src/lesson/story.rs -f shared/src/book/flip.rs -f shared/src/room/mesh.rs \
  --re '^shared/src/(math|lesson|book)/' --re "$pre_pass" "$@" -- --lib
