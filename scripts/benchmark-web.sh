#!/usr/bin/env bash
# The web step against the native step (docs/web.md): the median step of a scene (default the
# curtain, assets/curtain.json) over 120 steps, on one thread, natively (build/, as
# scripts/test.sh builds it) and in WebAssembly under node (build-web/, scripts/build-web.sh),
# which runs wasm with the same engine (V8) as Chrome, and in the page itself in headless Chromium
# (index.html?bench: the steps run once the page shows the scene). Prints a table and the ratios; a
# benchmark, never a pass or fail.
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
# The same steps inside the page, in headless Chromium.
browser_ms=$(python3 tests/web/bench_page.py build-web/site \
               --query "scene=$(basename "$scene" .json)&frames=120")
printf '%-10s %-28s %10s\n' build runs "step (ms)"
printf '%-10s %-28s %10.2f\n' native "x86-64, --threads 1" "$native_ms"
printf '%-10s %-28s %10.2f\n' web "wasm under node $(node --version)" "$web_ms"
printf '%-10s %-28s %10.2f\n' web "wasm in headless Chromium" "$browser_ms"
python3 -c "print(f'web / native: node {$web_ms / $native_ms:.2f}x, '
               f'Chromium {$browser_ms / $native_ms:.2f}x')"
