#!/usr/bin/env bash
# The CPU backend and the lavapipes of two Mesas (bookworm's 22.3 and bookworm-backports' 25,
# fetched and unpacked by scripts/private-mesa.sh, never installed) on one render, in one run:
# ROUNDS rounds, each timing the three once in turn (after rtvk bench's own warm-up), so that a
# shared machine's slow minutes fall on all three alike. Prints a Markdown table of medians and
# of each lavapipe's time over the CPU's.
#   bench-lavapipes.sh [RTVK [ROUNDS]] [-- rtvk bench flags]
# Default: build/release/rtvk, 3 rounds, book-final 1200x675, 10 spp, depth 20.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
positional=()
while [[ $# -gt 0 && $1 != -- ]]; do
  positional+=("$1")
  shift
done
[[ ${1:-} == -- ]] && shift
rtvk=$(realpath "${positional[0]:-$root/build/release/rtvk}")
rounds=${positional[1]:-3}
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench-lavapipes.sh: ROUNDS '$rounds' is not a count" >&2; exit 2; }
scene=("$@")
[[ ${#scene[@]} -gt 0 ]] || scene=(--scene book-final --width 1200 --aspect 16:9 --spp 10 --depth 20)
suites=(bookworm bookworm-backports)
out=$(mktemp -d /tmp/rtvk-bench-lavapipes-XXXXXX)
trap 'rm -rf "$out"' EXIT

declare -A env_of
for s in "${suites[@]}"; do env_of[$s]=$(bash "$root/scripts/private-mesa.sh" "$s"); done
unset RTVK_DEVICE

# bench NAME [ENV_FILE] -- FLAGS: one timed run into $out/NAME.ROUND.json
bench() {
  local name=$1 env_file=$2
  shift 2
  (
    if [[ -n $env_file ]]; then
      set -a
      # shellcheck disable=SC1090 # written by private-mesa.sh
      source "$env_file"
      set +a
    fi
    "$rtvk" bench "${scene[@]}" --repeat 1 --json "$out/$name.$round.json" "$@" >&2
  )
}
for round in $(seq 1 "$rounds"); do
  echo "== round $round of $rounds" >&2
  bench cpu "" --backend cpu
  for s in "${suites[@]}"; do bench "$s" "${env_of[$s]}" --backend gpu --device lavapipe; done
done

# A record's field, from rtvk bench's JSON (one record a file here).
field() {
  sed -n -e "s/^ *\"$2\": \"\(.*\)\",\{0,1\}$/\1/p" -e "s/^ *\"$2\": \([^\"][^,]*\),\{0,1\}$/\1/p" "$1" |
    head -1
}
median() {
  sort -g | awk '{ v[NR] = $1 } END { if (NR) print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
runs() { for f in "$out/$1".*.json; do field "$f" "$2"; done; }
cpu_median=$(runs cpu seconds | median)
echo "| backend | device | seconds, median (runs) | device time, median | Mrays/s | time / CPU's |"
echo "|---|---|---|---|---|---|"
for name in cpu "${suites[@]}"; do
  m=$(runs "$name" seconds | median)
  all=$(runs "$name" seconds | awk '{ printf "%s%.3f", (NR > 1 ? ", " : ""), $1 }')
  dev=$(runs "$name" gpu_seconds | grep -v null | median || true)
  rays=$(field "$out/$name.1.json" rays)
  backend=$(field "$out/$name.1.json" backend)
  device=$(field "$out/$name.1.json" device)
  [[ $name == cpu ]] && device="$device, $(field "$out/cpu.1.json" threads) threads"
  awk -v b="$backend" -v d="$device" -v m="$m" -v a="$all" -v g="${dev:-}" -v r="$rays" \
    -v c="$cpu_median" 'BEGIN { printf "| %s | %s | **%.3f** (%s) | %s | %.2f | %.2fx |\n",
      b, d, m, a, (g == "" ? "-" : sprintf("%.3f", g)), r / m / 1e6, m / c }'
done
