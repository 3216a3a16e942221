#!/usr/bin/env bash
# The HTML report and the SVG pictures in a real browser (headless chromium over the
# DevTools protocol, browser_check.mjs): the page of the bundled finishing part (both
# directions) loads with no error and no request, draws the part in the tolerance map's
# colours, lists and marks every region, reads the error under the pointer and flies to a
# chosen region; the legend and
# histogram of every bundled part keep each label inside the picture and clear of the others.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
CHECK="$NCV_SOURCE_DIR/tests/e2e/browser_check.mjs"

"$NCVERIFY" -q run "$PARTS/core_finishing.stl" "$PARTS/core_nominal.stl" -d fin --tol 0.15 \
  >/dev/null 2>&1
regions=$(/usr/bin/python3 -c "import json; c = json.load(open('fin/core_finishing.report.json'))['region_counts']; print(c['excess'] + c['gouge'])")
check "the finishing part has regions to show" test "$regions" -gt 20
# browser_page: the page checked once in a fresh headless chromium.
browser_page() {
  EXPECT_REGIONS=$regions EXPECT_VIEWS=2 EXPECT_VERDICT=FAIL EXPECT_EXCESS=1 EXPECT_GOUGE=1 \
    node "$CHECK" report fin/core_finishing.report.html page.png >browser.log 2>&1
}
# A second try only when the first failed, with its log kept: on a loaded machine chromium
# has been seen to miss a step's deadline once in a while; a page that is wrong fails both.
if browser_page || { cp browser.log browser.first.log && browser_page; }; then
  pass
  [ -s browser.first.log ] && echo "note: the first try failed: $(grep -v '^canvas' browser.first.log | head -5)"
else
  fail "the finishing part's page in chromium: $(grep -v '^canvas' browser.log | head -20)"
fi
check "the page's screenshot is written" test -s page.png

# Every bundled workpiece against its nominal, with the Makefile's tolerance and a zone
# whose limits sit close together: the pictures' labels must stay readable.
svgs=()
for part in "$PARTS"/*.stl; do
  name=$(basename "$part" .stl)
  case $name in *_nominal) continue ;; esac
  nominal="$PARTS/${name%%_*}_nominal.stl"
  for tol in 0.25 -0.02:0.01; do
    dir="svg_${name}_${tol}"
    "$NCVERIFY" -q run "$part" "$nominal" -d "$dir" --tol "$tol" --step 0.5% >/dev/null 2>&1
    check "$name at $tol: pictures written" test -s "$dir/$name.legend.svg" -a -s "$dir/$name.histogram.svg"
    svgs+=("$dir/$name.legend.svg" "$dir/$name.histogram.svg"
      "$dir/$name.reverse.legend.svg" "$dir/$name.reverse.histogram.svg")
  done
done
if node "$CHECK" svg "${svgs[@]}" >svg.log 2>&1; then
  pass
else
  fail "labels of the bundled parts' pictures: $(head -20 svg.log)"
fi
finish
