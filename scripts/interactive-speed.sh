#!/usr/bin/env bash
# Measures the interactive-speed targets (docs/BENCHMARKS.md, "The interactive-speed targets")
# and prints each figure beside its limit, one block per round and binary.
#
#   scripts/interactive-speed.sh [--rounds N] [--build DIR] [--compare CLI SCULPT]
#
#   --build DIR     the build whose bin/sculpt-cli and bin/sculpt are measured (default: build)
#   --compare A B   also measures another sculpt-cli (A) and sculpt (B), alternating with the
#                   build's in every round: this machine's speed moves by 2x within an hour, so
#                   only binaries measured in the same minutes compare (copy a binary elsewhere
#                   before rebuilding, to keep it)
#   --rounds N      rounds (default 1; about 90 s each per binary on a 2-core machine)
#
# A limit that depends on another figure (the painted step against the unpainted one) is taken
# within the same round. The window's figures need a display: without $DISPLAY they run under
# xvfb-run. Exit status 0 once every round ran, whatever the verdicts; 2 on bad arguments.
# No -e: a command that fails leaves its figures as "?" (MISSED) and the round goes on.
set -uo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"

usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }

ROUNDS=1
BUILD="build"
COMPARE_CLI=""
COMPARE_SCULPT=""
# Fails (exit 2) unless option $1 has $2 values after it among the $3 arguments left.
needs() {
  if (($3 <= $2)); then
    echo "interactive-speed.sh: $1 needs $2 value(s)" >&2
    usage >&2
    exit 2
  fi
}
while [[ $# -gt 0 ]]; do
  case "$1" in
    --rounds) needs "$1" 1 $#; ROUNDS="$2"; shift 2 ;;
    --build) needs "$1" 1 $#; BUILD="$2"; shift 2 ;;
    --compare) needs "$1" 2 $#; COMPARE_CLI="$2"; COMPARE_SCULPT="$3"; shift 3 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "interactive-speed.sh: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
if ! [[ "$ROUNDS" =~ ^[1-9][0-9]*$ ]]; then
  echo "interactive-speed.sh: --rounds needs a positive whole number, got '$ROUNDS'" >&2
  exit 2
fi
LABELS=("$BUILD")
CLIS=("$BUILD/bin/sculpt-cli")
SCULPTS=("$BUILD/bin/sculpt")
if [[ -n "$COMPARE_CLI" ]]; then
  LABELS+=("compare")
  CLIS+=("$COMPARE_CLI")
  SCULPTS+=("$COMPARE_SCULPT")
fi
for program in "${CLIS[@]}" "${SCULPTS[@]}"; do
  if [[ ! -x "$program" ]]; then
    echo "interactive-speed.sh: $program is not an executable (build first: scripts/test.sh)" >&2
    exit 2
  fi
done
WINDOW=()
if [[ -z "${DISPLAY:-}" ]]; then
  if ! command -v xvfb-run >/dev/null 2>&1; then
    echo "interactive-speed.sh: no \$DISPLAY and no xvfb-run (scripts/install-deps.sh)" >&2
    exit 2
  fi
  WINDOW=(xvfb-run -a -s "-screen 0 1280x1024x24")
fi
SCRATCH="$(mktemp -d)"
trap 'rm -rf "$SCRATCH"' EXIT

# The value of `key=` in the last line of `text` that has it.
field() { grep -oE "(^| )$2=[^ ]+" <<<"$1" | tail -1 | cut -d= -f2; }
# Prints one figure: what, its value, and ok or MISSED against the limit ("<= x" or ">= x").
report() {
  local what="$1" value="$2" op="$3" limit="$4" verdict="MISSED"
  if [[ -n "$value" ]] &&
     awk -v v="$value" -v l="$limit" -v op="$op" \
       'BEGIN { exit !(op == "<=" ? v <= l : v >= l) }'; then
    verdict="ok"
  fi
  printf '  %-56s %9s  %s %-6s %s\n' "$what" "${value:-?}" "$op" "$limit" "$verdict"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.2f", a / b }'; }
# Wall seconds of a command, its output discarded.
seconds() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1 || echo "interactive-speed.sh: failed: $*" >&2
  end=$(date +%s.%N)
  awk -v a="$start" -v b="$end" 'BEGIN { printf "%.2f", b - a }'
}

measure() {
  local cli="$1" sculpt="$2" block10=(assets/block10.json --levels 1 --integrator implicit)
  local line plain painted fresh
  echo "point 1: painting never stalls the simulation"
  plain=$("$cli" bench fem "${block10[@]}" 2>&1 | tail -1)
  painted=$("$cli" bench fem "${block10[@]}" --paint-every 1 2>&1 | tail -1)
  fresh=$("$cli" bench fem "${block10[@]}" --paint-every 1 --fresh-factor 2>&1 | tail -1)
  local median
  median=$(field "$plain" fem_step_ms)
  printf '  block10 fem_step_ms %s unpainted; painted (--paint-every 1) %s, p99 %s, max %s;\n' \
    "$median" "$(field "$painted" fem_step_ms)" "$(field "$painted" step_p99_ms)" \
    "$(field "$painted" step_max_ms)"
  printf '  with a fresh factor at every dab (--fresh-factor): p99 %s (%sx), max %s (%sx)\n' \
    "$(field "$fresh" step_p99_ms)" "$(ratio "$(field "$fresh" step_p99_ms)" "$median")" \
    "$(field "$fresh" step_max_ms)" "$(ratio "$(field "$fresh" step_max_ms)" "$median")"
  report "painted step_p99_ms / unpainted fem_step_ms" \
    "$(ratio "$(field "$painted" step_p99_ms)" "$median")" "<=" 1.5
  report "painted step_max_ms / unpainted fem_step_ms" \
    "$(ratio "$(field "$painted" step_max_ms)" "$median")" "<=" 3
  local simulate=("$cli" simulate assets/block10.json --levels 1 --gravity --dt 0.016667
                  --steps 120)
  local dabs pins
  dabs=$(seconds "${simulate[@]}" --script assets/scripts/block10_paint60.json \
         --out "$SCRATCH/paint60.vtk")
  pins=$(seconds "${simulate[@]}" --script assets/scripts/block10_pin.json \
         --out "$SCRATCH/pin.vtk")
  printf '  simulate block10, 120 steps: with 60 dabs %s s, pinned only %s s\n' "$dabs" "$pins"
  report "60 dabs / pinned only (wall time)" "$(ratio "$dabs" "$pins")" "<=" 1.3
  # Not one of the targets: what the docs propose in place of the ratios above.
  line=$("${WINDOW[@]}" "$sculpt" --bench 120 --script assets/scripts/bunny_paint_stroke.json \
         2>&1 | tail -1)
  report "proposed: a paint stroke in the window, step_ms" "$(field "$line" step_ms)" "<=" 16.7

  echo "point 2: larger cages start at once"
  local model limit
  for model in "assets/block10.json 500" "assets/block12.json 1500"; do
    limit=${model#* }
    line=$("$cli" bench fem "${model% *}" --levels 1 --integrator implicit --steps 40 2>&1 |
           tail -1)
    report "${model% *} --levels 1: first_step_ms" "$(field "$line" first_step_ms)" "<=" "$limit"
    report "${model% *} --levels 1: step_passes" "$(field "$line" step_passes)" "<=" 8
  done
  line=$("$cli" bench fem assets/block3.json --levels 2 --integrator implicit --steps 40 2>&1 |
         tail -1)
  report "assets/block3.json --levels 2: step_passes" "$(field "$line" step_passes)" "<=" 8

  echo "point 3: the default scene runs ahead of real time"
  local frames
  for frames in 20 60; do
    line=$("${WINDOW[@]}" "$sculpt" --bench "$frames" 2>&1 | tail -1)
    report "sculpt --bench $frames: step_ms" "$(field "$line" step_ms)" "<=" 8.33
  done
  line=$(SCULPT_THREADS=1 "${WINDOW[@]}" "$sculpt" --bench 60 2>&1 | tail -1)
  report "SCULPT_THREADS=1 sculpt --bench 60: step_ms" "$(field "$line" step_ms)" "<=" 16.7
  # Not one of the targets: the window as it is used, drawing while the simulation steps on
  # the same cores (--bench above interleaves the two).
  line=$("${WINDOW[@]}" "$sculpt" --quit-after 8 2>&1 | grep '^simulation ran')
  printf '  the window for 8 s: %s\n' "${line:-no report}"
  report "the window for 8 s: real-time factor" \
    "$(sed -n 's/.* \([0-9.]*\)x real time.*/\1/p' <<<"$line")" ">=" 0.95
  local start running
  for start in 1 2 3; do
    running=$("${WINDOW[@]}" "$sculpt" --quit-after 0.3 2>&1 |
              sed -n 's/^simulation running after \([0-9.]*\) s$/\1/p')
    report "sculpt start $start: simulation running after (s)" "$running" "<=" 0.4
  done

  echo "point 5: the paper's Table 1"
  line=$("$cli" bench table1 2>&1 | tail -1)
  printf '  %s\n' "$line"
  report "models measured" "$(field "$line" models)" ">=" 8
  report "slowest model's FPS over the paper's, paper's scheme" \
    "$(field "$line" min_speedup_paper)" ">=" 1
  report "slowest model's FPS over the paper's, implicit" \
    "$(field "$line" min_speedup_implicit)" ">=" 1
}

echo "interactive-speed.sh on $(nproc) cores, $(date '+%F %T')"
echo "point 4 (accuracy) is the test suite: ctest -L 'ccx|fem|sim'"
for ((round = 1; round <= ROUNDS; ++round)); do
  for k in "${!LABELS[@]}"; do
    echo
    echo "== round $round, ${LABELS[$k]} (${CLIS[$k]}, ${SCULPTS[$k]}), $(date +%T)"
    measure "${CLIS[$k]}" "${SCULPTS[$k]}"
  done
done
