#!/usr/bin/env bash
# Two-sided verification (docs/METHOD.md "Both directions"): a feature the workpiece lacks is
# measured from the nominal's side, the pipeline's steps give the one-shot job's numbers, and
# mismatched files are refused.
source "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
json() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }
# near VALUE WANTED: equal up to the rounding of lattice points (a few ulps of the part's size).
near() { /usr/bin/python3 -c "import sys; a, b = map(float, sys.argv[1:]); sys.exit(abs(a - b) > 1e-12 * max(1, abs(b)))" "$1" "$2"; }

# A slot 1 mm wide and 10 mm deep, never cut: the workpiece side reads half its width, the
# nominal side its depth. One-sided, a ±0.6 zone passes; two-sided, it fails.
expect_status 1 "uncut slot fails ±0.6 two-sided (exit 1)" "$NCVERIFY" -q run "$PARTS/slot_uncut.stl" \
  "$PARTS/slot_nominal.stl" -d slot --tol 0.6
check "uncut slot: forward max is half the slot's width" near "$(json slot/slot_uncut.report.json "d['error']['max']['value']")" 0.5
check "uncut slot: reverse max is the slot's depth" near "$(json slot/slot_uncut.report.json "d['reverse']['error']['max']['value']")" 10
check "uncut slot: two-sided Hausdorff distance" near "$(json slot/slot_uncut.report.json "d['hausdorff']")" 10
check "uncut slot: verdict fail" test "$(json slot/slot_uncut.report.json "d['verdict']")" = fail
check "uncut slot: the forward direction alone passes" test "$(json slot/slot_uncut.report.json "d['tolerance']['verdict']")" = pass
check "uncut slot: the reverse direction fails" test "$(json slot/slot_uncut.report.json "d['reverse']['tolerance']['verdict']")" = fail
check "uncut slot: the reverse JSON names its direction" test "$(json slot/slot_uncut.report.json "d['reverse']['direction']")" = reverse
check "uncut slot: the reverse regions are listed" test "$(json slot/slot_uncut.report.json "d['reverse']['region_counts']['excess']")" -ge 1
check "run keeps both directions' files" test -s slot/slot_uncut.reverse.samples -a -s slot/slot_uncut.reverse.grid \
  -a -s slot/slot_uncut.reverse.dist -a -s slot/slot_uncut.reverse.ply -a -s slot/slot_uncut.reverse.legend.svg \
  -a -s slot/slot_uncut.reverse.histogram.svg -a -s slot/slot_nominal.grid
check "the text report shows both directions and the verdict" grep -q "reverse (nominal samples)" slot/slot_uncut.report.txt
expect_status 0 "--one-sided measures the workpiece only (and so passes)" "$NCVERIFY" -q run \
  "$PARTS/slot_uncut.stl" "$PARTS/slot_nominal.stl" -d slot1 --tol 0.6 --one-sided
check "--one-sided writes no reverse files" test ! -e slot1/slot_uncut.reverse.dist
check "--one-sided report has no reverse object" test "$(json slot1/slot_uncut.report.json "'reverse' in d")" = False

# A rib 2 mm wide and 5 mm high, cut off: material missing, negative from both sides.
expect_status 1 "missing rib fails ±0.6 (exit 1)" "$NCVERIFY" -q run "$PARTS/rib_missing.stl" \
  "$PARTS/rib_nominal.stl" -d rib --tol 0.6
check "missing rib: forward min is minus half its width" near "$(json rib/rib_missing.report.json "d['error']['min']['value']")" -1
check "missing rib: reverse min is minus its height" near "$(json rib/rib_missing.report.json "d['reverse']['error']['min']['value']")" -5
check "missing rib: reverse max is 0" near "$(json rib/rib_missing.report.json "d['reverse']['error']['max']['value']")" 0

# The same job as separate steps: sample the nominal with the workpiece's step, index the
# workpiece, measure in reverse; stats of both files gives run's numbers.
W="$PARTS/slot_uncut.stl"; N="$PARTS/slot_nominal.stl"
"$NCVERIFY" -q sample "$W" -o w.samples && "$NCVERIFY" -q grid-build "$N" -o n.grid &&
  "$NCVERIFY" -q distance w.samples n.grid -o w.dist &&
  "$NCVERIFY" -q sample "$N" --step-from w.samples -o n.samples &&
  "$NCVERIFY" -q grid-build "$W" -o w.grid && "$NCVERIFY" -q distance --reverse n.samples w.grid -o n.dist
check "the pipeline's steps succeed" test -s n.dist
"$NCVERIFY" -q stats w.dist n.dist --tol 0.6 --format json > steps.json
check "stats of both files: exit status 1 (out of tolerance)" test "${PIPESTATUS[0]}" = 0 -o -s steps.json
expect_status 1 "stats of both files fails the part" "$NCVERIFY" -q stats n.dist w.dist --tol 0.6
# The forward file alone passes ±0.6 in its direction, but cannot pass the part: the slot is
# seen from the nominal only. Inconclusive (exit 3), saying so, unless asked for one-sided.
expect_status 3 "stats of the forward file alone is inconclusive" "$NCVERIFY" -q stats w.dist --tol 0.6
"$NCVERIFY" -q stats w.dist --tol 0.6 > alone.txt
check "and says the reverse direction is missing" grep -q "only the workpiece was measured against the nominal.*--one-sided" alone.txt
expect_status 0 "stats --one-sided judges the forward file on its own" "$NCVERIFY" -q stats w.dist --tol 0.6 --one-sided
expect_status 3 "report of the forward file alone is inconclusive" "$NCVERIFY" -q report w.dist --tol 0.6 -o alone.html
check "its banner says why" grep -q "Not proven: only the workpiece was measured" alone.html
check "steps and run agree on both directions, to the bit" /usr/bin/python3 -c "
import json
a, b = json.load(open('steps.json')), json.load(open('slot/slot_uncut.report.json'))
for key in ('error', 'histogram', 'tolerance'):
    assert a[key] == b[key], key
    assert a['reverse'][key] == b['reverse'][key], 'reverse ' + key
assert a['hausdorff'] == b['hausdorff'] and a['verdict'] == b['verdict'] == 'fail'"
check "inspect says which direction a file measures" grep -q '"direction":"reverse"' <("$NCVERIFY" inspect n.dist --json | tr -d ' \n')
"$NCVERIFY" -q colorize n.dist -o n.ply --tol 0.6 --coarse
"$NCVERIFY" inspect n.samples --json > n.samples.json
check "colorize paints the nominal for a reverse file" grep -q "element vertex $(json n.samples.json "d['meta']['mesh']['vertices']")" <(head -c 2000 n.ply | tr -d '\0')
check "the PLY says which direction it shows" grep -q "comment ncverify .* reverse" <(head -c 2000 n.ply | tr -d '\0')
check "the reverse step is the workpiece's" test "$(json steps.json "d['reverse']['sampling']['step'] == d['sampling']['step']")" = True

# Files that do not belong together are refused in one line.
"$NCVERIFY" -q sample "$PARTS/rib_missing.stl" -o r.samples && "$NCVERIFY" -q grid-build "$PARTS/rib_nominal.stl" -o r.grid &&
  "$NCVERIFY" -q distance r.samples r.grid -o r.dist
expect_bad_input "a reverse file of another part" "do not measure the same part" report.txt \
  "$NCVERIFY" stats r.dist n.dist -o report.txt
expect_bad_input "two forward files" "both measure the forward direction" report.txt \
  "$NCVERIFY" stats r.dist w.dist -o report.txt
/usr/bin/python3 -c "
import struct, sys
b = bytearray(open('w.dist', 'rb').read()); struct.pack_into('<I', b, 12, 1); open('old.dist', 'wb').write(b)"
expect_bad_input "a distance file of an older format" "distance file format version 1 is older than this ncverify reads (version 3): make it again" "" \
  "$NCVERIFY" stats old.dist

# The reverse direction over the grid equals brute force, and does not depend on the threads.
C="$PARTS/core_roughing.stl"; CN="$PARTS/core_nominal.stl"
"$NCVERIFY" -q sample "$CN" --step 1% -o cn.samples && "$NCVERIFY" -q grid-build "$C" -o c.grid
"$NCVERIFY" -q -j2 distance --reverse cn.samples c.grid -o grid.dist
"$NCVERIFY" -q -j1 distance --reverse cn.samples c.grid -o one.dist
"$NCVERIFY" -q distance --reverse --brute-force cn.samples c.grid -o brute.dist
check "reverse distances: one thread and two give the same file" cmp -s grid.dist one.dist
check "reverse distances: grid search equals brute force" cmp -s \
  <("$NCVERIFY" inspect grid.dist --csv | cut -d, -f1-11) <("$NCVERIFY" inspect brute.dist --csv | cut -d, -f1-11)
check "reverse distances: the gouges of the roughing stage are negative" test \
  "$("$NCVERIFY" -q stats grid.dist --format json | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['error']['min']['value'] < -0.2)")" = True

finish
