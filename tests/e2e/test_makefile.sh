#!/usr/bin/env bash
# samples/Makefile: a parallel batch that keeps going past failing parts, ends with a summary,
# and redoes only what changed.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
mkdir parts
cp "$NCV_SOURCE_DIR"/samples/parts/box_*.stl parts/
cp "$NCV_SOURCE_DIR"/samples/parts/core_nominal.stl "$NCV_SOURCE_DIR"/samples/parts/core_finishing.stl parts/
batch() { make -C "$NCV_SOURCE_DIR/samples" NCVERIFY="$NCVERIFY" PARTS="$WORK/parts" OUT="$WORK/out" \
  STEP=1% TOL=0.25 "$@"; }

batch -j2 -k >make1.log 2>&1
check "a failing part makes the batch fail" test $? -ne 0
check "the failing part is named" grep -q "core_finishing: OUT OF TOLERANCE" make1.log
check "summary has a header and one row per part" test "$(wc -l <out/summary.csv)" -eq 6
check "the box parts pass" test "$(grep -c ',pass$' out/summary.csv)" -eq 4
check "the gouged core fails" grep -q '^"core_finishing".*,fail$' out/summary.csv
check "summary line counts the parts" grep -q "4 parts within tolerance 0.25, 1 out of it" make1.log
check "one grid per nominal" test "$(ls out/*.grid | wc -l)" -eq 2
check "every part is coloured" test "$(ls out/*.ply | wc -l)" -eq 5
check "every part has its HTML report" test "$(ls out/*.report.html | wc -l)" -eq 5
check "every part lists its regions" test "$(ls out/*.regions.csv | wc -l)" -eq 5

batch -j2 -k >make2.log 2>&1
check "nothing is redone when nothing changed" test "$(grep -c 'ncverify.* sample\|distance\|grid-build' make2.log)" -eq 0
touch parts/box_offset.stl
batch -j2 -k >make3.log 2>&1
check "a changed part is redone" grep -q "sample .*box_offset.stl" make3.log
check "and only that part" test "$(grep -c ' sample ' make3.log)" -eq 1
finish
