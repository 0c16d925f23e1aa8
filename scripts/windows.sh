#!/usr/bin/env bash
# The workbook on Windows, proven on a Linux machine without a GPU: every lesson and the test suite
# cross-built for Windows (x86_64-pc-windows-gnu, linked by Debian's mingw-w64, which also compiles
# nv-flip's C++), then every lesson run under Wine on Mesa's software Vulkan (lavapipe, reached
# through winevulkan and the host's Vulkan loader): each `.exe` renders every picture the book has of
# its lesson and judges it against the book with its own `--check` (FLIP, at the tests' limits), and
# one lesson shows its window with the side panel for 30 frames. CI runs it after the tests (.ci/run).
#
#   scripts/windows.sh
#
# It installs what it needs where missing (apt: mingw-w64, Wine, Xvfb, lavapipe; rustup: the target).
# The suite's test binaries are compiled, not run: what they need from Linux (/proc, mkfifo, a
# tmpfs, Xvfb, xdotool, `import`) says `skipped on windows: ...` in one line there.
#
# Debug builds, as `cargo run` makes them: on two cores, from an empty target folder, the lessons
# alone built in 3.5 minutes in debug and 16 in release, and their checks under Wine took 78 s in
# debug and 70 s in release. Our own crates are built here without debug information, and the .exe
# files without symbols (57 MB each instead of 103, the whole cross build 4.7 GB instead of 9).
# The whole script took 6 minutes from an empty target folder, 1.5 once built.
#
# What Wine 8 (Debian bookworm's) needs beside the .exe files, all put there by this script:
# - mingw-w64's runtime DLLs (libstdc++-6, libgcc_s_seh-1, libwinpthread-1), which nv-flip's C++
#   links. On Windows, the MinGW-w64 that compiles it has them; MSVC's toolchain needs none.
# - bcryptprimitives.dll: Rust's standard library takes its random numbers from its ProcessPrng,
#   which Windows 10 and 11 have and Wine 8 does not; scripts/windows/bcryptprimitives.c stands in.
# Vulkan, not DX12: wgpu's DX12 through Wine's vkd3d fails to open its device ("Parent device is
# lost"), and a lesson left to choose prefers that adapter (it says it is a GPU) to lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."

target=x86_64-pc-windows-gnu
out=${CARGO_TARGET_DIR:-target}/$target/debug
wine=$(command -v wine64 || echo /usr/lib/wine/wine64)
wineserver=$(command -v wineserver || echo /usr/lib/wine/wineserver)
mapfile -t lessons < <(scripts/lessons.sh)

if [[ "${1:-}" != --inside ]]; then
    echo "windows: packages (mingw-w64, Wine, Xvfb, lavapipe) and the Rust target"
    # Wine without its recommendations (GStreamer, CUPS, 32-bit Wine...); what it does need to open
    # windows on X (the X libraries winex11 loads) and Vulkan (the host's loader) is listed.
    need=()
    for package in mingw-w64 wine64 xvfb xauth mesa-vulkan-drivers libvulkan1 libxrandr2 \
        libxrender1 libxi6 libxcursor1 libxcomposite1 libxinerama1 libxfixes3 libxxf86vm1; do
        dpkg -s "$package" > /dev/null 2>&1 || need+=("$package")
    done
    if [[ ${#need[@]} -gt 0 ]]; then
        sudo=""; [[ "$(id -u)" -eq 0 ]] || sudo="sudo"
        $sudo apt-get update -qq
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${need[@]}"
    fi
    rustup target add "$target"

    echo "windows: the test suite compiled for Windows, and with it every lesson's .exe"
    # `cargo test --no-run` builds every lesson's binary too (the suite runs them), with the features
    # of the whole workspace's test build, as .ci/run's tests step builds the Linux ones; a
    # separate `cargo build -p LESSON` would build wgpu and egui a second time with other features.
    CARGO_PROFILE_DEV_DEBUG=false CARGO_PROFILE_DEV_STRIP=symbols \
        cargo test --workspace --locked --no-run --target "$target"
    for lesson in "${lessons[@]}"; do
        [[ -f "$out/$lesson.exe" ]] || { echo "windows: $out/$lesson.exe was not built" >&2; exit 1; }
    done

    echo "windows: the DLLs Wine needs beside the .exe files"
    for dll in libstdc++-6.dll libgcc_s_seh-1.dll libwinpthread-1.dll; do
        path=$(x86_64-w64-mingw32-gcc -print-file-name="$dll")
        [[ -f "$path" ]] || { echo "windows: mingw-w64 has no $dll" >&2; exit 1; }
        cp "$path" "$out/"
    done
    x86_64-w64-mingw32-gcc -shared -O2 -Wall -Werror -o "$out/bcryptprimitives.dll" \
        scripts/windows/bcryptprimitives.c -ladvapi32

    exec xvfb-run -a -s "-screen 0 1280x1024x24" bash "$0" --inside
fi

# Under Xvfb. A Wine prefix (Wine's C: drive and registry) of our own, made afresh and removed after;
# no Mono and no Gecko (Wine would offer to download them); Wine's own messages off.
WINEPREFIX=$(mktemp -d)
export WINEPREFIX WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
finish() {
    "$wineserver" -k 2> /dev/null || true
    rm -rf "$WINEPREFIX"
}
trap finish EXIT
# Mesa's software Vulkan (the book's pictures are lavapipe's), and only it, even on a machine with a
# GPU: winevulkan hands Vulkan to the host's loader, which reads these variables.
lavapipe=(/usr/share/vulkan/icd.d/lvp_icd.*.json)
[[ -f "${lavapipe[0]}" ]] || { echo "windows: no lavapipe (mesa-vulkan-drivers)" >&2; exit 1; }
lavapipe=${lavapipe[0]}
export VK_DRIVER_FILES=$lavapipe VK_ICD_FILENAMES=$lavapipe WGPU_BACKEND=vulkan
# Mesa complains on stderr without a runtime folder (the window's check wants stderr quiet).
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$WINEPREFIX}
"$wine" wineboot --init > "$WINEPREFIX.log" 2>&1 || { cat "$WINEPREFIX.log" >&2; exit 1; }
rm -f "$WINEPREFIX.log"

# Each lesson's pictures, rendered by its .exe and compared with the book's by the .exe itself (the
# paths of book/ and assets/ are built in: Wine finds them on its Z: drive, the host's /). Where
# one differs, its render and the difference image go into check/.
echo "windows: every lesson's pictures under Wine, judged against the book's by its own --check"
failed=()
pictures=0
for lesson in "${lessons[@]}"; do
    start=$(date +%s)
    status=0
    report=$(timeout 600 "$wine" "$out/$lesson.exe" --check 2>&1) || status=$?
    echo "$lesson ($(($(date +%s) - start)) s):"
    sed 's/^/  /' <<< "$report"
    pictures=$((pictures + $(grep -c ': matches the book' <<< "$report" || true)))
    [[ $status -eq 0 ]] || failed+=("$lesson")
done

# One window with its panel (shown by default), 30 frames counted in its log, and nothing else said.
echo "windows: reflect-skull's window with its panel, 30 frames, under Wine"
status=0
log=$(RUST_LOG=workbook::frames=debug timeout 300 "$wine" "$out/reflect-skull.exe" --frames 30 \
    --size 640x360 2>&1) || status=$?
frames=$(grep -c 'frame [0-9]* drawn' <<< "$log" || true)
others=$(grep -v 'frame [0-9]* drawn' <<< "$log" || true)
window=""
if [[ $status -ne 0 || $frames -ne 30 || -n "$others" ]]; then
    [[ -z "$others" ]] || sed 's/^/  /' <<< "$others"
    window="reflect-skull's window (exit $status, $frames of 30 frames drawn)"
else
    echo "  30 frames drawn, the window closed cleanly"
fi

if [[ ${#failed[@]} -gt 0 ]]; then
    echo "windows: FAILED under Wine: ${failed[*]}${window:+ and $window}" \
        "(see above; a render that differs from the book is in check/)" >&2
    exit 1
elif [[ -n "$window" ]]; then
    echo "windows: FAILED under Wine: $window (see above)" >&2
    exit 1
fi
echo "windows: all ${#lessons[@]} lessons match the book under Wine ($pictures pictures), and the window ran"
