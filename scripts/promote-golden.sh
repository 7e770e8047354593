#!/usr/bin/env bash
# Copies reviewed images from the last test run (BUILD_DIR/tests/golden-actual) into tests/golden/.
# Look at each image (and its .diff.png) first; name the ones to promote, or none to promote them all.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
actual="${BUILD_DIR:-$root/build}/tests/golden-actual"
[ -d "$actual" ] || { echo "promote-golden: no $actual; run the tests first" >&2; exit 2; }
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
  for f in "$actual"/*.png; do
    case "$f" in *.diff.png) ;; *) names+=("$(basename "$f" .png)") ;; esac
  done
fi
for name in "${names[@]}"; do
  [ -f "$actual/$name.png" ] || { echo "promote-golden: no $actual/$name.png" >&2; exit 2; }
  cp "$actual/$name.png" "$root/tests/golden/$name.png"
  echo "promoted $name"
done
