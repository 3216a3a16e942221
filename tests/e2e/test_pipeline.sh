#!/usr/bin/env bash
# The whole verification on the bundled parts: run, the step-by-step pipeline through pipes,
# exactness of the grid against brute force, thread-count invariance, verdicts.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# Box offset by 0.1 on every face: errors from 0.1 (faces) to 0.1·√3 (corners).
expect_status 0 "offset box within ±0.2" "$NCVERIFY" -q run "$PARTS/box_offset.stl" \
  "$PARTS/box_nominal.stl" -d offset --tol 0.2 --step 1
check "run keeps every intermediate" test -s offset/box_offset.samples -a -s offset/box_nominal.grid \
  -a -s offset/box_offset.dist -a -s offset/box_offset.ply -a -s offset/box_offset.report.json \
  -a -s offset/box_offset.legend.svg -a -s offset/box_offset.histogram.svg
check "offset box: d_min is the face offset" /usr/bin/python3 -c "
import json; e = json.load(open('offset/box_offset.report.json'))['error']
assert abs(e['min']['value'] - 0.1) < 1e-5, e['min']  # float32 STL coordinates
assert abs(e['max']['value'] - 0.1 * 3 ** 0.5) < 1e-5, e['max']"
expect_status 1 "lowered top fails ±0.1 (exit 1)" "$NCVERIFY" -q run "$PARTS/box_top_lowered.stl" \
  "$PARTS/box_nominal.stl" -d lowered --tol 0.1 --step 1
# The top is gouged by 0.2 except within 0.1 of its rim, where the side walls are nearer:
# (100 - 0.2)(60 - 0.2) exactly; the 1 mm lattice resolves that rim only to about a step.
check "lowered top: the gouge is -0.2 and found as one region" /usr/bin/python3 -c "
import json; r = json.load(open('lowered/box_top_lowered.report.json'))
assert abs(r['error']['min']['value'] + 0.2) < 1e-5
assert r['tolerance']['verdict'] == 'fail' and r['region_counts']['gouge'] == 1
assert 99 * 59 - 1 < r['regions'][0]['area'] <= 99.8 * 59.8, r['regions'][0]['area']"

# Step by step through pipes gives the same distances as run.
"$NCVERIFY" -q grid-build "$PARTS/core_nominal.stl" -o core.grid
"$NCVERIFY" -q sample "$PARTS/core_finishing.stl" -o - --step 0.5% \
  | "$NCVERIFY" -q distance - core.grid -o - \
  | "$NCVERIFY" stats - --tol -0.05:0.1 --format json >piped.json
check "stats through a pipe exits 1 for the gouged part" test "${PIPESTATUS[2]}" -eq 1
"$NCVERIFY" -q sample "$PARTS/core_finishing.stl" -o fin.samples --step 0.5%
"$NCVERIFY" -q distance fin.samples core.grid -o fin.dist
"$NCVERIFY" stats fin.dist --tol -0.05:0.1 --format json >file.json
# The same report but for its traceability block (the command line and the date differ).
check "pipe and files agree" /usr/bin/python3 -c "
import json
a, b = (json.load(open(f)) for f in ('piped.json', 'file.json'))
assert a.pop('traceability')['inputs'] == b.pop('traceability')['inputs']
assert a == b"
"$NCVERIFY" -q colorize - -o piped.ply --tol -0.05:0.1 <fin.dist
check "colorize reads standard input" test -s piped.ply
"$NCVERIFY" stats --tol -0.05:0.1 --format json <fin.dist >omitted.json
check "stats without a file reads standard input, as its help says" /usr/bin/python3 -c "
import json
a, b = (json.load(open(f)) for f in ('omitted.json', 'file.json'))
assert a['error'] == b['error'] and a['tolerance'] == b['tolerance']"

# Exactness and determinism.
"$NCVERIFY" -q --threads 1 distance fin.samples core.grid -o one.dist
"$NCVERIFY" -q --threads 2 distance fin.samples core.grid -o two.dist
check "byte-identical with 1 and 2 threads" cmp -s one.dist two.dist
"$NCVERIFY" -q sample "$PARTS/core_finishing.stl" -o coarse.samples --step 2%
"$NCVERIFY" -q distance coarse.samples core.grid -o grid.dist
"$NCVERIFY" -q distance coarse.samples core.grid -o brute.dist --brute-force
"$NCVERIFY" inspect grid.dist --csv >grid.csv
"$NCVERIFY" inspect brute.dist --csv >brute.csv
check "grid search equals brute force, every sample, every digit" cmp -s grid.csv brute.csv

# The PLY header MeshLab and CloudCompare need.
head -c 1500 piped.ply | tr -d '\0' >ply_head.txt
for property in "format binary_little_endian 1.0" "property uchar red" "property float quality" \
  "property float scalar_signed_distance" "property int scalar_region" \
  "property list uchar int vertex_indices"; do
  check "PLY has '$property'" grep -q "$property" ply_head.txt
done
# -v says what a person debugging wants, beyond the default: the files read and written
# with their sizes and hashes, the topology behind the sign method, the cell size chosen and
# the search's work per query.
"$NCVERIFY" grid-build "$PARTS/core_nominal.stl" -o v.grid 2>default.log
"$NCVERIFY" -v grid-build "$PARTS/core_nominal.stl" -o v.grid 2>verbose.log
check "-v says more than the default" test "$(wc -l <verbose.log)" -gt "$(wc -l <default.log)"
check "-v: the topology behind the sign method" grep -q "debug: .*edges, 0 boundary, .* signed volume" verbose.log
check "-v: the cell size chosen" grep -q "debug: grid cell size .* requested" verbose.log
check "-v: the file written and its size" grep -q "debug: wrote v.grid ([0-9]* bytes)" verbose.log
"$NCVERIFY" -q sample "$PARTS/core_finishing.stl" -o v.samples --step 1%
"$NCVERIFY" -v distance v.samples v.grid -o v.dist 2>verbose.log
check "-v: the files read, with their hashes" \
  test "$(grep -c "debug: read v\.\(samples\|grid\): .* content hash [0-9a-f]\{16\}" verbose.log)" -eq 2
check "-v: the search's work per query" grep -q "debug: search: .* cells visited" verbose.log
"$NCVERIFY" -v stats v.dist 2>verbose.log >/dev/null
check "-v: the report's phases timed" grep -q "debug: statistics, histogram, percentiles and regions in" verbose.log
finish
