#!/usr/bin/env bash
# Build the course book and test every page in headless Chromium (book/browser-test.mjs):
# broken images, dead internal links and anchors, KaTeX errors, raw $ math, console errors
# and failed loads fail the test. Screenshots land in target/book-screenshots/.
# Installs the Debian package chromium when it is missing (apt-get, about 20 s).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v chromium >/dev/null; then
  echo "+ apt-get install chromium" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
fi
scripts/book-build.sh
node_flags=()
if node --experimental-websocket -e '' 2>/dev/null && ! node -e 'WebSocket' 2>/dev/null; then
  node_flags=(--experimental-websocket)
fi
node "${node_flags[@]}" book/browser-test.mjs "$(command -v chromium)"
