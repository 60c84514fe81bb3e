#!/usr/bin/env bash
# Install what is missing, build, and time Wobble's stepper against the plain reference on the
# curtain, 128x128 and 256x256 cloths and the jelly; ends with one table and the Chebyshev curve.
# Extra arguments go to Google Benchmark (e.g. --benchmark_filter=curtain);
# --self-collision prints the self-collision rows alone (--self-collision-motion: only whether it
# leaves free motion free, docs/performance.md; --self-collision-settling: whether the
# shipped pile settles with fewer iterations or a thinner cloth; --self-collision-landing:
# whether the tests' pile settles when it lands harder), --contact the contact rows;
# --solvers races L-BFGS against local-global (docs/solvers.md).
#
# bash scripts/benchmark.sh --busy-neighbour [--rounds N] [SCENE ...]
#   instead times every shipped scene's step quiet and beside a busy process that the benchmark
#   starts and stops itself, in turn, and prints both columns and their ratio.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/ensure-packages.sh
ensure_packages test
build_wobble -DWOBBLE_BUILD_TESTS=ON
cmake --build build --parallel "$(nproc)" --target wobble_benchmark wobble_busy_neighbour
if [ "${1:-}" = --busy-neighbour ]; then
  shift
  exec build/tests/wobble_busy_neighbour "$@"
fi
exec build/tests/wobble_benchmark "$@"
