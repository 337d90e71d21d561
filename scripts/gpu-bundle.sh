#!/usr/bin/env bash
# Packs what scripts/gpu-check.sh needs on a machine that has a GPU and its driver but no package
# registry and none of rtvk's libraries (the device machine lent to some sessions): the shared
# libraries the ci build's rtvk and rtvk_tests load (glibc aside), the Vulkan loader and the
# validation layer, from this Debian machine, into .gpu/libs.tar.xz (git ignores .gpu).
# Usage: bash scripts/gpu-bundle.sh [build-dir]   (default build/ci, built beforehand)
set -euo pipefail
build=${1:-build/ci}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/lib" "$stage/fallback" "$stage/layers" .gpu
multiarch=/usr/lib/x86_64-linux-gnu
layer=$multiarch/libVkLayer_khronos_validation.so
for bin in "$build/rtvk" "$build/rtvk_tests" "$build"/tests/librtvk_test_fault_layer.so "$layer" \
           "$multiarch/libvulkan.so.1"; do
  ldd "$bin" | awk '$3 ~ /^\// {print $3}'
done | sort -u | while read -r lib; do
  case $(basename "$lib") in
    libc.so*|libm.so*|libdl.so*|libpthread.so*|librt.so*|ld-linux*) ;;  # the machine's glibc
    libstdc++.so*|libgcc_s.so*) cp -L "$lib" "$stage/fallback/" ;;  # only if the machine lacks it
    *) cp -L "$lib" "$stage/lib/" ;;
  esac
done
cp -L "$multiarch/libvulkan.so.1" "$layer" "$stage/lib/"
cp /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json "$stage/layers/"
tar -C "$stage" -cJf .gpu/libs.tar.xz lib fallback layers
ls -la .gpu/libs.tar.xz
