#!/usr/bin/env bash
# README command 2: install what is missing, build with warnings as errors, run every test; then
# build again with AddressSanitizer + UndefinedBehaviorSanitizer (LeakSanitizer on) and run every
# test again under them.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
cd "$root"
for preset in ci asan; do
  echo "== preset $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset" -j2
done
