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

# Builds the book with `mdbook build` and the environment given, into DEST (relative to book/), and
# fails on any error or warning mdBook logs.
build() {
  local dest=$1; shift
  local log status=0
  log=$(mktemp)
  env "$@" mdbook build -d "$dest" 2>&1 | tee "$log" || status=$?
  if [ "$status" -ne 0 ]; then
    echo "book: mdbook failed (exit $status) building $dest" >&2
    exit 1
  fi
  if grep -iE "error|warn" "$log" >/dev/null; then
    echo "book: mdbook logged errors or warnings building $dest (above); the book is not clean" >&2
    exit 1
  fi
}

# English, at the root of build/html.
build build

# Translations (see po/README.md). Each language's messages must match the English as it is now:
# every message of a fresh extraction translated, none fuzzy, or the build fails and says which.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
MDBOOK_BUILD__USE_DEFAULT_PREPROCESSORS=false MDBOOK_OUTPUT='{"xgettext": {}}' \
  mdbook build -d "$work/pot" >"$work/extract.log" 2>&1 || { cat "$work/extract.log"; exit 1; }
for po in po/*.po; do
  language=$(basename "$po" .po)
  if ! msgcmp "$po" "$work/pot/messages.pot" 2>"$work/msgcmp.log"; then
    grep -v 'this message is not used' "$work/msgcmp.log" | head -20 >&2
    echo "book: $po lacks translations of the English as it is now ($(sed -n 's/.*found \([0-9]*\) fatal error.*/\1/p' "$work/msgcmp.log") messages: untranslated, fuzzy or new; the first are above); run book/po/update.sh and translate them (book/po/README.md)" >&2
    exit 1
  fi
  # One voice: the glossary's Chinese for each of its terms, and Chinese punctuation in alt texts and
  # captions (po/check-terms.py; the glossary has a Chinese column only).
  if [ "$language" = zh-CN ] && ! python3 po/check-terms.py "$po"; then
    echo "book: $po does not follow the glossary (src/glossary.md) or po/README.md (the problems are above)" >&2
    exit 1
  fi
  # The book's title is no message of any page: it is the .po header's X-Book-Title.
  title=$(sed -n 's/^"X-Book-Title: \(.*\)\\n"$/\1/p' "$po")
  settings=(MDBOOK_BOOK__LANGUAGE="$language")
  [ -z "$title" ] || settings+=(MDBOOK_BOOK__TITLE="$title")
  build "$work/$language" "${settings[@]}"
  # A language written without spaces: its search index holds the text as characters and pairs of
  # characters, which web/search.js cuts a query into (po/cjk-search.py).
  case "$language" in
    zh* | ja* | ko*) python3 po/cjk-search.py "$work/$language/html" ;;
  esac
  if grep -rl 'katex-error' "$work/$language/html" --include=*.html; then
    echo "book: KaTeX errors in the $language book (the pages above)" >&2
    exit 1
  fi
  rm -rf "build/html/$language"
  mv "$work/$language/html" "build/html/$language"
done

# The round trip: a translation with every message empty gives the English book back, page for page
# (whitespace aside) and formula for formula. This guards the patch that keeps the TeX intact
# through gettext (po/TOOLCHAIN.md).
mkdir -p "$work/empty"
sed 's/charset=CHARSET/charset=UTF-8/' "$work/pot/messages.pot" >"$work/empty/xx.po"
build "$work/xx" MDBOOK_BOOK__LANGUAGE=xx MDBOOK_PREPROCESSOR__GETTEXT__PO_DIR="$work/empty"
python3 po/round_trip.py build/html "$work/xx/html"

echo "book: built into book/build/html (and $(ls po/*.po | sed 's|po/\(.*\)\.po|build/html/\1|' | paste -sd ' '))"
