#!/usr/bin/env bash
# Build figures for the book's cost page: the rebuild after editing one lesson, and with --cold the
# clean debug build of the whole workspace (in a target folder of its own). Start-up (headless start
# to PNG of every lesson, debug and release) is measured by `cargo bench-lessons --only start-up`.
# Usage: scripts/measure-build.sh [--cold]
set -euo pipefail
cd "$(dirname "$0")/.."

seconds() { # command...: wall seconds of one run
  local start end
  start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N)
  awk "BEGIN { print $end - $start }"
}

cargo build --quiet --workspace --bins
touch chapters/01-depth-test/src/lib.rs
printf 'rebuild after editing lesson 1: %.1f s\n' "$(seconds cargo build --quiet -p depth-test)"

if [ "${1:-}" = "--cold" ]; then
  cold=$(mktemp -d)
  printf 'clean debug build of the workspace: %.0f s\n' \
    "$(seconds env CARGO_TARGET_DIR="$cold" cargo build --quiet --workspace)"
  rm -rf "$cold"
fi
