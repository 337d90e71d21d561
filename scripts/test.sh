#!/usr/bin/env bash
# README command 2: install what is missing, then for each preset build (warnings are errors) and
# run its tests: fuzz (a one-minute libFuzzer run on the scene parser), ci (every test), asan
# (every test again under AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer, except
# the Slurm job-array test, which runs once, in ci).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh" --test
cd "$root"
for preset in fuzz ci asan; do
  echo "== preset $preset"
  cmake --preset "$preset" >/dev/null
  cmake --build --preset "$preset"
  ctest --preset "$preset" -j2
done
