#!/usr/bin/env bash
# Serve the site scripts/build-web.sh built (build-web/site/) on http://localhost:PORT/ until
# stopped (docs/web.md). Any static host serves it as well: the files are all there is.
set -euo pipefail
cd "$(dirname "$0")/.."
port="${1:-8080}"
site=build-web/site
if [ ! -f "$site/index.html" ] || [ ! -f "$site/wobble.wasm" ]; then
  echo "wobble: no site in $site; run scripts/build-web.sh first" >&2
  exit 1
fi
echo "wobble: serving $site on http://localhost:$port/ (Ctrl+C stops)" >&2
exec /usr/bin/python3 -m http.server "$port" --bind 127.0.0.1 --directory "$site"
