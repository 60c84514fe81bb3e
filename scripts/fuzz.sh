#!/usr/bin/env bash
# Fuzz the five file loaders: build the libFuzzer harnesses of tests/fuzz/ with clang, ASan and
# UBSan into build-fuzz/, then run each for SECONDS_PER_HARNESS (default 60) seconds.
#
#   bash scripts/fuzz.sh [SECONDS_PER_HARNESS]
#
# Each harness starts from its seeds in tests/fuzz/corpus/HARNESS/, copied into a working corpus
# build-fuzz/fuzz/HARNESS/corpus/ that keeps growing from run to run (the repository's corpus is
# never written). A crash, sanitizer report, leak, timeout (10 s per input) or memory blow-up
# (2 GiB) is saved under build-fuzz/fuzz/HARNESS/findings/, and the script exits with 1 after
# running every harness, naming the files. Reproduce one with
#   build-fuzz/tests/fuzz/HARNESS FILE
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: bash scripts/fuzz.sh [SECONDS_PER_HARNESS]  (a whole number of seconds, default 60)" >&2
  exit 2
fi

source scripts/ensure-packages.sh
ensure_packages fuzz </dev/null

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DWOBBLE_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null </dev/null
cmake --build build-fuzz --parallel "$(nproc)" </dev/null

declare -A dictionary=(
  [fuzz_course_scene]=course_scene.dict
  [fuzz_wobble_scene]=wobble_scene.dict
  [fuzz_obj]=obj.dict
  [fuzz_medit_mesh]=medit_mesh.dict
  [fuzz_png]=png.dict
)
# A harness that crashes cannot remove its private folder, so the folders go here, cleared after
# each harness, rather than into /tmp.
export TMPDIR="$PWD/build-fuzz/fuzz/tmp"
findings=()
summary=()
for harness in fuzz_course_scene fuzz_wobble_scene fuzz_obj fuzz_medit_mesh fuzz_png; do
  work="build-fuzz/fuzz/$harness"
  mkdir -p "$work/corpus" "$work/findings" "$TMPDIR"
  cp -n "tests/fuzz/corpus/$harness/"* "$work/corpus/"
  log="$work/last-run.log"
  echo "wobble: fuzzing $harness for ${seconds}s (log: $log)" >&2
  # libFuzzer stops by itself after -max_total_time and kills a slow input after -timeout; the
  # outer timeout is only a backstop, so that the script can never hang.
  status=0
  timeout --kill-after=30 $((seconds + 300)) "build-fuzz/tests/fuzz/$harness" \
    -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
    -dict="tests/fuzz/${dictionary[$harness]}" -artifact_prefix="$work/findings/" \
    "$work/corpus" </dev/null >"$log" 2>&1 || status=$?
  rm -rf "$TMPDIR"/wobble-fuzz-*
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  speed=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  written=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" |
    grep -v '/slow-unit-' || true)
  if [ "$status" -ne 0 ] || [ -n "$written" ]; then
    echo "wobble: $harness FAILED (exit status $status); the end of $log:" >&2
    grep -E 'ERROR|SUMMARY|wobble fuzz:|terminate called|what\(\)' "$log" | head -n 8 >&2 || true
    for file in $written; do
      findings+=("$harness: $file")
    done
    [ -z "$written" ] && findings+=("$harness: no input saved, see $log")
    summary+=("$harness: FAILED after ${runs:-?} inputs")
  else
    summary+=("$harness: ok, ${runs:-?} inputs in ${seconds}s (${speed:-?}/s)")
  fi
done

printf 'wobble: %s\n' "${summary[@]}" >&2
if [ ${#findings[@]} -gt 0 ]; then
  echo "wobble: inputs that break a loader (rerun: build-fuzz/tests/fuzz/HARNESS FILE):" >&2
  printf '  %s\n' "${findings[@]}" >&2
  exit 1
fi
echo "wobble: no findings" >&2
