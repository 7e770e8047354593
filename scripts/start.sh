#!/usr/bin/env bash
# The first command of the README: installs what is missing, builds, and runs the main job on the built-in
# Cornell box (or on the SCENE and options given). With a display it opens the viewer; without one it renders
# a headless screenshot to out/ and prints where it is.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
# Only the program: the tests and benchmarks are built by scripts/test.sh, so the first picture comes sooner.
BUILD_TARGETS="${BUILD_TARGETS:-radiosity}" "$root/scripts/build.sh"
radiosity="${BUILD_DIR:-$root/build}/app/radiosity"
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec "$radiosity" "$@"
fi
mkdir -p "$root/out"
image="$root/out/cornell.png"
[ $# -eq 0 ] || image="$root/out/render.png"
echo "no display: rendering a headless screenshot instead of opening the viewer" >&2
"$radiosity" render "$@" --out "$image"
