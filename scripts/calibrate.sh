#!/usr/bin/env bash
# The source's calibration, done once (seed 000 §7): scale the concrete's effective tensile
# strength and fracture toughness until the depth at 500 ft/s is 5 in. Writes
# sweeps/penetration.toml (the calibrated scene, level 1) from sweeps/penetration_base.toml, and
# sweeps/penetration_ci.toml, the same scene one refinement level down. Never edit either by
# hand; rerun this after a change to the base scene or to the physics.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
bin="${CARGO_TARGET_DIR:-target}/release/demsweep"
"$bin" calibrate --v0 500 --depth-in 5 --scene sweeps/penetration_base.toml --out sweeps/penetration.toml
tmp=sweeps/penetration_ci.toml.tmp
{
    echo "# The CI scene: sweeps/penetration.toml one refinement level down (R = 0.5 in, about"
    echo "# 3 300 elements), with the same calibration. Written by scripts/calibrate.sh; never edit."
    sed -e 's/^name = "penetration"$/name = "penetration_ci"/' -e 's/^level = 1$/level = 0/' sweeps/penetration.toml
} > "$tmp"
grep -q '^level = 0$' "$tmp" && grep -q '^name = "penetration_ci"$' "$tmp" || { echo "calibrate.sh: could not derive the CI scene" >&2; rm -f "$tmp"; exit 1; }
mv "$tmp" sweeps/penetration_ci.toml
echo "wrote sweeps/penetration.toml and sweeps/penetration_ci.toml"
