#!/usr/bin/env bash
# samples/Makefile: a parallel batch that goes past failing parts, always writes summary.csv
# (CSV only: a header and one row per workpiece), and redoes exactly what a changed input,
# option or binary affects, so that no verdict is ever stale.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
mkdir parts
cp "$NCV_SOURCE_DIR"/samples/parts/box_{nominal,offset,top_raised,top_lowered}.stl parts/
cp "$NCV_SOURCE_DIR"/samples/parts/{core_nominal,core_finishing,slot_nominal,slot_uncut}.stl parts/
batch() {
  make -f "$NCV_SOURCE_DIR/samples/Makefile" NCVERIFY="$NCVERIFY" PARTS="$WORK/parts" \
    OUT="$WORK/out" STEP=1% "$@"
}
# ran COMMAND LOG: how many times the batch in LOG ran `ncverify COMMAND`.
ran() { grep -c -- "-q $1 " "$2"; }
# verdict PART: the part's verdict in the summary.
verdict() {
  python3 -c 'import csv, sys
rows = {r["part"]: r for r in csv.DictReader(open("out/summary.csv"))}
print(rows[sys.argv[1]]["verdict"] if sys.argv[1] in rows else "missing")' "$1"
}
# redone "description" LOG sample grid-build distance stats colorize: the commands each ran.
redone() {
  local what=$1 log=$2 got=""
  shift 2
  for command in sample grid-build distance stats colorize; do got+="$(ran $command "$log") "; done
  if [ "$got" = "$* " ]; then pass; else fail "$what: ran $got, wanted $*"; fi
}

# Box tops 0.2 mm out: within ±0.5, out of ±0.1. The core's finishing part is out of both,
# and so is the uncut slot, 10 mm deep, which only the reverse direction sees. Both
# directions, as `run` measures them: per part 2 samples, a grid of the workpiece (beside one
# per nominal), 2 distance files, a row and 2 PLYs.
batch -j2 -k TOL=0.5 >run1.log 2>&1
check "a part out of tolerance makes the batch fail" test $? -ne 0
redone "the first batch runs everything, one grid per nominal" run1.log 10 8 10 5 10
check "the raised box top passes ±0.5" test "$(verdict box_top_raised)" = pass
check "the lowered box top passes ±0.5" test "$(verdict box_top_lowered)" = pass
check "the gouged core fails" test "$(verdict core_finishing)" = fail
check "the uncut slot fails" test "$(verdict slot_uncut)" = fail
check "the failing parts are named" test "$(grep -c "^\(core_finishing\|slot_uncut\): fail$" run1.log)" -eq 2
check "the counts go to standard error" grep -q "^summary $WORK/out/summary.csv: 3 pass, 2 fail$" run1.log
check "every workpiece and nominal is coloured" test "$(ls out/*.ply | wc -l)" -eq 10
check "every part has its HTML report" test "$(ls out/*.report.html | wc -l)" -eq 5
check "every part lists its regions" test "$(ls out/*.regions.csv | wc -l)" -eq 5

# summary.csv is plain CSV: the header, then one row per workpiece sorted by name, every row
# as wide as the header; nothing after the last part's row.
check "summary.csv is a header and one row per part, sorted, nothing else" python3 -c '
import csv
rows = list(csv.reader(open("out/summary.csv")))
assert rows[0][0] == "part" and rows[0][-2:] == ["verdict", "message"], rows[0]
assert [r[0] for r in rows[1:]] == ["box_offset", "box_top_lowered", "box_top_raised", "core_finishing", "slot_uncut"]
assert all(len(r) == len(rows[0]) for r in rows)'

batch -j2 -k TOL=0.5 >run2.log 2>&1
redone "nothing is redone when nothing changed" run2.log 0 0 0 0 0

# Tolerance: only stats and colorize run again, and the verdicts follow (both ways).
batch -j2 -k TOL=0.1 >run3.log 2>&1
redone "a new TOL redoes stats and colorize only" run3.log 0 0 0 5 10
check "±0.1 fails the raised box top" test "$(verdict box_top_raised)" = fail
check "±0.1 fails the lowered box top" test "$(verdict box_top_lowered)" = fail
check "the summary's rows carry the new tolerance" \
  test "$(grep -c ',-0.1,0.1,' out/summary.csv)" -eq 5
batch -j2 -k TOL=0.5 >run4.log 2>&1
check "back to ±0.5 passes them again" test "$(verdict box_top_raised)" = pass
check "and the lowered one" test "$(verdict box_top_lowered)" = pass

# Each option redoes its step and what follows it, nothing before it.
batch -j2 -k TOL=0.5 STEP=2% >run5.log 2>&1
redone "a new STEP redoes the samples and what follows, not the grids" run5.log 10 0 10 5 10
batch -j2 -k TOL=0.5 STEP=2% CELL=3 >run6.log 2>&1
redone "a new CELL redoes the grids and what follows" run6.log 0 8 10 5 10
batch -j2 -k TOL=0.5 STEP=2% CELL=3 SIGN=winding >run7.log 2>&1
redone "a new SIGN redoes the distances and what follows" run7.log 0 0 10 5 10
batch -j2 -k TOL=0.5 STEP=2% CELL=3 SIGN=winding BINS=16 >run8.log 2>&1
redone "a new BINS redoes stats only" run8.log 0 0 0 5 0
cp "$NCVERIFY" ncverify-copy
printf '\0' >>ncverify-copy
batch -j2 -k TOL=0.5 STEP=2% CELL=3 SIGN=winding BINS=16 NCVERIFY="$WORK/ncverify-copy" \
  >run9.log 2>&1
redone "another ncverify binary redoes everything" run9.log 10 8 10 5 10
settings=(TOL=0.5 STEP=2% CELL=3 SIGN=winding BINS=16 NCVERIFY="$WORK/ncverify-copy")

touch parts/box_offset.stl
batch -j2 -k "${settings[@]}" >run10.log 2>&1
redone "a changed workpiece is redone, and only it (and its grid)" run10.log 2 1 2 1 2

# One direction, as `run --one-sided`: the rows change (stats only), and the uncut slot passes
# ±0.6, which is why both directions are the default.
batch -j2 -k "${settings[@]}" SIDES=one >run10b.log 2>&1
redone "SIDES=one redoes stats only" run10b.log 0 0 0 5 0
batch -j2 -k TOL=0.6 "${settings[@]:1}" SIDES=one >run10c.log 2>&1
check "one-sided, the uncut slot passes ±0.6" test "$(verdict slot_uncut)" = pass
batch -j2 -k TOL=0.6 "${settings[@]:1}" >run10d.log 2>&1
check "two-sided, it fails" test "$(verdict slot_uncut)" = fail
redone "back to SIDES=two redoes stats, and the nominals' PLYs of the old TOL" run10d.log 0 0 0 5 5

# A part's row is the row `run` gives for it, byte for byte (both directions).
"$NCVERIFY" -q run "$WORK/parts/slot_uncut.stl" "$WORK/parts/slot_nominal.stl" -d run-slot \
  --step 2% --cell 3 --sign winding --bins 16 --tol 0.6 --format csv >run-slot.csv
check "the batch's row is run's" test "$(grep '^"slot_uncut"' out/summary.csv)" = \
  "$(tail -n 1 run-slot.csv),"
step_of() { "$NCVERIFY" inspect "$1" --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["meta"]["sampling"]["step"])'; }
check "the nominal is sampled at its workpiece's absolute step (sample --step-from)" \
  test "$(step_of out/core_finishing.reverse.samples)" = "$(step_of out/core_finishing.samples)"
batch TOL=0.6 "${settings[@]:1}" SIDES=both >sides.log 2>&1
check "SIDES other than one or two is refused (exit 2), in one line" \
  test "$? $(wc -l <sides.log)" = "2 1" -a -n "$(grep 'SIDES=both' sides.log)"

# A workpiece without its nominal and one that cannot be read: error rows, the rest goes on.
cp parts/box_offset.stl parts/widget_a.stl
printf 'solid x\n' >parts/box_bad.stl
batch -j2 -k "${settings[@]}" >run11.log 2>&1
check "the batch with a part without nominal fails" test $? -ne 0
check "a part without nominal is an error row naming the missing file" grep -q \
  "^\"widget_a\",.*,error,\"no nominal: $WORK/parts/widget_nominal.stl does not exist\"$" out/summary.csv
check "a part that cannot be read is an error row quoting ncverify" grep -q \
  '^"box_bad",.*,error,"sample: error: .*box_bad.stl: ASCII STL' out/summary.csv
check "the other parts still have their rows" \
  test "$(grep -c ',\(pass\|fail\),$' out/summary.csv)" -eq 5
check "the counts include the errors" \
  grep -q "^summary $WORK/out/summary.csv: 3 pass, 2 fail, 2 error$" run11.log

rm parts/box_bad.stl parts/widget_a.stl

# A batch stopped halfway (here: one part made with a new TOL, then the summary alone): the
# parts not redone are error rows, not their stale rows of the last batch.
batch TOL=0.4 "${settings[@]:1}" part-box_offset >run12.log 2>&1
batch TOL=0.4 "${settings[@]:1}" summary >run13.log 2>&1
check "the part made with the new TOL has its row" grep -q '^"box_offset",.*,-0.4,0.4,' out/summary.csv
check "a part not redone for the new TOL is an error row, not its old verdict" grep -q \
  '^"box_top_raised",.*,error,"no result up to date' out/summary.csv
check "no row claims the old tolerance" test "$(grep -c ',-0.5,0.5,' out/summary.csv)" -eq 0
batch -j2 TOL=0.4 "${settings[@]:1}" >run14.log 2>&1
check "the next batch completes them" test "$(grep -c ',-0.4,0.4,' out/summary.csv)" -eq 5

# make's own flags do not confuse the summary: -B redoes everything, -n changes nothing.
batch -B -j2 "${settings[@]}" >run15.log 2>&1
check "-B: every row counts" grep -q ": 3 pass, 2 fail$" run15.log
touch -d '1 hour ago' out/*
batch -n TOL=0.3 "${settings[@]:1}" >run16.log 2>&1
check "-n makes no result" test -z "$(find out -maxdepth 1 -type f -newer parts/box_nominal.stl)"

# SHARDS: each part measured in pieces gives the same rows, to the bit; a new SHARDS redoes
# the samples, as any sampling option does, and a bad one is refused before any work.
batch -j2 "${settings[@]}" >run17.log 2>&1
cp out/summary.csv whole.csv
batch -j2 "${settings[@]}" SHARDS=3 >run18.log 2>&1
check "three shards a part: the same summary, byte for byte but for the certified bounds" \
  same_but_bounds whole.csv out/summary.csv
check "each part in three shards, both directions" test "$(ls out/*.s[123].dist | wc -l)" -eq 30
check "a new SHARDS redoes the samples" test "$(ran sample run18.log)" -eq 30
batch SHARDS=0 >run19.log 2>&1
check "SHARDS=0 is refused" grep -q "SHARDS=0: give a whole number from 1 to 1000" run19.log
finish
