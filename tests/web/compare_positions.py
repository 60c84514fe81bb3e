#!/usr/bin/env python3
"""The web build computes the desktop's numbers: the stepper compiled to WebAssembly and run
under node (build-web/node/wobble_step_positions.js) gives the native build's positions after 60
steps, to 1e-9 of the rest shape's bounding-box diagonal, for the course's scenes and the
built-in cloth and jelly.

Why 1e-9 and not 0: both are IEEE double precision with no fused multiply-add, but the native
build's Eigen sums some dot products in SSE2 lanes and the WebAssembly build (no SIMD) one term
at a time, so the last bits may differ and grow a little over the steps (cloth: about 1e-11 of
the diagonal after 60 steps). A real difference in the method (a missing force, another solver
path, single precision) moves the vertices by far more.

  compare_positions.py NATIVE_PROGRAM NODE_PROGRAM SCENE...
"""
import json
import math
import os
import subprocess
import sys

TOLERANCE = 1e-9  # of the bounding-box diagonal
FRAMES = '60'


def run(command):
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    if result.returncode != 0:
        raise RuntimeError(f'{" ".join(command)} exited {result.returncode}: {result.stderr}')
    return json.loads(result.stdout)


def main():
    native_program, node_program, scenes = sys.argv[1], sys.argv[2], sys.argv[3:]
    node = ['node'] if os.path.exists('/usr/bin/node') else ['nodejs']
    failed = 0
    for scene in scenes:
        options = [scene, '--frames', FRAMES, '--threads', '1']
        native = run([native_program] + options)
        web = run(node + [node_program] + options)
        if len(native['positions']) != len(web['positions']):
            print(f'{scene}: {len(native["positions"])} native vertices, '
                  f'{len(web["positions"])} in WebAssembly')
            failed += 1
            continue
        largest = max(math.dist(a, b) for a, b in zip(native['positions'], web['positions']))
        relative = largest / native['diagonal']
        ok = relative <= TOLERANCE
        failed += not ok
        print(f'{native["scene"]}: {len(native["positions"])} vertices, largest distance '
              f'{largest:.3e} m = {relative:.3e} of the diagonal '
              f'({"ok" if ok else "MORE THAN"} {TOLERANCE:g})')
    print(f'{len(scenes) - failed} passed, {failed} failed')
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
