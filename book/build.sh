#!/usr/bin/env bash
# Builds the book into book/build/html and fails on any ERROR or WARN that mdBook logs: mdBook itself exits 0
# on a missing include, a bad anchor or broken math. Needs mdbook 0.5.3, mdbook-katex 0.10.0 and
# mdbook-linkcheck2 0.13.0 (see .ci/run), and npm for KaTeX's CSS and fonts.
set -euo pipefail
cd "$(dirname "$0")"

# KaTeX's stylesheet and fonts, from npm (not committed: they are someone else's files).
if [ ! -f katex/katex.min.css ] || [ ! -d src/katex/fonts ]; then
  work=$(mktemp -d)
  (cd "$work" && npm pack --silent katex@0.16.4 >/dev/null && tar xzf katex-0.16.4.tgz)
  mkdir -p katex src/katex/fonts
  cp "$work/package/dist/katex.min.css" katex/katex.min.css
  cp "$work"/package/dist/fonts/* src/katex/fonts/
  rm -rf "$work"
fi

# The web edition: every lesson's module, its bindings and the room's assets into src/live, which mdBook
# copies into the book (needs wasm-bindgen-cli of the crate's version, and npm for wasm-opt).
cargo web ${CI:+--locked}

log=$(mktemp)
status=0
mdbook build 2>&1 | tee "$log" || status=$?
if [ "$status" -ne 0 ]; then
  echo "book: mdbook failed (exit $status)" >&2
  exit 1
fi
if grep -iE "error|warn" "$log" >/dev/null; then
  echo "book: mdbook logged errors or warnings (above); the book is not clean" >&2
  exit 1
fi
echo "book: built into book/build/html"
