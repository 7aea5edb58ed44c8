#!/bin/sh
# Renders a page of a report (six of its figures, 2 x 3) to report-page.png for the README.
# Usage: postproc/docs/render_picture.sh RESULTS/report POINT_SLUG [OUT.png]
#   e.g. postproc/docs/render_picture.sh cases/sawyer2001/results/report u2-0
# Needs rsvg-convert (librsvg2-bin, .ci/packages).
set -eu
report=$1
slug=$2
out=${3:-$(dirname "$0")/report-page.png}
plots=$report/plots
page=$(mktemp --suffix=.svg)
trap 'rm -f "$page"' EXIT
{
  echo '<svg xmlns="http://www.w3.org/2000/svg" width="1080" height="1140" viewBox="0 0 1080 1140">'
  echo '<rect width="1080" height="1140" fill="#ffffff"/>'
  i=0
  for fig in profile_${slug}_u profile_${slug}_nu profile_${slug}_T stress_shear_stress_bottom slip_bottom solid_fraction; do
    x=$(( (i % 2) * 540 )); y=$(( (i / 2) * 380 ))
    # Nest each standalone SVG at its grid position.
    sed -e '1s/^<?xml[^>]*>//' -e "s/^<svg /<svg x=\"$x\" y=\"$y\" /" "$plots/$fig.svg"
    i=$((i + 1))
  done
  echo '</svg>'
} > "$page"
rsvg-convert -o "$out" "$page"
echo "wrote $out"
