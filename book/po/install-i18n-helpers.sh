#!/usr/bin/env bash
# Installs mdbook-xgettext, mdbook-gettext and mdbook-i18n-normalize from mdbook-i18n-helpers 0.4.0
# (the only release for mdBook 0.5) with the patch beside this script (math kept intact, emphasis written with `*`), into cargo's bin folder.
#
# Why patched: 0.4.0 parses Markdown without pulldown-cmark's math option, so it re-renders the TeX
# in `$...$` and `$$...$$` as prose: backslashes dropped (`\,` `\{` `\&`), `_` and `<` escaped,
# display blocks folded onto one line (upstream issue #105). The patch turns the option on and
# keeps math inside the message it stands in. It also writes emphasis back as `*...*`, not `_..._`,
# which does not work next to Chinese characters. See TOOLCHAIN.md.
#
# Idempotent: does nothing when `mdbook-xgettext --version` already names the patched build (the
# unpatched one has no --version). Needs cargo, the crates.io registry and, if `patch` is missing,
# apt-get. Build jobs: set CARGO_BUILD_JOBS as usual.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
want="mdbook-xgettext 0.4.0+math+star"

if [ "$(mdbook-xgettext --version </dev/null 2>/dev/null || true)" = "$want" ]; then
  echo "i18n: $want is already installed"
  exit 0
fi

command -v patch >/dev/null || { apt-get update -qq && apt-get install -y -qq patch >/dev/null; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The crate's source, as published: cargo has no `download` command, so a scratch project that
# depends on exactly 0.4.0 makes `cargo fetch` put its .crate file into cargo's registry cache.
mkdir -p "$work/fetch/src"
cat >"$work/fetch/Cargo.toml" <<'EOF'
[package]
name = "fetch-mdbook-i18n-helpers"
version = "0.0.0"
edition = "2021"
publish = false

[dependencies]
mdbook-i18n-helpers = "=0.4.0"
EOF
touch "$work/fetch/src/lib.rs"
cargo fetch --quiet --manifest-path "$work/fetch/Cargo.toml"
crate=$(ls "${CARGO_HOME:-$HOME/.cargo}"/registry/cache/*/mdbook-i18n-helpers-0.4.0.crate | head -n 1)
tar -xzf "$crate" -C "$work"

patch -p1 --quiet -d "$work/mdbook-i18n-helpers-0.4.0" <"$here/mdbook-i18n-helpers-0.4.0-workbook.patch"

# --locked: the published crate ships its Cargo.lock, so the build uses the versions upstream
# tested (pulldown-cmark 0.13.0, pulldown-cmark-to-cmark 21.0.0). --force: replaces an unpatched
# 0.4.0 that `cargo install` would otherwise take as already installed.
cargo install --locked --force --path "$work/mdbook-i18n-helpers-0.4.0"
mdbook-xgettext --version
