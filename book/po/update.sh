#!/usr/bin/env bash
# After editing the English book: extracts its messages into po/messages.pot (not committed: its date
# changes on every extraction) and merges them into every translation (po/*.po). A changed English
# sentence comes back "fuzzy", with the old translation as a draft, and a new one empty: the book's
# build fails until each is translated (see README.md here). Needs the patched mdbook-xgettext
# (install-i18n-helpers.sh) and GNU gettext.
set -euo pipefail
cd "$(dirname "$0")/.."

# Without the default preprocessors: `links` must not run, so that the messages are the Markdown as
# written, which is what mdbook-gettext sees when it translates (it runs before `links`). mdBook then
# warns that `links`, named in book.toml, is not there: expected, and filtered out.
MDBOOK_BUILD__USE_DEFAULT_PREPROCESSORS=false MDBOOK_OUTPUT='{"xgettext": {}}' \
  mdbook build -d po 2>&1 | grep -v 'contains "links", which was not found' || true
test -s po/messages.pot || { echo "update.sh: no po/messages.pot was written" >&2; exit 1; }

shopt -s nullglob
for po in po/*.po; do
  msgmerge --quiet --update --backup=none --no-wrap --previous "$po" po/messages.pot
  echo "$po: $(msgfmt --statistics -o /dev/null "$po" 2>&1)"
done
