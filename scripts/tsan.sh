#!/usr/bin/env bash
# The viewer's tests (tests/viewer: the solver worker's thread, and the window the viewer opens) under
# ThreadSanitizer, built into build-tsan (BUILD_DIR). TBB and Mesa are not instrumented, so ThreadSanitizer
# cannot see how their threads are ordered and reports their every handover as a race (1,385 reports from
# tests_viewer on 2 cores). The run holds TBB to one thread by giving the tests one CPU (TBB sizes its pool by
# the CPUs the process may use, and the viewer that the window tests start inherits that); llvmpipe
# rasterizes on the thread that draws, and Mesa keeps no shader cache on disk, whose writer threads would
# report too. A report then fails the test it comes from.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
export BUILD_DIR="${BUILD_DIR:-$root/build-tsan}" BUILD_TYPE=Debug BUILD_TARGETS=tests_viewer
"$root/scripts/build.sh" -DRAD_TSAN=ON -DRAD_BUILD_BENCHMARKS=OFF
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1" LP_NUM_THREADS=0 MESA_SHADER_CACHE_DISABLE=true
first_cpu="$(taskset -pc $$ | sed 's/.*: //; s/[-,].*//')"
# Only tests_viewer is built: the other test programs' placeholders (NAME_NOT_BUILT) are left out.
taskset -c "$first_cpu" ctest --test-dir "$BUILD_DIR" -E '_NOT_BUILT$' --output-on-failure
