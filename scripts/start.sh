#!/usr/bin/env bash
# The first command of the README: installs what is missing, builds, and runs the main job on the built-in
# Cornell box. The interactive viewer is not there yet, so for now this prints the scene's summary.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
"$root/scripts/build.sh"
"${BUILD_DIR:-$root/build}/app/radiosity" "$@"
