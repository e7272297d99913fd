#!/usr/bin/env bash
# Full-resolution validation studies (slow: tens of minutes on two cores). Regenerates the
# golden tables in results/validation/ with `demsweep validate`, then runs the tests that need
# the fine meshes. Commit the tables it writes; never edit them by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin=target/release/demsweep
$bin validate cracked-plate --levels 0,1,2
$bin validate cantilever --levels 0,1,2
cargo test --release -- --include-ignored
