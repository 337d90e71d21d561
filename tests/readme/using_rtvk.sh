#!/usr/bin/env bash
# The README's "Using rtvk" commands, run as written and in order, the way a new user copies
# them: every line must exit 0 (the compare line included: its comment promises 0, alike), and
# the block must stay short enough to try on a small machine. The built rtvk stands in for
# build/release/rtvk. Fails naming the README line that failed.
#   using_rtvk.sh RTVK_EXECUTABLE README.md
set -euo pipefail
rtvk=$(realpath "$1") readme=$(realpath "$2")
src=$(dirname "$readme") name=$(basename "$readme")
tmp=$(mktemp -d /tmp/rtvk-readme-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
# One line past this many seconds fails, naming itself, before ctest's timeout would stop the
# test without saying which line was slow; a new user would wait that long too.
line_limit=120

# The lines of the first sh block under "## Using rtvk", each with its line number in README.md.
block=$(awk '/^## / { on = ($0 == "## Using rtvk") }
             on && !inside && /^```sh$/ { inside = 1; next }
             inside && /^```$/ { exit }
             inside { print NR "\t" $0 }' "$readme")
[[ $block == *build/release/rtvk* ]] || fail "no sh block of build/release/rtvk commands under '## Using rtvk' in $readme"

# The GPU lines run on the lavapipe the test run has (the system's, or the one a second Mesa's
# VK_DRIVER_FILES points at), found by its driver ID whatever else the machine offers, or on the
# device the suite is told to test (RTVK_TEST_DEVICE). Without one: a failure in CI, a skip
# elsewhere, as for the suite's GPU tests.
export RTVK_DEVICE=${RTVK_TEST_DEVICE:-lavapipe}
if ! "$rtvk" devices --device "$RTVK_DEVICE" >"$tmp/devices.txt" 2>&1; then
  [[ -z ${CI:-} || $CI == false || $CI == 0 ]] || fail "no Vulkan device '$RTVK_DEVICE' in CI: $(cat "$tmp/devices.txt")"
  echo "SKIP: no Vulkan device '$RTVK_DEVICE' for the README's GPU lines (Debian: mesa-vulkan-drivers)"
  exit 77
fi
# Run by hand, rtvk's pipeline cache goes to the temporary folder, not the user's (ctest sets
# XDG_CACHE_HOME to the build tree).
export XDG_CACHE_HOME=${XDG_CACHE_HOME:-$tmp/cache}

# The README's commands run at the top of a clone, where docs/ is (docs/scenes/views.json); here
# they run in a fresh folder with a copy of the source tree's docs/, so what they write lands in the
# folder and never in the source tree.
work=$tmp/work
mkdir -p "$work"
cp -r "$src/docs" "$work/docs"  # a copy: a line that wrote under docs/ must not reach the source
export RTVK="$rtvk"
since() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }
start=$EPOCHREALTIME ran=0
while IFS=$'\t' read -r n line; do
  [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
  # rtvk view opens a window, which needs a display; tests/view drive it under Xvfb.
  [[ $line =~ ^build/release/rtvk\ view([[:space:]]|$) ]] && { echo "skip $name:$n (a window): $line"; continue; }
  cmd=${line//build\/release\/rtvk/\"\$RTVK\"}
  echo "$name:$n: $line"
  t=$EPOCHREALTIME rc=0
  (cd "$work" && timeout --kill-after=10 "$line_limit" bash -o pipefail -c "$cmd") </dev/null >"$tmp/out.txt" 2>&1 || rc=$?
  if [[ $rc != 0 ]]; then
    cat "$tmp/out.txt"
    [[ $rc == 124 ]] && fail "$name:$n took over $line_limit s: $line"
    fail "$name:$n exited $rc: $line"
  fi
  echo "  ok, $(since "$t") s"
  ran=$((ran + 1))
done <<<"$block"
echo "PASS: $ran lines of $name's \"Using rtvk\" ran as written in $(since "$start") s" \
  "(GPU: $RTVK_DEVICE)"
