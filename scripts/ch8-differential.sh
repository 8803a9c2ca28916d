#!/usr/bin/env bash
# Chapter 8's long differential test (issue 29): the event-driven model against the
# chapter's Moreau-Jean time-stepper on CH8_DIFF_SCENES random scenes (default 200) of
# 1 s each, in release mode. Run it before a change to the contact code
# (src/physics/stick_inertia/): every scene must agree within Moreau-Jean's own error
# estimate (refined to T/3276800), or the event-driven run must say it cannot vouch for
# its answer. Where the ladder is not conclusive at the end, the two are compared at the
# latest whole drive period at which it is (AgreeUntil, with the measured sensitivity of
# the end: a run from theta(0) + 1e-9 rad); a gap within 3 times the estimate, or a
# ladder conclusive nowhere, is inconclusive, and at most a quarter may be. Two-solution
# pivots are checked against a stiff compliant contact (docs/ch8-contact-checks.md).
#
#   scripts/ch8-differential.sh            # 200 scenes (a few minutes)
#   CH8_DIFF_SCENES=1000 scripts/ch8-differential.sh
#   CH8_DIFF_ONLY=76 scripts/ch8-differential.sh   # one scene of the draw
# (150 scenes: 3 min 17 s of CPU, 8 min 42 s on a shared 2-core machine at load 10)
set -euo pipefail
cd "$(dirname "$0")/.."
export CH8_DIFF_SCENES="${CH8_DIFF_SCENES:-200}"
exec cargo test --release --test suite ch8_differential:: -- --ignored --nocapture
