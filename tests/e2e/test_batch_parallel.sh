#!/usr/bin/env bash
# scripts/parallel/verify_parts.sh on this machine (GNU parallel's sshlogin ':'): the same
# summary.csv as samples/Makefile for the same parts and parameters, through the same tasks
# (scripts/batch/task.sh) that Slurm runs, and nothing redone the second time.
. "$(dirname "$0")/lib.sh"
command -v parallel >/dev/null || { echo "SKIP: GNU parallel is not installed (scripts/setup.sh installs it)"; exit 77; }
cd "$WORK"
mkdir parts
cp "$NCV_SOURCE_DIR"/samples/parts/box_{nominal,offset,top_raised,scallop}.stl parts/
cp parts/box_offset.stl parts/widget_a.stl
settings=(NCVERIFY="$NCVERIFY" STEP=3% TOL=0.15)

make -f "$NCV_SOURCE_DIR/samples/Makefile" PARTS="$WORK/parts" OUT="$WORK/make" "${settings[@]}" \
  -j2 -k >make.log 2>&1
"$NCV_SOURCE_DIR/scripts/parallel/verify_parts.sh" -S : parts results "${settings[@]}" >run1.log 2>&1
check "the batch fails: parts out of tolerance, one without nominal" test $? -ne 0
check "the same summary as the Makefile's, byte for byte" cmp make/summary.csv results/summary.csv
check "one task per grid and per part, in GNU parallel's job logs" \
  test "$(tail -n +2 results/batch/log/grids.txt.joblog | wc -l) $(tail -n +2 results/batch/log/parts.txt.joblog | wc -l)" = "1 3"
# box_scallop's scallops (0.03) are within the zone, proven so between the samples too.
check "the counts end its output" \
  grep -q "^summary $WORK/results/summary.csv: 1 pass, 2 fail, 1 error$" run1.log
"$NCV_SOURCE_DIR/scripts/parallel/verify_parts.sh" -S : parts results "${settings[@]}" >run2.log 2>&1
check "nothing is redone the second time" test "$(grep -c -- '-q ' run2.log)" -eq 0
check "and the summary is the same" cmp make/summary.csv results/summary.csv
"$NCV_SOURCE_DIR/scripts/parallel/verify_parts.sh" -S : parts sharded "${settings[@]}" SHARDS=3 \
  >sharded.log 2>&1
check "in three shards a part: the same summary, byte for byte but for the certified bounds" \
  same_but_bounds make/summary.csv sharded/summary.csv
check "a task per shard, and the reverse grids with the grids" \
  test "$(tail -n +2 sharded/batch/log/shards.txt.joblog | wc -l) $(tail -n +2 sharded/batch/log/grids.txt.joblog | wc -l)" = "9 4"
expect_status 2 "a VARIABLE=value that is not one refuses" \
  "$NCV_SOURCE_DIR/scripts/parallel/verify_parts.sh" -S : parts results2 tol=0.1
check "nothing left by the refused batch" test ! -e results2
finish
