#!/bin/sh
# Looks at a report as a reader does: the whole index.html in headless Chromium, one full-page
# PNG, plus each figure alone (for a close look) under OUTDIR/figures/.
# Usage: postproc/docs/screenshot_report.sh RESULTS/report OUTDIR [WIDTH]
#   e.g. postproc/docs/screenshot_report.sh cases/sawyer2001/results/report /tmp/look
# Needs chromium (headless) and rsvg-convert (librsvg2-bin).
set -eu
report=$(cd "$1" && pwd)
out=$2
width=${3:-1400}
mkdir -p "$out/figures"
# The page's height: long enough for the whole report (chromium cuts the screenshot at the window).
height=${HEIGHT:-20000}
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$width,$height" \
  --screenshot="$out/page.png" "file://$report/index.html" 2>"$out/chromium.log" ||
  { cat "$out/chromium.log" >&2; exit 1; }
test -s "$out/page.png" || { echo "chromium wrote no $out/page.png (see $out/chromium.log)" >&2; exit 1; }
for svg in "$report"/plots/*.svg; do
  rsvg-convert -w 900 -b white -o "$out/figures/$(basename "$svg" .svg).png" "$svg"
done
echo "wrote $out/page.png and $(ls "$out/figures" | wc -l) figures in $out/figures"
