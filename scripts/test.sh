#!/usr/bin/env bash
# The second command of the README: installs what is missing, builds, and runs every test.
# With SANITIZE=1 it builds a Debug build with AddressSanitizer and UndefinedBehaviorSanitizer into
# build-sanitize and runs the same tests there. The default run then runs the fuzz smoke (scripts/fuzz.sh,
# about a minute plus its clang build); FUZZ=0 skips it.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
if [ "${SANITIZE:-0}" = 1 ]; then
  export BUILD_DIR="${BUILD_DIR:-$root/build-sanitize}" BUILD_TYPE=Debug
  export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
  "$root/scripts/build.sh" -DRAD_SANITIZE=ON -DRAD_BUILD_BENCHMARKS=OFF
else
  "$root/scripts/build.sh"
fi
ctest --test-dir "${BUILD_DIR:-$root/build}" --output-on-failure -j "$(nproc)"
if [ "${SANITIZE:-0}" != 1 ] && [ "${FUZZ:-1}" != 0 ]; then
  "$root/scripts/fuzz.sh"
fi
