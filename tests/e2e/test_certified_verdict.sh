#!/usr/bin/env bash
# The certified verdict (docs/CERTIFICATION.md): pass only when proven between the samples,
# fail when a measured point is out, inconclusive (exit 3) otherwise, in every report.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# The top 0.2 low, at a step so coarse that the samples are the box's corners, all on the
# nominal's walls (0): refinement measures the lowered top between them.
expect_status 1 "a lowered top between the samples fails (exit 1)" "$NCVERIFY" -q run \
  "$PARTS/box_top_lowered.stl" "$PARTS/box_nominal.stl" --tol -0.05:0.1 --step 30% -d low
check "its samples alone read 0" test "$(json low/box_top_lowered.report.json "d['error']['min']['value']")" = 0.0
check "refinement measured the gouge" /usr/bin/python3 -c "import sys; sys.exit(not $(json low/box_top_lowered.report.json "d['certificate']['min']['measured']") <= -0.19)"
check "the certified min holds it" /usr/bin/python3 -c "import sys; sys.exit(not $(json low/box_top_lowered.report.json "d['error']['min']['lower_bound']") <= -0.2)"
check "the JSON verdict is fail" test "$(json low/box_top_lowered.report.json "d['verdict']")" = fail

# Scheme II leaves triangles unsampled: nothing bounds the error there, so never a pass.
expect_status 3 "scheme II is inconclusive at best (exit 3)" "$NCVERIFY" -q run \
  "$PARTS/core_finishing.stl" "$PARTS/core_nominal.stl" --scheme paper-ii --step 1% --tol 0.15 \
  --one-sided -d two
check "the JSON verdict is inconclusive" test "$(json two/core_finishing.report.json "d['verdict']")" = inconclusive
check "the reason names the unsampled triangles" grep -q "were not sampled (scheme paper-ii)" two/core_finishing.report.txt
check "the text report ends with the verdict" test "$(tail -n 1 two/core_finishing.report.txt)" = "verdict     INCONCLUSIVE"
check "the HTML banner says it" grep -q 'ncv-verdict ncv-inconclusive' two/core_finishing.report.html

# A part offset 0.1 outward everywhere: proven within a zone that holds it, whatever the step.
expect_status 0 "an offset box is proven within ±0.2 (exit 0)" "$NCVERIFY" -q run \
  "$PARTS/box_offset.stl" "$PARTS/box_nominal.stl" --tol 0.2 --step 30% -d offset
check "the certified max lies within the zone" /usr/bin/python3 -c "import sys; sys.exit(not $(json offset/box_offset.report.json "d['error']['max']['upper_bound']") <= 0.2)"
check "its interval is as narrow as asked" /usr/bin/python3 -c "import sys; sys.exit(not $(json offset/box_offset.report.json "d['certificate']['max_width']") <= 0.001)"
check "the summary row carries the bounds" /usr/bin/python3 -c "
import csv, subprocess, sys
out = subprocess.run(['$NCVERIFY', '-q', 'stats', 'offset/box_offset.dist', 'offset/box_offset.reverse.dist',
                      '--tol', '0.2', '--format', 'csv'], capture_output=True, text=True).stdout
rows = list(csv.DictReader(out.splitlines()))
sys.exit(not (rows[0]['verdict'] == 'pass' and float(rows[0]['max_upper_bound']) <= 0.2))"

# The same steps one by one give run's certificate: the width does not depend on --tol.
"$NCVERIFY" -q sample "$PARTS/box_offset.stl" --step 30% -o w.samples
"$NCVERIFY" -q grid-build "$PARTS/box_nominal.stl" -o n.grid
"$NCVERIFY" -q distance w.samples n.grid -o w.dist
check "distance's certificate is run's" test \
  "$("$NCVERIFY" inspect w.dist --json | jq -S .meta.certificate)" = \
  "$("$NCVERIFY" inspect offset/box_offset.dist --json | jq -S .meta.certificate)"

expect_bad_input "refinement beyond the memory budget is refused before measuring" \
  "give a smaller --certify-points" big.dist env NCV_MEMORY_BUDGET=400000000 "$NCVERIFY" distance \
  w.samples n.grid -o big.dist --certify-points 50000000
expect_bad_input "a zero width is refused" "not a positive length" zero.dist "$NCVERIFY" distance \
  w.samples n.grid -o zero.dist --certify 0
finish
