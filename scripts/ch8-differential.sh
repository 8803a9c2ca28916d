#!/usr/bin/env bash
# Chapter 8's long differential test (issue 29): the event-driven model against the
# chapter's Moreau-Jean time-stepper on CH8_DIFF_SCENES random scenes (default 200) of
# 1 s each, in release mode. Run it before a change to the contact code
# (src/physics/stick_inertia/): every scene must agree within Moreau-Jean's own error
# estimate (refined to T/3276800), or the event-driven run must say it cannot vouch for
# its answer. Where the ladder is not conclusive at the end (or the gap is within 3 times
# its estimate), the run is checked window by window: Moreau-Jean started from the
# event-driven state at the start of every window of at most a drive period must reach
# the event-driven state at its end within its own estimate (AgreeWindowed, with the
# measured growth of a 1e-9 rad perturbation of theta(0) to the end). A scene neither
# agreeing nor invalid fails. Two-solution pivots are checked against a stiff compliant
# contact (docs/ch8-contact-checks.md).
#
#   scripts/ch8-differential.sh            # 200 scenes (a few minutes)
#   CH8_DIFF_SCENES=1000 scripts/ch8-differential.sh
#   CH8_DIFF_ONLY=76 scripts/ch8-differential.sh       # one scene of the draw
#   CH8_DIFF_ONLY=10,16,88 scripts/ch8-differential.sh # several
#   CH8_DIFF_WINDOWED=1 scripts/ch8-differential.sh    # every scene window by window
#   CH8_DIFF_DEBUG=1 ...                               # every window's result
# (150 scenes: 2 min 41 s of CPU, 5 min 19 s on a shared 2-core machine at load 5 to 6)
set -euo pipefail
cd "$(dirname "$0")/.."
export CH8_DIFF_SCENES="${CH8_DIFF_SCENES:-200}"
exec cargo test --release --test suite ch8_differential:: -- --ignored --nocapture
