#!/usr/bin/env bash
# Browser test of `workbook lab` (book/lab-test.mjs): starts the lab on a free loopback
# port, drives the page in headless Chromium (slider, animation, an invalid value, a click
# on the speed map, a comparison; issue 31: the book's mode colours, the force on top of
# the rod, the foot close-up, log sliders, timeline ticks, the three downloads, the
# stroboscope, chapter 8's rod and ghost, the guided tasks, the 400 px layout) and
# compares the page's numbers and error line with the CLI's (chapters 6 and 8). Reports
# the slider-to-redraw latency. Screenshots at 1280 and 400 px wide land in
# target/lab-screenshots/ (look at them).
# Uses the release build (what the README's commands build, so `.ci/run` builds no second
# profile; the latency a reader sees with `cargo run --release -- lab`); LAB_PROFILE=dev
# tests the dev binary.
# Installs the Debian package chromium when it is missing (apt-get, about 20 s).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v chromium >/dev/null; then
  echo "+ apt-get install chromium" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium >/dev/null
fi
profile="${LAB_PROFILE:-release}"
if [ "$profile" = release ]; then
  cargo build --release --locked --bin workbook
  bin=target/release/workbook
else
  cargo build --locked --bin workbook
  bin=target/debug/workbook
fi
node_flags=()
if node --experimental-websocket -e '' 2>/dev/null && ! node -e 'WebSocket' 2>/dev/null; then
  node_flags=(--experimental-websocket)
fi
node "${node_flags[@]}" book/lab-test.mjs "$(command -v chromium)" "$bin"
