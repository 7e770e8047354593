#!/usr/bin/env bash
# Fuzz smoke: builds the libFuzzer targets (tests/fuzz: fuzz_obj, fuzz_ply, fuzz_gltf, fuzz_cli) with clang,
# AddressSanitizer and UndefinedBehaviorSanitizer into build-fuzz, then runs each for FUZZ_SECONDS (20)
# on a fresh copy of its seed corpus (tests/fuzz/corpus/TARGET; the repository's copy is never written).
# A crash, timeout, leak or out-of-memory fails the script and names the reproducer, which is kept in
# build-fuzz/artifacts/. FUZZ_TARGETS picks targets (e.g. "fuzz_ply"); extra arguments go to libFuzzer.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${FUZZ_BUILD_DIR:-$root/build-fuzz}"
seconds="${FUZZ_SECONDS:-20}"
read -r -a targets <<<"${FUZZ_TARGETS:-fuzz_obj fuzz_ply fuzz_gltf fuzz_cli}"
"$root/scripts/install-deps.sh"

# RelWithDebInfo: fast enough to fuzz, with line numbers in the sanitizers' reports.
CC=clang CXX=clang++ BUILD_DIR="$build_dir" BUILD_TYPE=RelWithDebInfo BUILD_TARGETS="${targets[*]}" \
  "$root/scripts/build.sh" -DRAD_FUZZ=ON -DRAD_BUILD_TESTS=OFF -DRAD_BUILD_BENCHMARKS=OFF

artifacts="$build_dir/artifacts"
mkdir -p "$artifacts" "$build_dir/logs"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1}"
failed=0
for target in "${targets[@]}"; do
  name="${target#fuzz_}"
  corpus="$build_dir/corpus/$name"
  rm -rf "$corpus"
  mkdir -p "$corpus"
  cp "$root/tests/fuzz/corpus/$name/"* "$corpus/"
  log="$build_dir/logs/$target.log"
  if "$build_dir/tests/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -timeout=10 -artifact_prefix="$artifacts/$target-" -print_final_stats=1 "$@" "$corpus" >"$log" 2>&1; then
    echo "fuzz: $target: $(grep -a -E '^Done [0-9]+ runs' "$log" | tail -1), corpus now $(ls "$corpus" | wc -l) inputs"
  else
    failed=1
    tail -n 40 "$log" >&2
    reproducer="$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)"
    echo "fuzz: $target FAILED; reproducer: ${reproducer:-none written (see $log)}" >&2
    echo "fuzz: replay it with $build_dir/tests/fuzz/$target ${reproducer:-FILE}" >&2
  fi
done
exit "$failed"
