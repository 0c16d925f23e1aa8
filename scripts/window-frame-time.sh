#!/usr/bin/env bash
# A lesson's frame time in a real window under Xvfb (1280×720, lavapipe), with the workbench's panel
# and without it (--no-panel): the window draws continuously with --frames, and the time per frame is
# that of frames 60 to 180 (a run of 180 frames less a run of 60: the start, the first frames and the
# panel's comparison with the book are in both). Three runs each, debug and release.
#
#   scripts/window-frame-time.sh [LESSON]      (default: reflect-skull)
set -euo pipefail
cd "$(dirname "$0")/.."
lesson=${1:-reflect-skull}
if [[ "${2:-}" != --inside ]]; then
    cargo build --quiet -p "$lesson"
    cargo build --quiet --release -p "$lesson"
    exec xvfb-run -a -s "-screen 0 1280x720x24" "$0" "$lesson" --inside
fi
calc() { awk "BEGIN { printf \"%.3f\", $1 }"; }
seconds() { local start end; start=$(date +%s.%N); "$@" > /dev/null 2>&1; end=$(date +%s.%N); calc "$end - $start"; }
per_frame() { # binary [args]: ms per frame over frames 60..180
    local short long
    short=$(seconds "$@" --frames 60)
    long=$(seconds "$@" --frames 180)
    calc "($long - $short) * 1000 / 120"
}
echo "$lesson, 1280x720, ms per frame: with the panel / without (--no-panel)"
for profile in debug release; do
    for run in 1 2 3; do
        with=$(per_frame "target/$profile/$lesson")
        without=$(per_frame "target/$profile/$lesson" --no-panel)
        echo "$profile run $run: $with / $without ms ($(calc "($with / $without - 1) * 100")%)"
    done
done
