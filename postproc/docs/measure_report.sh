#!/bin/sh
# Measures a report as a reader's browser lays it out: headless Chromium opens a copy of index.html
# with a script that writes the measurements into the page, and --dump-dom prints them.
# Usage: postproc/docs/measure_report.sh RESULTS/report WIDTH HEIGHT
# Prints one JSON line: the viewport (clientWidth, innerHeight), the page's scrollWidth and
# scrollHeight (folds as the report leaves them), the summary's top and bottom (px from the top;
# -1 without a summary), images that did not load, how often the legend's note appears, and the
# figure titles (class "title"): how many, how many pass their figure's edge, by how much at most.
# Runs as root (CI) with --no-sandbox and a throw-away profile. Needs chromium.
set -eu
report=$(cd "$1" && pwd)
width=$2
height=$3
work=$(mktemp -d)
page="$report/.measure-$$.html"
trap 'rm -rf "$work" "$page"' EXIT
script='<script>
(function () {
  var d = document.documentElement, s = document.getElementById("s-summary"), top = -1, bottom = -1;
  if (s) {
    top = s.getBoundingClientRect().top + window.scrollY;
    bottom = s.getBoundingClientRect().bottom + window.scrollY;
    for (var e = s.nextElementSibling; e && e.tagName !== "H2"; e = e.nextElementSibling)
      bottom = Math.max(bottom, e.getBoundingClientRect().bottom + window.scrollY);
  }
  var broken = 0, imgs = document.images;
  for (var i = 0; i < imgs.length; ++i) if (!imgs[i].complete || imgs[i].naturalWidth === 0) ++broken;
  var legend = document.body.textContent.split("Hollow " + "faded").length - 1;  // split: not the text of this script
  var m = {clientWidth: d.clientWidth, innerHeight: window.innerHeight, scrollWidth: d.scrollWidth,
           scrollHeight: d.scrollHeight, summaryTop: Math.round(top), summaryBottom: Math.round(bottom),
           images: imgs.length, brokenImages: broken, legendNotes: legend};
  // Figure titles as rendered, every fold opened (a folded figure is not laid out): a title whose
  // box passes the viewBox of its figure is cut at the edge.
  var folds = document.getElementsByTagName("details");
  for (var k = 0; k < folds.length; ++k) folds[k].open = true;
  var titles = document.querySelectorAll("svg text.title"), cut = 0, overflow = 0;
  for (var t = 0; t < titles.length; ++t) {
    var b = titles[t].getBBox(), vb = titles[t].ownerSVGElement.viewBox.baseVal;
    var over = Math.max(vb.x - b.x, b.x + b.width - (vb.x + vb.width));
    if (over > 0) ++cut;
    overflow = Math.max(overflow, over);
  }
  m.titles = titles.length;
  m.titlesCut = cut;
  m.titleOverflowPx = Math.round(overflow * 10) / 10;
  var p = document.createElement("pre");
  p.id = "granlub-measure";
  p.textContent = "granlub-" + "measure " + JSON.stringify(m) + " end-" + "measure";  // not this line
  document.body.appendChild(p);
})();
</script>'
# The script goes in just before </body>, so it runs once the page is laid out.
awk -v s="$script" '{ if ($0 == "</body>") print s; print }' "$report/index.html" > "$page"
DBUS_SESSION_BUS_ADDRESS=disabled: chromium --headless --no-sandbox --disable-gpu --no-first-run --disable-extensions \
--user-data-dir="$work/profile" --window-size="$width,$height" --dump-dom \
  "file://$page" > "$work/dom.html" 2> "$work/chromium.log" || { cat "$work/chromium.log" >&2; exit 1; }
sed -n 's/.*granlub-measure \(.*\) end-measure.*/\1/p' "$work/dom.html" | head -n 1 | grep . ||
  { echo "measure_report.sh: no measurement in chromium's page (see its log below)" >&2; tail -n 5 "$work/chromium.log" >&2; exit 1; }
