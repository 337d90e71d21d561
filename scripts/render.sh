#!/usr/bin/env bash
# README command 1: install what is missing, build the release preset, render the seed scene.
# Usage: bash scripts/render.sh [extra rtvk render flags]   (writes seed.png in the current folder)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh"
cmake -S "$root" --preset release >/dev/null
# rtvk with its man page and completion, so that `cmake --install build/release` (README,
# "Installing") has all it installs; not the test suite, which a whole build would compile too.
cmake --build "$root/build/release" --target rtvk_install_files
"$root/build/release/rtvk" render --scene seed -o seed.png "$@"
