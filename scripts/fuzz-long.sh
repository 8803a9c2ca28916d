#!/usr/bin/env sh
# The long fuzz of the input contract (issue 29): thousands of accepted inputs, every
# chapter drawn from its own seed, each run in --quick mode on the release binary, for a
# bounded time. Prints per chapter the accepted runs and the exit-1 runs (a claim that
# failed on a valid input: must be 0) and fails on any breach of the contract.
#
#   scripts/fuzz-long.sh [SECONDS] [CASES_PER_CHAPTER] [SEED]
#
# Defaults: 240 s, 400 cases per chapter, the test's fixed seed, one worker per core
# (WORKBOOK_FUZZ_JOBS to change). Run it before a change
# to a model, a tolerance or a flag range; the per-chapter fuzz in `cargo test` is its
# short version.
set -eu
cd "$(dirname "$0")/.."
seconds="${1:-240}"
cases="${2:-400}"
cargo build --release --locked --bin workbook
export WORKBOOK_FUZZ_BIN="$PWD/target/release/workbook"
export WORKBOOK_FUZZ_SECONDS="$seconds"
export WORKBOOK_FUZZ_CASES="$cases"
if [ -n "${3:-}" ]; then
    export WORKBOOK_FUZZ_SEED="$3"
fi
exec cargo test --locked --test suite fuzz::long_fuzz_has_no_exit_1 -- --ignored --nocapture
