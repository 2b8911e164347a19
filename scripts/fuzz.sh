#!/usr/bin/env bash
# Builds and runs the libFuzzer targets of fuzz/ (docs/fuzzing.md) with clang-14, AddressSanitizer
# and UndefinedBehaviorSanitizer, in build-fuzz/.
#
#   scripts/fuzz.sh TARGET SECONDS   build TARGET's fuzzer and run it for SECONDS
#   scripts/fuzz.sh all SECONDS      every target in turn, SECONDS each
#   scripts/fuzz.sh --list           the targets
#
# The corpus of each target grows in build-fuzz/corpus/TARGET (seeds from assets/, tests/data/
# and fuzz/seeds/ are copied in first); crashes, timeouts and out-of-memory inputs land in
# build-fuzz/artifacts/TARGET/, the log in build-fuzz/logs/TARGET.log. Each run ends with a
# summary line: executions, exec/s, coverage (cov, ft), corpus size and findings. The exit code
# is 1 when a run found something, 2 for bad arguments.
#
# The build and the runs are niced (CPU is shared); FUZZ_BUILD_JOBS sets the build's parallelism
# (default 1). FUZZ_SKIP_BUILD=1 runs the fuzzers as they were last built (while another build
# uses build-fuzz/, say).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$ROOT/build-fuzz"

usage() {
  sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'
}

# target | -max_len (bytes; about twice the largest useful seed) | seed files and directories
TARGETS=(
  "control_mesh_json|8192|assets/*.json tests/data/*.json"
  "vtk_volume_mesh|8192|generated"
  "gmsh_mesh|8192|"
  "tetgen_mesh|8192|"
  "obj_surface|16384|assets/bunny.obj generated"
  "gltf_surface|16384|generated"
  "session_script|8192|assets/scripts/*.json"
  "project_file|16384|generated"
  "preferences|4096|generated"
  "key_map|4096|"
  "hid_profile|4096|assets/hid_profiles/*.json"
  "hid_recording|16384|tests/data/hid/*.txt"
)

target_names() {
  local entry
  for entry in "${TARGETS[@]}"; do echo "${entry%%|*}"; done
}

target_entry() {
  local entry
  for entry in "${TARGETS[@]}"; do
    if [[ "${entry%%|*}" == "$1" ]]; then
      echo "$entry"
      return 0
    fi
  done
  return 1
}

bad_usage() {
  echo "scripts/fuzz.sh: $*" >&2
  usage >&2
  exit 2
}

if [[ $# -eq 1 && "$1" == "--list" ]]; then
  target_names
  exit 0
fi
if [[ $# -eq 1 && ( "$1" == "-h" || "$1" == "--help" ) ]]; then
  usage
  exit 0
fi
[[ $# -eq 2 ]] || bad_usage "expected TARGET SECONDS, 'all SECONDS' or --list"
[[ "$2" =~ ^[1-9][0-9]*$ ]] || bad_usage "SECONDS must be a positive whole number (got '$2')"
SECONDS_PER_TARGET="$2"
if [[ "$1" == "all" ]]; then
  mapfile -t SELECTED < <(target_names)
else
  target_entry "$1" >/dev/null ||
    bad_usage "unknown target '$1' (scripts/fuzz.sh --list shows the targets)"
  SELECTED=("$1")
fi

for tool in clang-14 clang++-14 cmake ninja; do
  command -v "$tool" >/dev/null 2>&1 ||
    { echo "scripts/fuzz.sh: $tool not found; run scripts/install-deps.sh" >&2; exit 1; }
done

# Seeds the project's writers make from the assets (formats no file in the tree is in), needed
# by the targets whose seed list says "generated".
build_targets=()
for name in "${SELECTED[@]}"; do
  build_targets+=("${name}_fuzzer")
  [[ "$(target_entry "$name")" != *generated* ]] || needs_generated=1
done
[[ -z "${needs_generated:-}" ]] || build_targets+=(fuzz_make_seeds)

if [[ "${FUZZ_SKIP_BUILD:-0}" != 1 ]]; then
  echo "==== configure $BUILD (clang-14, SCULPT_FUZZ=ON) ===="
  mkdir -p "$BUILD"
  nice -n 10 cmake -S "$ROOT" -B "$BUILD" -G Ninja --no-warn-unused-cli \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14 \
    -DSCULPT_FUZZ=ON -DSCULPT_BUILD_TESTS=OFF -DSCULPT_BUILD_BENCH=OFF -DSCULPT_WERROR=ON \
    >"$BUILD/configure.log" 2>&1 || { cat "$BUILD/configure.log" >&2; exit 1; }
  echo "==== build ${build_targets[*]} ===="
  nice -n 10 cmake --build "$BUILD" --parallel "${FUZZ_BUILD_JOBS:-1}" --target "${build_targets[@]}"
fi
for target in "${build_targets[@]}"; do
  [[ -x "$BUILD/bin/$target" ]] ||
    { echo "scripts/fuzz.sh: $BUILD/bin/$target is not built" >&2; exit 1; }
done

# One directory per process, so that two runs of this script can share build-fuzz/.
GENERATED="$BUILD/seeds-generated/$$"
if [[ -n "${needs_generated:-}" ]]; then
  rm -rf "$GENERATED"
  "$BUILD/bin/fuzz_make_seeds" "$ROOT" "$GENERATED"
fi

# Copies the seeds of target $1 into its corpus (existing corpus files are kept).
seed_corpus() {
  local name="$1" sources="$2" corpus="$BUILD/corpus/$1" pattern file
  mkdir -p "$corpus"
  cd "$ROOT"
  for pattern in $sources "fuzz/seeds/$name/*" "tests/data/fuzz/$name/*"; do
    if [[ "$pattern" == generated ]]; then
      pattern="$GENERATED/$name/*"
    fi
    for file in $pattern; do
      [[ -f "$file" ]] && cp -n "$file" "$corpus/" || true
    done
  done
}

# The last status line of a libFuzzer log ("#N ... cov: C ft: F corp: ... exec/s: E ...").
summarise() {
  local name="$1" log="$2" artifacts="$3" status line runs execs cov ft corpus findings
  line="$(grep -E '^#[0-9]+.*cov: ' "$log" | tail -n 1 || true)"
  runs="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)"
  execs="$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)"
  cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<<"$line")"
  ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<<"$line")"
  corpus="$(find "$BUILD/corpus/$name" -type f | wc -l)"
  findings="$(find "$artifacts" -type f | wc -l)"
  status="ok"
  [[ "$findings" -eq 0 ]] || status="FOUND $findings input(s) in ${artifacts#"$ROOT"/}"
  printf '%-18s runs=%s exec/s=%s cov=%s ft=%s corpus=%s  %s\n' "$name" "${runs:-?}" \
    "${execs:-?}" "${cov:-?}" "${ft:-?}" "$corpus" "$status"
}

SUMMARY=()
EXIT=0
for name in "${SELECTED[@]}"; do
  entry="$(target_entry "$name")"
  max_len="$(cut -d'|' -f2 <<<"$entry")"
  seed_corpus "$name" "$(cut -d'|' -f3 <<<"$entry")"
  artifacts="$BUILD/artifacts/$name"
  log="$BUILD/logs/$name.log"
  mkdir -p "$artifacts" "$BUILD/logs"
  echo "==== fuzz $name for ${SECONDS_PER_TARGET} s (log: ${log#"$ROOT"/}) ===="
  # Leaks are reported too (ASan's default); -timeout and -rss_limit_mb turn hangs and unbounded
  # allocation into findings.
  set +e
  nice -n 15 "$BUILD/bin/${name}_fuzzer" "$BUILD/corpus/$name" \
    -max_total_time="$SECONDS_PER_TARGET" -timeout=10 -rss_limit_mb=2048 -max_len="$max_len" \
    -artifact_prefix="$artifacts/" -print_final_stats=1 >"$log" 2>&1
  rc=$?
  set -e
  grep -E '^#[0-9]+' "$log" | tail -n 1 || true
  SUMMARY+=("$(summarise "$name" "$log" "$artifacts")")
  if [[ $rc -ne 0 ]]; then
    EXIT=1
    grep -E 'ERROR|SUMMARY|contract broken|Test unit written' "$log" | head -n 5 >&2 || true
  fi
done

echo "==== summary ($(date -u '+%Y-%m-%d %H:%M UTC'), ${SECONDS_PER_TARGET} s per target) ===="
printf '%s\n' "${SUMMARY[@]}"
rm -rf "$GENERATED"
exit "$EXIT"
