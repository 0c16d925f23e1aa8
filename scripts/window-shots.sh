#!/usr/bin/env bash
# Pictures of every lesson's window with its side panel, as a learner sees it, for the book's
# "Running the lessons" page: each lesson runs in a real window under Xvfb at 1280×720, and after
# WAIT seconds (the panel's timings and its comparison with the book need a few frames) the screen
# is captured with ImageMagick. Needs xvfb-run, xdotool and ImageMagick (`import`). For the lessons in
# PICKS, a second picture has a pixel of the view right-clicked: the panel tells its story.
#
#   scripts/window-shots.sh [LESSON...]      (default: every lesson, scripts/lessons.sh)
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" != --inside ]]; then
    cargo build --quiet --workspace --bins
    exec xvfb-run -a -s "-screen 0 1280x720x24" "$0" --inside "$@"
fi
shift
lessons=("$@")
if [[ ${#lessons[@]} -eq 0 ]]; then
    mapfile -t lessons < <(scripts/lessons.sh)
fi
# The pixel right-clicked in LESSON-pixel.jpg, in the window's pixels.
declare -A PICKS=([mark-mirror]="470 250")
out=book/src/images/window
mkdir -p "$out" /tmp/workbook-window-shots
for lesson in "${lessons[@]}"; do
    log=/tmp/workbook-window-shots/$lesson.log
    "target/debug/$lesson" --resolution full > "$log" 2>&1 &
    pid=$!
    if ! timeout 30 xdotool search --sync --name "^$lesson " > /dev/null; then
        echo "window-shots: $lesson opened no window:" >&2; cat "$log" >&2; exit 1
    fi
    sleep "${WAIT:-8}"
    import -window root -quality 92 "$out/$lesson.jpg"
    if [[ -n "${PICKS[$lesson]:-}" ]]; then
        read -r x y <<< "${PICKS[$lesson]}"
        xdotool mousemove "$x" "$y" click 3
        sleep "${WAIT:-8}"
        import -window root -quality 92 "$out/$lesson-pixel.jpg"
        echo "wrote $out/$lesson-pixel.jpg"
    fi
    kill "$pid"; wait "$pid" 2>/dev/null || true
    echo "wrote $out/$lesson.jpg"
done
