#!/usr/bin/env bash
# The row-groups timing prototype (scripts/row_groups_prototype.rs; README "The one-thread beam on
# this machine"): the bond lanes on an all-bonded block, contacts gathered as demsweep does against
# contacts grouped by lattice row and direction. Built with rustc alone, at demsweep's release
# optimisation, into a scratch folder; not part of the product or of CI.
#
#   scripts/row_groups_prototype.sh [COLS ROWS STEPS ROUNDS]   (default 120 100 500 7)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d /tmp/demsweep-rowproto.XXXXXX)
rustc --edition 2024 -C opt-level=3 -C codegen-units=1 -o "$work/row_groups_prototype" scripts/row_groups_prototype.rs
"$work/row_groups_prototype" "$@"
