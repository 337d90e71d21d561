#!/usr/bin/env bash
# Re-derives the GPU tests that run under the sanitizers (labels gpu-sanitize and
# gpu-sanitize-quick in tests/CMakeLists.txt): the cheapest few GPU tests that between them run
# every line of host code that some GPU test runs and no host test does. Run it when GPU tests
# are added or removed, or when host code a GPU test reaches changes, and paste the two lists it
# prints at the end over those in tests/CMakeLists.txt.
#
#   scripts/choose-sanitize-tests.sh [--only REGEX] [--mesa SUITE]
#     --only REGEX  runs only the tests whose names match (a ctest -R regex): for trying the tool;
#                   the lists it then prints speak only for those tests
#     --mesa SUITE  the lavapipe to measure on: bookworm-backports (Mesa 25, fetched by
#                   scripts/private-mesa.sh), bookworm (Mesa 22.3, likewise) or system (the
#                   installed one). Default: bookworm-backports where the system has Mesa 22.x,
#                   else system, as scripts/test.sh picks the lavapipe with ray tracing.
#
# It configures and builds a coverage tree, build/coverage (gcc --coverage), runs each test with
# the label host or gpu* alone, its .gcda files written to a folder of its own (GCOV_PREFIX), and
# hands the runs to scripts/choose_sanitize_tests.py, which says which host lines each test ran
# and picks the set. Everything it measures lies in build/coverage/sanitize-choice/ (each
# test's .gcda files, its log, its lines; results.tsv has each test's seconds and status),
# so the Python part can be run again on it alone.
#
# A full run takes about 20 minutes of a 2-core machine: about 4 for the coverage build, 11 for
# some 385 tests one after another, 4 for gcov to read their runs. A test is stopped after
# RTVK_COVERAGE_TEST_TIMEOUT seconds (default 150): a test that slow could never be in the set;
# its lines are lost with it, and the report names it. The folder ends up at about 700 MB.
#
# RTVK_COVERAGE_BUILD=DIR measures an existing coverage build tree instead (configured with
# --coverage; it is built, not configured), e.g. to try the tool without a second build.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

bad() { echo "rtvk: choose-sanitize-tests.sh: $*" >&2; exit 2; }
only=""
mesa=""
while (($#)); do
  case $1 in
    --only) (($# >= 2)) || bad "--only needs a REGEX"; only=$2; shift 2 ;;
    --mesa) (($# >= 2)) || bad "--mesa needs a SUITE"; mesa=$2; shift 2 ;;
    -h | --help) sed -n '2,/^set -euo/{/^set/d;s/^# \{0,1\}//;p}' "${BASH_SOURCE[0]}"; exit 0 ;;
    *) bad "unknown argument '$1' (--only REGEX, --mesa SUITE)" ;;
  esac
done
case $mesa in
  "" | bookworm | bookworm-backports | system) ;;
  *) bad "--mesa '$mesa' is none of bookworm-backports, bookworm, system" ;;
esac
# grep exits 2 on a regex it cannot read; ctest would instead match nothing and say little.
if [[ -n $only ]]; then
  rc=0
  grep -Eq -- "$only" <<<"" 2>/dev/null || rc=$?
  ((rc < 2)) || bad "--only '$only' is not a regular expression"
fi
timeout=${RTVK_COVERAGE_TEST_TIMEOUT:-150}
[[ $timeout =~ ^[1-9][0-9]*$ ]] ||
  bad "RTVK_COVERAGE_TEST_TIMEOUT '$timeout' is not a whole number of seconds"

cd "$root"
build=${RTVK_COVERAGE_BUILD:-$root/build/coverage}
build=$(realpath -m "$build")
data=$build/sanitize-choice

# The build. Our own tree is configured every time (a no-op when nothing changed) so that it
# always has these flags; a tree named by RTVK_COVERAGE_BUILD is only built, and must already
# count lines, or every test would seem to run none.
if [[ -z ${RTVK_COVERAGE_BUILD:-} ]]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_FLAGS=--coverage -DCMAKE_CXX_FLAGS=--coverage \
    -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage \
    -DCMAKE_MODULE_LINKER_FLAGS=--coverage \
    -DRTVK_SLURM_TEST=OFF -DRTVK_BENCHMARKS=OFF >/dev/null
elif ! grep -q '^CMAKE_CXX_FLAGS:STRING=.*--coverage' "$build/CMakeCache.txt" 2>/dev/null; then
  bad "RTVK_COVERAGE_BUILD '$build' is not a build tree configured with --coverage"
fi
cmake --build "$build" --target rtvk rtvk_tests rtvk_test_fault_layer rtvk_install_files

# The lavapipe with ray tracing, as scripts/test.sh picks it: its hardware paths' host code runs
# only where the driver has them, and those lines are the ones the sanitizers most need to see.
if [[ -z $mesa ]]; then
  arch=$(dpkg --print-architecture)
  system_mesa=$(dpkg-query -W -f='${Version}\n' "mesa-vulkan-drivers:$arch")
  if [[ $system_mesa == 22.* ]]; then mesa=bookworm-backports; else mesa=system; fi
fi
# A device named for other runs must not steer this one.
unset RTVK_DEVICE RTVK_TEST_DEVICE
if [[ $mesa != system ]]; then
  mesa_env=$(bash scripts/private-mesa.sh "$mesa")
  set -a
  # shellcheck disable=SC1090 # written by private-mesa.sh
  source "$mesa_env"
  set +a
fi
# The tests that look for ray tracing must find it, not pass by checking that it is refused; CI
# turns on the tests that are skipped outside it. One shader cache for all the runs: lavapipe
# then compiles each shader once, not once per test, and the seconds are the tests' own.
export RTVK_EXPECT_RAY_TRACING=1 CI=true
export MESA_SHADER_CACHE_DIR=$build/mesa-shader-cache

# Each measurement starts from nothing: a test left over from an earlier run would count.
rm -rf "$data"
mkdir -p "$data/runs" "$data/logs"
"$build/rtvk" devices >"$data/devices.txt" 2>&1 || true
echo "mesa: $mesa${RTVK_PRIVATE_MESA_VERSION:+ ($RTVK_PRIVATE_MESA_VERSION)}" >"$data/driver.txt"
cat "$data/driver.txt" "$data/devices.txt"

# The tests, with their labels: one label each (tests/CMakeLists.txt), so one listing per label
# gives every test once. ctest -N prints "  Test  #12: Name".
only_args=()
[[ -z $only ]] || only_args=(-R "$only")
for label in host gpu gpu-quick gpu-sanitize gpu-sanitize-quick; do
  ctest --test-dir "$build" -N -L "^$label\$" "${only_args[@]}" |
    sed -nE "s/^ *Test +#([0-9]+): (.*)\$/\1\t\2\t$label/p"
done | grep -v $'\ttsan\.' | sort -n >"$data/tests.tsv"
# (The tsan.* tests never run under the other sanitizers: their lines must not count as covered.)
count=$(wc -l <"$data/tests.tsv")
# GoogleTest's own names: only they can go into the lists, which are GoogleTest filters.
"$build/rtvk_tests" --gtest_list_tests |
  awk '/^[^ ]/ { suite = $1; next } { print suite $1 }' >"$data/gtest.txt"
((count > 0)) || bad "no test with the label host or gpu* matches --only '$only'"

# The .gcno files as this build made them: the runs' .gcda files are read against these, so a
# later rebuild of the tree cannot mismatch them.
mkdir -p "$data/gcno"
(cd "$build" && find . -path ./sanitize-choice -prune -o -name '*.gcno' -print0 |
  xargs -0 -r cp --parents -t "$data/gcno")

# One test at a time, so that each one's seconds are its own and its .gcda files hold only its
# lines: GCOV_PREFIX sends them, under the build tree's full path (GCOV_PREFIX_STRIP=0), into
# runs/N, for this process and every rtvk it starts.
echo "running $count tests one at a time (results in $data)"
k=0
while IFS=$'\t' read -r num name label; do
  k=$((k + 1))
  export GCOV_PREFIX=$data/runs/$num GCOV_PREFIX_STRIP=0
  mkdir -p "$GCOV_PREFIX"
  start=$(date +%s.%N)
  # Not from the list on stdin, which the test would otherwise be free to read.
  # Host tests run as the sanitizers' pass runs them (scripts/test.sh): with no driver at all, so
  # that a line they reach only where a device exists does not count as theirs.
  no_driver=()
  [[ $label != host ]] || no_driver=(VK_DRIVER_FILES=/nonexistent/x.json VK_ICD_FILENAMES=/nonexistent/x.json)
  env "${no_driver[@]}" ctest --test-dir "$build" -I "$num,$num" --timeout "$timeout" \
    --output-on-failure </dev/null >"$data/logs/$num.log" 2>&1 || true
  wall=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  # ctest's own line for the test: "1/1 Test #12: Name ....   Passed    0.25 sec".
  line=$(grep -E '^ *1/1 Test +#' "$data/logs/$num.log" || true)
  case $line in
    *"***Timeout"*) status=TIMEOUT ;;
    *"***Skipped"* | *"***Not Run"*) status=SKIPPED ;;
    *" Passed "*) status=PASS ;;
    "") status=NOTRUN ;;
    *) status=FAIL ;;
  esac
  # The test's seconds as ctest timed it; the wall time around ctest where it printed none.
  seconds=$(sed -nE 's/.* ([0-9]+\.[0-9]+) sec$/\1/p' <<<"$line")
  seconds=${seconds:-$wall}
  printf '%s\t%s\t%s\t%s\t%s\n' "$num" "$name" "$label" "$seconds" "$status" >>"$data/results.tsv"
  printf '%4d/%d %7.2f s  %-7s %s\n' "$k" "$count" "$seconds" "$status" "$name"
done <"$data/tests.tsv"
unset GCOV_PREFIX GCOV_PREFIX_STRIP

python3 "$root/scripts/choose_sanitize_tests.py" --build "$build" "$data"
