#!/usr/bin/env bash
# A report as a person sees it: renders DIR/report.html in headless Chromium (Debian's
# `chromium` package: apt-get install chromium) and saves DIR/report.png, the top of the page
# at 1200 × 1500 px.
#
#   scripts/report_screenshot.sh [DIR]     default results/ballistic
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-results/ballistic}
[ -f "$dir/report.html" ] || { echo "no $dir/report.html: run demsweep report $dir first" >&2; exit 2; }
browser=$(command -v chromium || command -v chromium-browser || command -v google-chrome || true)
[ -n "$browser" ] || { echo "no chromium: apt-get install chromium" >&2; exit 2; }
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,1500 \
    --screenshot="$PWD/$dir/report.png" "file://$PWD/$dir/report.html" 2>/dev/null
echo "screenshot: $dir/report.png"
