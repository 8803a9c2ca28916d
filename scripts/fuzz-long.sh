#!/usr/bin/env sh
# The long fuzz of the input contract (issue 29): thousands of accepted inputs, every
# chapter drawn from its own seed, each run in --quick mode in one process through the
# CLI's own entry point (no process start, no figures), on 2 threads.
#
#   scripts/fuzz-long.sh [CHAPTER_SECONDS] [DRAWS_PER_CHAPTER] [SEED]
#
# Per-chapter budget: every chapter runs until it has run its DRAWS_PER_CHAPTER draws
# (default 500) or spent its own time budget, CHAPTER_SECONDS (default 45 s of thread
# time) times a factor for the three chapters whose quick run is intrinsically slow:
# vertical-shaking x6 (a quick run costs 5 to 11 s, its flight-time, law and viscous
# sweeps up to Gamma = 32768), stick-with-inertia x3 (3 to 8 s, its evidence scenes
# and rod-mass ladder), speed-vs-accuracy x2 (1 to 3 s, its work-precision ladders).
# Neither slow chapter has a flag that selects a smaller piece of its run (the cost is
# in the evidence every run repeats; a short --duration-s does not shorten it), so
# they get more time instead. The chapters are interleaved: a free thread takes the
# chapter that has used the smallest fraction of its budget, so the cheap chapters run
# all their draws early and no chapter waits for another's leftovers. The wall time
# is at most the sum of the budgets over the threads (printed at the start; about
# 5 minutes with the defaults on an idle machine).
#
# Output: one line per chapter (runs, accepted, exit 0/1/2, runs that said `invalid`,
# panics, non-finite outputs, slowest run, time used of the budget), the command line
# of each chapter's slowest run, and the command line and failed claims (id, expected,
# computed, tolerance) of every breach as it happens. Exits nonzero if any accepted run
# ended exit 1, panicked, wrote NaN, inf or null, or broke the contract otherwise.
#
# Environment: WORKBOOK_FUZZ_JOBS (threads, default 2); WORKBOOK_FUZZ_FINDINGS=FILE
# appends every breach to FILE as it is found (UTC time, command line, what failed);
# WORKBOOK_FUZZ_CHAPTERS=id,id runs only those chapters (before a change to one of the
# slow chapters, e.g. WORKBOOK_FUZZ_CHAPTERS=vertical-shaking scripts/fuzz-long.sh 90).
# Run it before a change to a model, a tolerance or a flag range; the per-chapter fuzz
# in `cargo test` (tests/fuzz.rs) is its short version. Everything is built in the
# release profile, as `cargo test --release` builds it. docs/fuzz.md has the figures.
set -eu
cd "$(dirname "$0")/.."
export WORKBOOK_FUZZ_CHAPTER_SECONDS="${1:-45}"
export WORKBOOK_FUZZ_CASES="${2:-500}"
export WORKBOOK_FUZZ_JOBS="${WORKBOOK_FUZZ_JOBS:-2}"
if [ -n "${3:-}" ]; then
    export WORKBOOK_FUZZ_SEED="$3"
fi
exec cargo test --release --locked --test suite fuzz::long_fuzz_has_no_exit_1 -- --ignored --nocapture
