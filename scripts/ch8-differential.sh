#!/usr/bin/env bash
# Chapter 8's long differential test (issue 29): the event-driven model against the
# chapter's Moreau-Jean time-stepper on CH8_DIFF_SCENES random scenes (default 200) of
# 1 s each, in release mode. Run it before a change to the contact code
# (src/physics/stick_inertia/): every scene must agree within Moreau-Jean's own error
# estimate, or the event-driven run must say it cannot vouch for its answer; a scene whose
# Moreau-Jean ladder never reaches its asymptotic range (refined to T/819200) is
# inconclusive, and at most a quarter may be.
#
#   scripts/ch8-differential.sh            # 200 scenes (a few minutes)
#   CH8_DIFF_SCENES=1000 scripts/ch8-differential.sh
#   CH8_DIFF_ONLY=76 scripts/ch8-differential.sh   # one scene of the draw
# (150 scenes: about 10 minutes on a shared 2-core machine)
set -euo pipefail
cd "$(dirname "$0")/.."
export CH8_DIFF_SCENES="${CH8_DIFF_SCENES:-200}"
exec cargo test --release --test suite ch8_differential:: -- --ignored --nocapture
