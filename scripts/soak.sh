#!/usr/bin/env bash
# Soak test: a long headless run of the built-in cloth with scripted drags (default 100,000
# steps), watching that every step stays finite and that resident memory stays flat. Not part of
# the test suite: it takes a while. Usage: bash scripts/soak.sh [STEPS] [EXTRA WOBBLE ARGUMENTS]
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages run
build_wobble >/dev/null

steps=${1:-100000}
shift || true
[[ "$steps" =~ ^[0-9]+$ ]] && [ "$steps" -ge 1000 ] || {
  echo "soak: STEPS must be a whole number of at least 1000, got '$steps'" >&2
  exit 2
}

# Every 500 frames a drag of one second (60 frames): in turn a free corner flung up and across, a
# pinned corner pulled out and (next time) back, and the middle of the cloth pushed through.
drags=()
turn=0
for ((frame = 200; frame + 60 <= steps; frame += 500)); do
  case $((turn % 4)) in
    0) drags+=(--drag "1599:0.6,0.9,0.5@$frame-$((frame + 59))") ;;
    1) drags+=(--drag "0:-0.4,0.2,0.3@$frame-$((frame + 59))") ;;
    2) drags+=(--drag "820:0.1,-0.3,-0.8@$frame-$((frame + 59))") ;;
    3) drags+=(--drag "0:0.4,-0.2,-0.3@$frame-$((frame + 59))") ;;
  esac
  turn=$((turn + 1))
done

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s.%N)
build/src/app/wobble cloth --headless --frames "$steps" "${drags[@]}" \
  --export-obj "$out/final.obj" "$@" >"$out/stats" 2>"$out/err" &
pid=$!

# (No --stats: its per-step timings would grow memory by design.) Resident memory (kB) once a second while it runs.
: >"$out/rss"
while kill -0 "$pid" 2>/dev/null; do
  rss=$(awk '/^VmRSS:/ { print $2 }' "/proc/$pid/status" 2>/dev/null || true)
  [ -n "$rss" ] && echo "$(date +%s.%N) $rss" >>"$out/rss"
  sleep 1
done
status=0
wait "$pid" || status=$?
end=$(date +%s.%N)

cat "$out/err" >&2
samples=$(wc -l <"$out/rss")
echo "soak: $steps steps of the built-in cloth, ${#drags[@]} arguments of scripted drags ($((${#drags[@]} / 2)) drags)"
echo "soak: exit code $status, wall time $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.1f", b - a }') s"
if [ "$samples" -ge 2 ]; then
  # The first second covers start-up (loading, factorizing): memory is taken after it.
  awk 'NR == 2 { first = $2 } { last = $2; if ($2 > peak) peak = $2 }
       END { printf "soak: resident memory %d kB after 1 s, %d kB at the end, peak %d kB (%d samples)\n",
             first, last, peak, NR }' "$out/rss"
fi
if [ "$status" -ne 0 ]; then
  echo "soak: FAILED: wobble exited with $status" >&2
  exit 1
fi
non_finite=$(grep -ciE '^v .*(nan|inf)' "$out/final.obj" || true)
echo "soak: final positions: $(grep -c '^v ' "$out/final.obj") vertices, $non_finite non-finite"
if [ "$non_finite" -ne 0 ]; then
  echo "soak: FAILED: non-finite positions in the final frame" >&2
  exit 1
fi
# Flat: the end within 5% (and 4 MB) of the first sample after start-up.
if [ "$samples" -ge 3 ]; then
  awk 'NR == 2 { first = $2 } { last = $2 }
       END { grow = last - first; if (grow > 4096 && grow > 0.05 * first) exit 1 }' "$out/rss" || {
    echo "soak: FAILED: resident memory grew during the run" >&2
    exit 1
  }
fi
echo "soak: passed"
