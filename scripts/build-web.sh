#!/usr/bin/env bash
# Build Wobble for the browser (docs/web.md): a static site in build-web/site/ (index.html,
# wobble.js, wobble.wasm, wobble.data with assets/ preloaded) to copy to any static host, and
# build-web/node/ (wobble_step_positions.js for node: the web tests' numbers).
#
# Installs what is missing (emscripten, and Debian's imgui, libspng and zlib sources, fetched
# once with `apt-get source` into build-web/sources/), then builds with emcmake into
# build-web/cmake/ from the same sources as the desktop program. Nothing is downloaded at build
# or run time besides that install step. Works as root or with sudo.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
source scripts/ensure-packages.sh
ensure_packages web

# Debian's emscripten breaks with another python3 first on PATH, and needs Debian's node
# modules when another node is installed.
export PATH="/usr/bin:/bin:$PATH"
export NODE_PATH=/usr/share/nodejs

as_root() {
  if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi
}

# Debian's source packages of what the browser build compiles, unpacked under fixed names.
sources="$root/build-web/sources"
fetch_sources() {
  [ -d "$sources/imgui" ] && [ -d "$sources/libspng" ] && [ -d "$sources/zlib" ] && return 0
  if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "wobble: adding Debian's source packages (deb-src) to apt's sources" >&2
    as_root tee /etc/apt/sources.list.d/wobble-deb-src.sources >/dev/null <<'SOURCES'
Types: deb-src
URIs: http://deb.debian.org/debian
Suites: bookworm
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
    as_root apt-get update -q
  fi
  local download="$root/build-web/sources.tmp"
  rm -rf "$download" && mkdir -p "$download"
  (cd "$download" && apt-get source -q imgui libspng zlib </dev/null >/dev/null)
  mkdir -p "$sources"
  for name in imgui libspng zlib; do
    rm -rf "${sources:?}/$name"
    mv "$(find "$download" -mindepth 1 -maxdepth 1 -type d -name "$name-*" | head -n 1)" \
       "$sources/$name"
  done
  rm -rf "$download"
}
fetch_sources

# The browser's ImGui must be the desktop's: the panel code is written for one version.
version_of() { grep -m1 '#define IMGUI_VERSION ' "$1" | cut -d'"' -f2; }
if [ "$(version_of "$sources/imgui/imgui.h")" != "$(version_of /usr/include/imgui/imgui.h)" ]; then
  echo "wobble: Debian's imgui source ($(version_of "$sources/imgui/imgui.h")) is not the" \
       "desktop's libimgui-dev ($(version_of /usr/include/imgui/imgui.h))" >&2
  exit 1
fi

emcmake cmake -S "$root" -B "$root/build-web/cmake" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DWOBBLE_BUILD_TESTS=OFF -DWOBBLE_WEB_SOURCES="$sources" >/dev/null
cmake --build "$root/build-web/cmake" --parallel "$(nproc)" --target wobble_web wobble_step_positions

site="$root/build-web/site"
rm -rf "$site" && mkdir -p "$site"
built="$root/build-web/cmake/src/app/web"
cp "$root/src/app/web/index.html" "$built/wobble.js" "$built/wobble.wasm" "$built/wobble.data" \
   "$site/"
mkdir -p "$root/build-web/node"
cp "$built/wobble_step_positions.js" "$built/wobble_step_positions.wasm" "$root/build-web/node/"
echo "wobble: the site is in build-web/site/ ($(du -sh "$site" | cut -f1)); serve it with" \
     "scripts/serve-web.sh PORT" >&2
