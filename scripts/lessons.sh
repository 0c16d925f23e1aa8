#!/bin/sh
# Prints the lessons' names, one a line, in the book's order, for the scripts (`.ci/run`,
# scripts/window-shots.sh): the lines `NAME = { path = "../NN-NAME" }` of chapters/lessons/Cargo.toml's
# [dependencies], the workbook's one list of the lessons (its build.rs reads the same lines, and the
# test suite's `lessons` module checks that this prints what `lessons::LESSONS` holds).
#
#   for lesson in $(scripts/lessons.sh); do ...; done
cd "$(dirname "$0")/.." || exit 1
exec sed -n '/^\[dependencies\]$/,/^\[/ s/^\([a-z0-9-]*\) = { path = "\.\.\/[0-9][0-9]-\1" }[[:space:]]*\(#.*\)\{0,1\}$/\1/p' \
    chapters/lessons/Cargo.toml
