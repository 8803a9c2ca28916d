#!/usr/bin/env sh
# The long fuzz of the input contract (issue 29): thousands of accepted inputs, every
# chapter drawn from its own seed, each run in --quick mode in one process through the
# CLI's own entry point (no process start, no figures), on 2 threads, for a bounded time.
# Prints per chapter the accepted runs, the refused ones (exit 2: a range coupled to
# another flag), those that ended `invalid` and the exit-1 runs (a claim that failed on
# a valid input: must be 0), with the command line of every exit-1 run; fails on any
# breach of the contract.
#
#   scripts/fuzz-long.sh [SECONDS] [DRAWS_PER_CHAPTER] [SEED]
#
# Defaults: 240 s, 500 draws per chapter, the test's fixed seed, 2 threads
# (WORKBOOK_FUZZ_JOBS to change). A free thread takes the chapter with the least wall
# time so far: the cheap chapters run all their draws within seconds, the costly ones
# (vertical-shaking, stick-with-inertia: seconds per run) share the rest. Run it before
# a change to a model, a tolerance or a flag range; the per-chapter fuzz in `cargo test`
# is its short version. Everything is built in the release profile, as `cargo test
# --release` builds it.
set -eu
cd "$(dirname "$0")/.."
export WORKBOOK_FUZZ_SECONDS="${1:-240}"
export WORKBOOK_FUZZ_CASES="${2:-500}"
export WORKBOOK_FUZZ_JOBS="${WORKBOOK_FUZZ_JOBS:-2}"
if [ -n "${3:-}" ]; then
    export WORKBOOK_FUZZ_SEED="$3"
fi
exec cargo test --release --locked --test suite fuzz::long_fuzz_has_no_exit_1 -- --ignored --nocapture
