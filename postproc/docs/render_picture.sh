#!/bin/sh
# Renders a page of a report (six of its figures, 2 x 3) to docs/report-page.png, the READMEs' picture.
# Usage: postproc/docs/render_picture.sh RESULTS/report POINT_SLUG [OUT.png]
#   e.g. postproc/docs/render_picture.sh cases/sawyer2001/results/report u2-0
# Needs rsvg-convert (librsvg2-bin, .ci/packages).
set -eu
report=$1
slug=$2
out=${3:-$(dirname "$0")/../../docs/report-page.png}
plots=$report/plots
page=$(mktemp --suffix=.svg)
trap 'rm -f "$page"' EXIT
figs="profile_${slug}_u profile_${slug}_nu profile_${slug}_T stress_shear_stress_bottom slip_bottom solid_fraction"
# A figure is 380 px high, more when its legend sits below the frame: each row as high as its tallest.
height_of() { sed -n 's/^<svg [^>]*height="\([0-9.]*\)".*/\1/p' "$plots/$1.svg" | head -n 1 | cut -d. -f1; }
body=$(mktemp)
trap 'rm -f "$page" "$body"' EXIT
i=0; y=0; row=0
for fig in $figs; do
  x=$(( (i % 2) * 540 ))
  # Nest each standalone SVG at its grid position.
  sed -e '1s/^<?xml[^>]*>//' -e "s/^<svg /<svg x=\"$x\" y=\"$y\" /" "$plots/$fig.svg" >> "$body"
  h=$(height_of "$fig"); [ "$h" -gt "$row" ] && row=$h
  i=$((i + 1))
  if [ $((i % 2)) -eq 0 ]; then y=$((y + row)); row=0; fi
done
y=$((y + row))
{
  echo "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"1080\" height=\"$y\" viewBox=\"0 0 1080 $y\">"
  echo "<rect width=\"1080\" height=\"$y\" fill=\"#ffffff\"/>"
  cat "$body"
  echo '</svg>'
} > "$page"
rsvg-convert -o "$out" "$page"
echo "wrote $out"
