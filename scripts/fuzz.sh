#!/usr/bin/env bash
# The input fuzzing of tests/input_fuzz.rs with many more cases than CI runs:
#
#   scripts/fuzz.sh [CASES]      CASES per reading property (default 50 000); BUILD_CASES
#                                builds of the CI scenes (default a tenth; each ~0.1-1 s)
#
# Prints how many mutated scene files, --set strings and built scenes were read in total.
# New random cases each run (CI draws the same ones each time); a failure prints its minimal input.
set -euo pipefail
cd "$(dirname "$0")/.."
cases=${1:-50000}
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$HOME/.cache/demsweep-target}"
export DEMSWEEP_FUZZ_RANDOM=1
DEMSWEEP_FUZZ_CASES=$cases cargo test --release --test input_fuzz -- --nocapture --test-threads 2 mutated any_set 2>&1 | grep -E "input_fuzz:|test result|panicked|FAILED|minimal"
DEMSWEEP_FUZZ_CASES=${BUILD_CASES:-$((cases / 10))} cargo test --release --test input_fuzz -- --nocapture accepted_ci 2>&1 | grep -E "input_fuzz:|test result|panicked|FAILED|minimal"
