#!/usr/bin/env bash
# README command 2, and what CI runs (.ci/run): install what is missing, then build and test in
# passes, each aimed at what it alone can find (docs/testing.md: what runs where, and why):
#   ci      every test, on the system's lavapipe (release build, warnings are errors)
#   second  the GPU tests (label gpu) again, on a second lavapipe: Mesa 25 from
#           bookworm-backports when the system has bookworm's Mesa 22.3, else bookworm's 22.3,
#           fetched by scripts/private-mesa.sh into ~/.cache/rtvk-test-mesa/ (RTVK_MESA_DIR) and
#           never installed (RTVK_SECOND_MESA=SUITE picks the suite)
#   asan    one clang build under AddressSanitizer + UndefinedBehaviorSanitizer + LeakSanitizer:
#           first the four libFuzzer targets (scene files, mesh files, calibrations, environment
#           maps), 30 s each from their committed corpora; then the host tests
#           (label host) with no Vulkan driver at all, so a test that needs a device and is not
#           labelled gpu fails; then the GPU tests that run every host-side Vulkan path (label
#           sanitize) on the lavapipe with ray tracing, and those of the hardware paths on the
#           other too (where they are refused), last, so that both lavapipes' shaders are
#           compiled (the cache is shared) before the sanitizers' slow process would compile them
# At the end it prints each stage's time and the slowest tests of the run (build/test-report.txt).
#
#   scripts/test.sh --quick   the inner loop while working: builds the ci preset and runs the host
#                             tests and a few GPU tests (labels gpu-sanitize-quick and
#                             gpu-quick), in about a minute
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
quick=false
case ${1:-} in
  --quick) quick=true ;;
  "") ;;
  *) echo "rtvk: test.sh: unknown argument '$1' (--quick or nothing)" >&2; exit 2 ;;
esac
cd "$root"
jobs=${RTVK_TEST_JOBS:-$(nproc)}
# One Mesa shader cache for every test process of every pass: lavapipe then compiles each of
# rtvk's shader variants once per driver, not once per test (tests/test_main.cpp says why).
export MESA_SHADER_CACHE_DIR=${MESA_SHADER_CACHE_DIR:-$root/build/mesa-shader-cache}
logs=$root/build/test-logs
timings=()
timed() {  # timed LABEL COMMAND...: runs it, and notes how long it took (and if it failed)
  local label=$1 start=$SECONDS status=0
  shift
  "$@" || status=$?
  local line
  line=$(printf '%5d s  %s' $((SECONDS - start)) "$label")
  if ((status)); then line+="  (failed: exit $status)"; fi
  timings+=("$line")
  return "$status"
}
# (timed runs these where set -e does not reach, so each step's failure is passed on by &&.)
build() {  # build PRESET [TARGET...]: all of the preset's targets, or these
  local preset=$1
  shift
  cmake --preset "$preset" >/dev/null && cmake --build --preset "$preset" ${1:+--target "$@"}
}
# tests PASS PRESET CTEST-ARGS...: one ctest run, its output kept for the report.
tests() {
  local pass=$1 preset=$2
  shift 2
  mkdir -p "$logs"
  ctest --preset "$preset" -j"$jobs" "$@" 2>&1 | tee "$logs/$pass.log"
  return "${PIPESTATUS[0]}"
}
# Which lavapipe the loader offers, as rtvk sees it: the log says what each pass ran on.
show_devices() { "$root/build/ci/rtvk" devices || true; }
report() {
  # At exit, whatever the outcome: no pipe here may turn a green run red (head closing early).
  set +e +o pipefail
  mkdir -p "$root/build"
  {
    echo "== stages"
    printf '%s\n' "${timings[@]}"
    echo "== the slowest tests (seconds, pass, test)"
    # ctest prints "  n/N Test  #k: NAME ....   Passed   12.34 sec" per test.
    for f in "$logs"/*.log; do
      [[ -f $f ]] || continue
      sed -nE "s/^.*Test +#[0-9]+: ([^ ]+) .* ([0-9]+\.[0-9]+) sec$/\2 $(basename "$f" .log) \1/p" "$f"
    done | sort -rn | awk 'NR <= 20 {printf "%8.1f  %-16s %s\n", $1, $2, $3}'
  } | tee "$root/build/test-report.txt"
}
trap 'status=$?; report; exit $status' EXIT
rm -rf "$logs"

timed "install what is missing" bash "$root/scripts/install-deps.sh" --test

if $quick; then
  timed "build ci" build ci
  timed "host and quick tests" tests quick ci -L '^host$|quick' -E '^Slurm\.'
  exit 0
fi

system_mesa=$(dpkg-query -W -f='${Version}\n' "mesa-vulkan-drivers:$(dpkg --print-architecture)")
if [[ $system_mesa == 22.* ]]; then second=bookworm-backports; else second=bookworm; fi
second=${RTVK_SECOND_MESA:-$second}
fetch_second() { second_env=$(bash scripts/private-mesa.sh "$second"); }  # the env file's path
timed "fetch and unpack $second's lavapipe" fetch_second
# on_second COMMAND...: runs it with the loader pointed at the second lavapipe alone.
on_second() {
  (
    # The suite picks lavapipe itself; a device named for other runs must not steer this one.
    unset RTVK_DEVICE RTVK_TEST_DEVICE
    set -a
    # shellcheck disable=SC1090 # written by private-mesa.sh
    source "$second_env"
    set +a
    # Mesa 25's lavapipe has ray queries and pipelines: the hardware paths' tests must find them
    # there rather than pass by checking that they are refused.
    if [[ $second == bookworm-backports ]]; then export RTVK_EXPECT_RAY_TRACING=1; fi
    "$@"
  )
}
# The hardware ray-tracing paths' host code (acceleration structures, ray pipelines) runs only
# where the driver has them (Mesa 25), their refusals only where it has not (Mesa 22.3): the
# sanitizers' GPU tests run on both lavapipes.
if [[ $second != bookworm-backports && $system_mesa == 22.* ]]; then
  echo "rtvk: warning: neither lavapipe has ray tracing (RTVK_SECOND_MESA=$second): its host code goes unsanitized" >&2
fi

echo "== ci: every test, on the system's lavapipe ($system_mesa)"
timed "build ci" build ci
show_devices
timed "ci: every test" tests ci ci

# Before the sanitizers' pass: the shader cache is shared, so their process (where a cold Mesa 25
# compile takes several times longer) finds the second lavapipe's variants already compiled.
echo "== the GPU tests again, on the lavapipe of $second's mesa-vulkan-drivers (the system has $system_mesa)"
listing=$(on_second show_devices)
echo "$listing"
# The pass must run on the fetched driver, not silently on the system's.
want="Mesa $(sed -n 's/^RTVK_PRIVATE_MESA_VERSION=//p' "$second_env" | cut -d- -f1)"
grep -qF "$want" <<<"$listing" || { echo "rtvk: expected a lavapipe of $want (above)" >&2; exit 1; }
# The PBR renders run on the system's lavapipe only (the ci pass): a PBR shader variant compiles
# cold in about 20 s on Mesa 22.3 but for 2 to 9 minutes on Mesa 25 (pbr-spheres 137 s;
# GpuGltfSamples 553 s and GpuPbr's hardware-path test 433 s, which compile several), nearly all
# in LLVM's CoroSplit pass over lavapipe's compute coroutine. The kernels' probe (seconds) still
# runs here. PBR on the hardware paths was checked on an NVIDIA H200 instead (docs/materials.md,
# docs/benchmarks.md). GpuFastMode (the CPU's fast mode against the GPU, showcase included) runs
# here too little to be worth its cold PBR compile (229 s): what it checks is the CPU's side.
# Python.* (70 s here, cold) checks the module against the CLI; its GPU renders are the engine's
# that the GPU tests above run on this driver.
pbr_renders='^(Python\..*|GpuFastMode\..*|GpuPbr\.(TheGalleryMatchesTheCpu|AWhiteSphereInAWhiteFurnaceIsWhite|AVolumeAttenuatesByBeerLambert|TheHardwarePathsGiveTheComputeBvhsExactSums)|GpuGltfSamples\..*|GpuNee\.ThePbrGalleryMatchesTheCpu|GpuShowcase\..*)$'
# Four compute-path image tests (GpuSurface's, GpuNextWeek's, GpuSampling's and GpuTextures'
# checker and image values) compile a cold variant per feature or scene: 1,600 s of the Mesa 25
# pass's test time on stop 56's CI machine with GpuTextures' noise test (GpuSurface 578 s,
# GpuNextWeek 425 s, GpuSampling 342 s, GpuTextures 259 s). Their features run on Mesa 25's
# compute path elsewhere: the surface features, image textures and both texture coordinates in
# GpuHardwareRt's surfaces test, the books' objects (their textures taken off) in its built-in
# scenes test, both bit for bit against the hardware paths; lights sampling in GpuNee's and
# GpuLightTree's; noise textures in GpuTextures.NoiseValuesMatchTheHosts, which runs there. These
# four compare it with the CPU on Mesa 22.3, in the ci pass.
compute_repeats='GpuSurface\.EmissionVertexColorsAlphaAndCullingMatchTheCpu|GpuNextWeek\.TheBooksTexturedLitAndSmokyScenesMatchTheCpu|GpuSampling\.LightsSamplingMatchesTheCpu|GpuTextures\.CheckerAndImageValuesMatchTheHosts'
# Six more took over 20 s each of that pass (a clean clone of e408422 on 2 vCPUs) for what the
# pass shows elsewhere: GpuLimits' image-texture refusal (119 s: its render within the limit
# compiles a texture variant of its own; the refusal is the host's), the OpenCV oracle (52 s)
# and the README's commands (46 s), renders of rtvk's CLI whose math the GPU tests check here,
# RealGpuFaults' long render under a simulated watchdog (24 s, the host's pacing), GpuShapes'
# instances of groups (37 s; the instances run here in GpuHardwareRt's and GpuShapes' other
# tests) and the viewer's screenshot of quads and a mesh (24 s; the viewer runs here in the other
# XvfbTest tests).
driver_alike='GpuLimits\.AnImageTextureAboveTheStorageRangeIsRefusedNamingIt|Oracle\.OpenCvAndColmapProjectionsLandOnRtvksPixels|Readme\.UsingRtvkRunsAsWritten|RealGpuFaults\.ALongRenderFinishesUnderAWatchdogWithTheSameImage|GpuShapes\.InstancesOfGroupsMatchTheCpu|XvfbTest\.QuadsAndAMeshFileScreenshotAreTheBytesRtvkRenderWrites'
left_out="$pbr_renders|^($compute_repeats|$driver_alike)\$"
# The hardware paths' tests first, in a ctest run of their own: each compiles several variants
# there (minutes), where the ci pass's timings, by which ctest orders the tests it knows, had them
# start last (under a second each on Mesa 22.3, which refuses them), and the pass ended on one
# core for five minutes.
hardware='HardwareRt\.|HardwarePaths'
second_pass() {  # both runs, whatever the first gives
  local status=0
  tests second-hardware ci -L '^gpu' -R "$hardware" -E "$left_out" || status=$?
  tests second ci -L '^gpu' -E "$left_out|$hardware" || status=$?
  return "$status"
}
timed "GPU tests on $want" on_second second_pass

echo "== asan: the fuzz targets, the host tests with no Vulkan driver, the sanitize GPU tests on both lavapipes"
# Only what its tests run: rtvk_tests, which depends on rtvk and the fault layer (not librtvk.so,
# made from the objects rtvk_tests links as rtvk_lib, which the ci pass links and installs), and
# the libFuzzer targets, which link the same sanitized parsers (clang builds both, once).
timed "build asan" build asan rtvk_tests rtvk_fuzzers
timed "fuzz: 4 targets, 30 s each" tests fuzz asan -R '^fuzz_'
# without_driver COMMAND...: runs it with a loader that finds no driver at all, and as in CI
# (where a GPU test without a device fails rather than skips), so that only a test that needs no
# device can pass: one that needs a device and lacks the gpu label fails here, naming it.
without_driver() {
  (
    unset RTVK_DEVICE RTVK_TEST_DEVICE VK_ADD_DRIVER_FILES
    export CI=true
    export VK_DRIVER_FILES=/nonexistent/rtvk-no-driver.json VK_ICD_FILENAMES=/nonexistent/rtvk-no-driver.json
    "$@"
  )
}
timed "asan: host tests, no driver" without_driver tests asan-host asan -L '^host$'
# The host-side Vulkan code is the same on both lavapipes but where a driver has ray tracing or
# has not: the whole label runs on the second lavapipe, which has it when the system's has not
# (Mesa 25 beside 22.3), and on the system's only the tests of the hardware paths, whose
# refusals run there (the label's other tests took 240 s on the system's Mesa 22.3, all of it
# the same host code again).
refusals="$hardware|DevicesShowTheDriver"  # the hardware paths' tests, and the device listing
if [[ $second == bookworm-backports ]]; then
  timed "asan: sanitize GPU tests, second lavapipe" on_second tests asan-gpu-second asan -L sanitize
  timed "asan: the hardware paths' sanitize GPU tests, system's lavapipe" \
    tests asan-gpu asan -L sanitize -R "$refusals"
else
  timed "asan: sanitize GPU tests, system's lavapipe" tests asan-gpu asan -L sanitize
  timed "asan: the hardware paths' sanitize GPU tests, second lavapipe" \
    on_second tests asan-gpu-second asan -L sanitize -R "$refusals"
fi
