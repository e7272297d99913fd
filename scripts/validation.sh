#!/usr/bin/env bash
# Full-resolution validation studies (slow: tens of minutes on two cores). Regenerates the
# golden tables in results/validation/ with `demsweep validate`, then runs the tests that need
# the fine meshes. Commit the tables it writes; never edit them by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin="${CARGO_TARGET_DIR:-target}/release/demsweep"
$bin validate cracked-plate --levels 0,1,2
$bin validate cantilever --levels 0,1,2
# Continuum references for the cracked plate (LEFM and a cohesive crack, plane-stress FE): a
# cross-check in Python (numpy, scipy), outside the product.
if python3 -c 'import numpy, scipy' 2>/dev/null; then python3 scripts/cohesive_sent.py; fi
cargo test --release -- --include-ignored
