#!/usr/bin/env bash
# Install the Debian packages Wobble needs, but only those that are missing: a machine that has
# them all is left untouched and nothing is downloaded. Sourced by run.sh, test.sh and fuzz.sh.
set -euo pipefail

# What building and running wobble needs.
run_packages=(
  cmake ninja-build g++ pkg-config      # toolchain
  libeigen3-dev                         # simulation core
  libcli11-dev nlohmann-json3-dev       # command line
  libglfw3-dev libimgui-dev             # window and panel
  libegl-dev libegl-mesa0 libgl1-mesa-dri  # headless EGL, and Mesa's renderer (llvmpipe)
  libspng-dev                           # PNG input and output
  # --record FILE.webm / FILE.mp4: FFmpeg's libraries (they bring libvpx and libx264)
  libavcodec-dev libavformat-dev libavutil-dev libswscale-dev
  procps                                # ps: the checker's clean-up on a signal
)
# What the test suite needs on top: the window smoke test runs under a virtual X server.
test_packages=(
  libgtest-dev libbenchmark-dev
  xvfb xauth
  strace                                # a test watches the atomic write's system calls
  python3                               # tests/docs/check_links.py: the docs' links resolve
)

# What scripts/build-web.sh needs on top: emscripten, and dpkg-dev for `apt-get source` (Dear
# ImGui, libspng and zlib are compiled for the browser from Debian's source packages).
web_packages=(
  emscripten dpkg-dev
)
# What the web tests need on top (tests/web/): headless Chromium draws the page with WebGL 2.
web_test_packages=(
  chromium
)

# What scripts/fuzz.sh needs on top: clang and its libFuzzer and sanitizer runtimes.
fuzz_packages=(
  clang libclang-rt-14-dev
)

# ensure_packages run|test|fuzz|web
ensure_packages() {
  local wanted=("${run_packages[@]}")
  [ "${1:-run}" = test ] && wanted+=("${test_packages[@]}" "${web_packages[@]}"
                                     "${web_test_packages[@]}")
  [ "${1:-run}" = web ] && wanted+=("${web_packages[@]}")
  [ "${1:-run}" = fuzz ] && wanted+=("${fuzz_packages[@]}")
  local missing=()
  for package in "${wanted[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed'; then
      missing+=("$package")
    fi
  done
  [ ${#missing[@]} -eq 0 ] && return 0

  echo "wobble: installing missing Debian packages: ${missing[*]}" >&2
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null 2>&1; then
      echo "wobble: missing packages (${missing[*]}) and no sudo; run as root or install them" >&2
      exit 1
    fi
    sudo=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo[@]}" apt-get update -q
  "${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}" </dev/null
}

# seed_test_costs BUILD_FOLDER COSTS_FILE: ctest runs the longest tests first when it knows their
# times from an earlier run (BUILD_FOLDER/Testing/Temporary/CTestCostData.txt). A fresh build has
# none, and in declared order the longest could start last, with one core idle meanwhile; so it
# starts from a reference run's times (the file's lines without its # comments). Once ctest has
# run, its own times replace them.
seed_test_costs() {
  local costs="$1/Testing/Temporary/CTestCostData.txt"
  [ -f "$costs" ] && return 0
  mkdir -p "$(dirname "$costs")"
  grep -v '^#' "$2" > "$costs"
}

# Configure and build into build/ (Release). Extra arguments go to cmake's configure step.
build_wobble() {
  local root
  root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
  cmake -S "$root" -B "$root/build" -G Ninja "$@" >/dev/null
  cmake --build "$root/build" --parallel "$(nproc)"
}
