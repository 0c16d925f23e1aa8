#!/usr/bin/env bash
# Start-up and build figures for the book's cost page: headless start to PNG for every lesson (debug
# and release, the median of 5 runs at 1280x720), the rebuild after editing one lesson, and with
# --cold the clean build of the whole workspace (debug, in a target folder of its own).
# Usage: scripts/measure-startup.sh [--cold]
set -euo pipefail
cd "$(dirname "$0")/.."
export XDG_RUNTIME_DIR="${XDG_RUNTIME_DIR:-$(mktemp -d)}"
lessons=$(sed -n 's|^    "chapters/[0-9]*-\(.*\)",|\1|p' Cargo.toml)

median() { sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
seconds() { # command...: wall seconds of one run
  local start end
  start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N)
  awk "BEGIN { print $end - $start }"
}

cargo build --quiet --workspace --bins
cargo build --quiet --release --workspace --bins
out=$(mktemp -d)
printf '%-20s %10s %10s\n' lesson "debug s" "release s"
for lesson in $lessons; do
  row=()
  for profile in debug release; do
    row+=("$(for _ in 1 2 3 4 5; do seconds "target/$profile/$lesson" --screenshot "$out/$lesson.png"; done | median)")
  done
  printf '%-20s %10.3f %10.3f\n' "$lesson" "${row[0]}" "${row[1]}"
done

touch chapters/01-depth-test/src/lib.rs
printf 'rebuild after editing lesson 1: %.1f s\n' "$(seconds cargo build --quiet -p depth-test)"

if [ "${1:-}" = "--cold" ]; then
  cold=$(mktemp -d)
  printf 'clean debug build of the workspace: %.0f s\n' \
    "$(seconds env CARGO_TARGET_DIR="$cold" cargo build --quiet --workspace)"
  rm -rf "$cold"
fi
