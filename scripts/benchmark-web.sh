#!/usr/bin/env bash
# The web step against the native step (docs/web.md): the median step of a scene (default the
# curtain, assets/curtain.json) over 120 steps, on one thread, natively (build/, as
# scripts/test.sh builds it) and in WebAssembly under node (build-web/, scripts/build-web.sh),
# which runs wasm with the same engine (V8) as Chrome. Prints a table and the ratio; a benchmark,
# never a pass or fail.
set -euo pipefail
cd "$(dirname "$0")/.."
scene="${1:-assets/curtain.json}"
native=build/src/app/web/wobble_step_positions
web=build-web/node/wobble_step_positions.js
for program in "$native" "$web"; do
  [ -f "$program" ] || { echo "wobble: $program is missing: run scripts/test.sh first" >&2; exit 1; }
done
median() { python3 -c 'import json, sys; print(json.load(sys.stdin)["step_ms_median"])'; }
native_ms=$("$native" "$scene" --frames 120 --threads 1 | median)
web_ms=$(PATH="/usr/bin:/bin:$PATH" node "$web" "$scene" --frames 120 --threads 1 | median)
printf '%-10s %-28s %10s\n' build runs "step (ms)"
printf '%-10s %-28s %10.2f\n' native "x86-64, --threads 1" "$native_ms"
printf '%-10s %-28s %10.2f\n' web "wasm under node $(node --version)" "$web_ms"
python3 -c "print(f'web / native: {$web_ms / $native_ms:.2f}x')"
