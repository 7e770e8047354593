#!/usr/bin/env bash
# Installs the Debian packages the project needs, and only those that are missing. Safe to run again.
set -euo pipefail

packages=(
  g++ cmake ninja-build pkg-config
  libopenmesh-dev libembree-dev libtbb-dev libglm-dev
  libtinyobjloader-dev libcli11-dev libeigen3-dev nlohmann-json3-dev libtinygltf-dev
  libgtest-dev libbenchmark-dev
  python3-glad libegl-dev libegl-mesa0 libosmesa6-dev libgl1-mesa-dri libstb-dev libtinyexr-dev
  libglfw3-dev libimgui-dev xvfb xauth
  # scripts/fuzz.sh: clang with its libFuzzer and sanitizer runtimes (libclang-rt-dev), and llvm for
  # llvm-symbolizer, which turns the sanitizers' stack traces into file:line.
  clang libclang-rt-dev llvm
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo_cmd=(sudo)
fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
# A fresh machine has no package lists yet; refresh them when an install cannot find a package.
if ! "${sudo_cmd[@]}" apt-get install -y --no-install-recommends "${missing[@]}" >/dev/null 2>&1; then
  "${sudo_cmd[@]}" apt-get update -q >/dev/null
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
