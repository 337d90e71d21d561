#!/usr/bin/env bash
# The real-GPU checks, on a machine with a GPU and its driver but none of rtvk's libraries (the
# device machine some sessions are lent): the GPU test suite on that device, `--backend both`
# on every built-in scene and a mesh, and `rtvk bench`. Run from the checkout's root, with the ci
# build (build/ci: rtvk, rtvk_tests, the test layer) and .gpu/libs.tar.xz (scripts/gpu-bundle.sh)
# carried along. Writes check.log, tests.log, bench.json and a few images into OUT.
# Usage: bash scripts/gpu-check.sh OUT [seconds for the tests, default 200] [gtest filter]
# RTVK_CHECK_STEPS picks steps (default "bench rt meshes both tests"; also "sampling").
set -uo pipefail
out=${1:?usage: gpu-check.sh OUT [test-seconds] [filter]}
test_seconds=${2:-200}
filter=${3:--Xvfb*:DevicePick*}
steps=" ${RTVK_CHECK_STEPS:-bench rt meshes both tests} "
root=$(pwd)
exec > >(tee -a "$out/check.log") 2>&1
step() { echo; echo "== $* ($(date +%T))"; }

# The tests name the executable and the test layer by the absolute paths they were built at.
built=$(sed -n 's|.*"library_path": "\(.*\)/build/ci/tests/librtvk_test_fault_layer.so".*|\1|p' \
        build/ci/tests/layers/rtvk_test_faults.json)
if [ -n "$built" ] && [ "$built" != "$root" ] && [ ! -e "$built/build/ci/rtvk" ]; then
  mkdir -p "$(dirname "$built")" && ln -sfn "$root" "$built"
fi

libs=/tmp/rtvk-libs
mkdir -p $libs && tar -C $libs -xJf .gpu/libs.tar.xz
export LD_LIBRARY_PATH=$libs/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
if ldd build/ci/rtvk_tests | grep -q "not found"; then
  export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$libs/fallback
fi
ldd build/ci/rtvk_tests build/ci/rtvk | grep "not found"
mkdir -p /usr/share/vulkan/explicit_layer.d
sed "s|\"libVkLayer_khronos_validation.so\"|\"$libs/lib/libVkLayer_khronos_validation.so\"|" \
  $libs/layers/VkLayer_khronos_validation.json > /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json

step devices
nvidia-smi -L
# NVIDIA's Vulkan driver is loaded through libglvnd: where the machine lacks it, the Debian
# packages carried in .gl (see .library/device/README.md) are unpacked over /.
if [ -d .gl ]; then for f in .gl/*.deb; do dpkg -x "$f" /; done; ldconfig; fi
nvidia=/usr/local/nvidia/share
if ! build/ci/rtvk devices 2>&1 | grep -qi nvidia && [ -f $nvidia/vulkan/icd.d/nvidia_icd.json ]; then
  export VK_DRIVER_FILES=$nvidia/vulkan/icd.d/nvidia_icd.json
  export __EGL_VENDOR_LIBRARY_FILENAMES=$nvidia/glvnd/egl_vendor.d/10_nvidia.json
fi
if ! build/ci/rtvk devices; then
  VK_LOADER_DEBUG=error,warn,driver build/ci/rtvk devices 2>&1 | tail -40
  cat $nvidia/vulkan/icd.d/*.json; ldd "$(ldconfig -p | awk '/libGLX_nvidia.so.0/ {print $NF; exit}')"
fi
export RTVK_DEVICE=${RTVK_DEVICE:-nvidia} RTVK_TEST_DEVICE=${RTVK_TEST_DEVICE:-nvidia}
rtvk=build/ci/rtvk
python3 scripts/make-mesh.py knot 20000 docs/scenes/knot.obj  # docs/scenes/knot.json's mesh (git ignores it)

if [[ $steps == *" bench "* ]]; then
step bench
: > "$out/bench.json"
bench() {  # bench NAME ARGS...: one JSON array per run, gathered into bench.json
  local name=$1; shift
  echo "-- $name: rtvk bench $*"
  timeout 120 $rtvk bench "$@" --json /tmp/bench-$name.json && \
    { echo "\"$name\":"; cat /tmp/bench-$name.json; echo ","; } >> "$out/bench.json"
}
final=(--scene book-final --width 1200 --aspect 16:9 --spp 10 --depth 20)
bench final-gpu "${final[@]}" --backend gpu --repeat 9
bench final-500spp-gpu --scene book-final --width 1200 --aspect 16:9 --spp 500 --depth 50 --backend gpu --repeat 3
bench final-cpu "${final[@]}" --backend cpu --repeat 3
bench final-gpu-validated "${final[@]}" --backend gpu --repeat 1 --validate
bench final-4k-gpu --scene book-final --width 3840 --aspect 16:9 --spp 16 --depth 50 --backend gpu --repeat 3
bench spheres1m-gpu --scene spheres:1000000 --width 1200 --spp 4 --backend gpu --repeat 3
bench knot-all --scene docs/scenes/knot.json --backend all --spp 32 --repeat 3
bench quads-all --scene quads --backend all --spp 100 --repeat 3
bench forest-all --scene docs/scenes/forest.json --backend all --spp 16 --repeat 3
bench cornell-gpu --scene cornell-box --backend gpu --spp 200 --repeat 3
bench cornell-1000spp-gpu --scene cornell-box --backend gpu --spp 1000 --repeat 3
bench next-week-final-gpu --scene next-week-final --backend gpu --spp 1000 --repeat 1
fi

if [[ $steps == *" rt "* ]]; then
step "hardware ray tracing: --accel bvh, rt-query, rt-pipeline (whichever the device has)"
$rtvk devices | grep -E "ray queries|^\*"
: > "$out/bench-rt.json"
for accel in bvh rt-query rt-pipeline; do
  for scene in book-final docs/scenes/knot.json; do
    name=rt-$accel-$(basename "$scene" .json)
    echo "-- $name"
    timeout 120 $rtvk bench --scene "$scene" --width 1200 --aspect 16:9 --spp 16 --backend gpu \
      --accel $accel --repeat 5 --json /tmp/$name.json && \
      { echo "\"$name\":"; cat /tmp/$name.json; echo ","; } >> "$out/bench-rt.json"
  done
  timeout 120 $rtvk render --scene book-final --width 400 --spp 8 --backend both --accel $accel \
    -o "$out/rt-$accel.png"
  echo "exit $?"
done
fi

if [[ $steps == *" sampling "* ]]; then
step "sampling: converged references, noise against time, the third book's scene (docs/benchmarks.md)"
for s in cornell-box rest-of-life-final; do
  echo "-- reference $s: rtvk render --backend gpu --scene $s --width 600 --spp 32768 --sampling lights"
  timeout 150 $rtvk render --backend gpu --scene $s --width 600 --spp 32768 --sampling lights -o "$out/ref-$s-600.exr"
done
timeout 150 python3 scripts/plot-sampling-noise.py $rtvk "$out/ref-cornell-box-600.exr" /tmp/noise --width 600 \
  --backends gpu --seconds 1 && cp /tmp/noise/sampling-noise-cornell-box.json "$out/noise-gpu.json"
timeout 120 $rtvk render --backend gpu --scene rest-of-life-final --spp 10000 -o "$out/rest-of-life-final.png"
bench cornell-plain-gpu --scene cornell-box --backend gpu --spp 200 --sampling plain --repeat 3
bench cornell-lights-gpu --scene cornell-box --backend gpu --spp 200 --sampling lights --repeat 3
bench rest-of-life-final-gpu --scene rest-of-life-final --backend gpu --spp 1000 --repeat 3
fi

if [[ $steps == *" meshes "* ]]; then
step "meshes, 1,000 to 1,000,000 triangles (docs/benchmarks.md's table)"
for n in 1000 10000 100000 1000000; do
  python3 scripts/make-mesh.py knot $n /tmp/knot$n.obj
  bench knot$n-gpu --scene /tmp/knot$n.obj --width 320 --aspect 1 --spp 32 --backend gpu --repeat 3
  bench knot$n-gpu-1080p --scene /tmp/knot$n.obj --width 1920 --aspect 16:9 --spp 32 --backend gpu --repeat 3
done
fi

if [[ $steps == *" both "* ]]; then
step "renders, --backend both"
both() {  # both NAME ARGS...: the CPU reference against the GPU, the comparison as rtvk says it
  local name=$1; shift
  echo "-- $name: rtvk render $* --backend both"
  timeout 120 $rtvk render "$@" --backend both -o /tmp/both-$name.png; echo "exit $?"
}
both seed --scene seed
both materials --scene materials --width 400 --spp 32
both final --scene book-final --width 600 --aspect 16:9 --spp 16
both bouncing --scene bouncing-spheres --width 400 --spp 16
both quads --scene quads --spp 32
both knot --scene docs/scenes/knot.json --spp 16
both equirect --scene book-final --projection equirectangular --aperture 0 --width 512 --aspect 2 --spp 8
both fisheye --scene book-final --projection fisheye-equisolid --aperture 0 --width 400 --aspect 1 --spp 8
both motion --scene bouncing-spheres --width 320 --spp 32 --shutter 0:1
both forest --scene docs/scenes/forest.json --spp 16
both forest-scan --scene docs/scenes/forest.json --spp 4 --accel none
both checkered --scene checkered-spheres --width 400 --spp 16
both perlin --scene perlin-spheres --width 400 --spp 16
both simple-light --scene simple-light --width 400 --spp 64
both cornell --scene cornell-box --width 300 --spp 64
both cornell-smoke --scene cornell-smoke --width 300 --spp 64
both next-week-final --scene next-week-final --width 400 --spp 16
both cornell-plain --scene cornell-box --width 300 --spp 64 --sampling plain
both rest-of-life-final --scene rest-of-life-final --width 300 --spp 64
both pbr-spheres --scene docs/scenes/pbr-spheres.json --spp 32
both pbr-layers --scene docs/scenes/pbr-layers.json --spp 32
# (the device tool brings back at most 8 files: RTVK_CHECK_NO_IMAGES=1 leaves these out)
[ -n "${RTVK_CHECK_NO_IMAGES:-}" ] ||
  cp /tmp/both-final.png /tmp/both-knot.png /tmp/both-forest.png /tmp/both-next-week-final.png "$out/" 2>/dev/null
fi

if [[ $steps == *" tests "* ]]; then
step "GPU test suite on $RTVK_TEST_DEVICE, 8 shards, at most $test_seconds s ($filter)"
export GTEST_TOTAL_SHARDS=8
pids=()
for i in 0 1 2 3 4 5 6 7; do
  GTEST_SHARD_INDEX=$i timeout "$test_seconds" build/ci/rtvk_tests --gtest_brief=1 \
    --gtest_filter="$filter" > /tmp/shard-$i.log 2>&1 &
  pids+=($!)
done
wait "${pids[@]}"  # not a bare wait: that also waits for the log's tee
for i in 0 1 2 3 4 5 6 7; do echo "### shard $i"; cat /tmp/shard-$i.log; done > "$out/tests.log"
grep -h "^\[  FAILED  \]\|^\[  PASSED  \]\|tests ran" /tmp/shard-*.log
fi
step done
