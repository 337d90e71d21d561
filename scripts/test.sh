#!/usr/bin/env bash
# README command 2: install what is missing, then for each preset build (warnings are errors) and
# run its tests: fuzz (a one-minute libFuzzer run on the scene parser), ci (every test, on the
# system's lavapipe), asan (every test again under AddressSanitizer + UndefinedBehaviorSanitizer +
# LeakSanitizer, except the Slurm job-array test, which runs once, in ci), and last the ci tests
# again (Slurm's aside) on a second lavapipe: Mesa 25 from bookworm-backports when the system
# has bookworm's Mesa 22.3, else bookworm's 22.3, fetched by scripts/private-mesa.sh into
# ~/.cache/rtvk-test-mesa/ (RTVK_MESA_DIR) and never installed: outside the source and build
# trees, which the install test hides. RTVK_SECOND_MESA=SUITE picks that suite instead.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$root/scripts/install-deps.sh" --test
cd "$root"
timings=()
timed() {  # timed LABEL COMMAND...: runs it, and notes how long it took
  local label=$1 start=$SECONDS
  shift
  "$@"
  timings+=("$label: $((SECONDS - start)) s")
}
run_preset() {
  cmake --preset "$1" >/dev/null
  cmake --build --preset "$1"
  ctest --preset "$1" -j2 "${@:2}"
}
# Which lavapipe the loader offers, as rtvk sees it: the log says what each pass ran on.
show_devices() { "$root/build/ci/rtvk" devices || true; }

system_mesa=$(dpkg-query -W -f='${Version}\n' "mesa-vulkan-drivers:$(dpkg --print-architecture)")
if [[ $system_mesa == 22.* ]]; then second=bookworm-backports; else second=bookworm; fi
second=${RTVK_SECOND_MESA:-$second}

for preset in fuzz ci asan; do
  echo "== preset $preset"
  timed "$preset" run_preset "$preset"
  [[ $preset == ci ]] && show_devices
done

echo "== preset ci again, on the lavapipe of $second's mesa-vulkan-drivers (the system has $system_mesa)"
start=$SECONDS
env_file=$(bash scripts/private-mesa.sh "$second")
timings+=("fetch and unpack $second's lavapipe: $((SECONDS - start)) s")
(
  # The suite picks lavapipe itself; a device named for other runs must not steer this one.
  unset RTVK_DEVICE RTVK_TEST_DEVICE
  set -a
  # shellcheck disable=SC1090 # written by private-mesa.sh
  source "$env_file"
  set +a
  # Mesa 25's lavapipe has ray queries and pipelines: the hardware paths' tests must find them
  # there rather than pass by checking that they are refused.
  if [[ $second == bookworm-backports ]]; then export RTVK_EXPECT_RAY_TRACING=1; fi
  listing=$(show_devices)
  echo "$listing"
  # The pass must run on the fetched driver, not silently on the system's.
  want="Mesa ${RTVK_PRIVATE_MESA_VERSION%%-*}"
  grep -qF "$want" <<<"$listing" || { echo "rtvk: expected a lavapipe of $want (above)" >&2; exit 1; }
  timed "ci on $want" ctest --preset ci -j2 -E '^Slurm\.'
  printf '%s\n' "${timings[@]}" >"$root/build/test-timings.txt"
)
echo "== timings"
cat "$root/build/test-timings.txt"
