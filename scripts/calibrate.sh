#!/usr/bin/env bash
# The source's calibration, done once (seed 000 §7): scale the concrete's effective tensile
# strength and fracture toughness until the mean depth at 500 ft/s over three packings is 5 in.
#
#   scripts/calibrate.sh        2D: sweeps/penetration.toml (level 1) from
#                               sweeps/penetration_base.toml, and sweeps/penetration_ci.toml
#   scripts/calibrate.sh 3d     3D: the same for sweeps/penetration3d*.toml (the slab)
#
# The CI scene is the calibrated scene one refinement level down. Never edit either by hand;
# rerun this after a change to the base scene or to the physics.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-2d}" in
    2d) stem=penetration; ci_note="(R = 0.5 in, about 3 300 elements)" ;;
    3d) stem=penetration3d; ci_note="(concrete spheres of R = 1 in near the impact, 4 in away from it)" ;;
    *) echo "usage: scripts/calibrate.sh [2d|3d]" >&2; exit 2 ;;
esac
. scripts/demsweep_bin.sh
"$bin" calibrate --v0 500 --depth-in 5 --packings 3 --scene "sweeps/${stem}_base.toml" --out "sweeps/$stem.toml"
tmp="sweeps/${stem}_ci.toml.tmp"
{
    echo "# The CI scene: sweeps/$stem.toml one refinement level down $ci_note,"
    echo "# with the same calibration. Written by scripts/calibrate.sh; never edit."
    sed -e "s/^name = \"$stem\"\$/name = \"${stem}_ci\"/" -e 's/^level = 1$/level = 0/' "sweeps/$stem.toml"
} > "$tmp"
grep -q '^level = 0$' "$tmp" && grep -q "^name = \"${stem}_ci\"\$" "$tmp" || { echo "calibrate.sh: could not derive the CI scene" >&2; rm -f "$tmp"; exit 1; }
mv "$tmp" "sweeps/${stem}_ci.toml"
echo "wrote sweeps/$stem.toml and sweeps/${stem}_ci.toml"
