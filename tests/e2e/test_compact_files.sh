#!/usr/bin/env bash
# The compact intermediate files (docs/FORMATS.md): a samples file holds no points, a distance
# file names its samples file and holds 12 bytes a sample, a job split into shards gives the
# whole job's results to the bit, and `run --keep` leaves what was asked.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
parts=$NCV_SOURCE_DIR/samples/parts
cp "$parts/core_finishing.stl" w.stl
cp "$parts/core_nominal.stl" n.stl
size() { stat -c %s "$1"; }
# A JSON report without what differs from run to run (the date and the command line).
results() { jq -S 'del(.traceability.date, .traceability.command_line)' "$1"; }
same_results() { test "$(results "$1")" = "$(results "$2")"; }
# The same without the certified bounds, which each shard refines towards its own measured
# extremes (docs/CERTIFICATION.md "Verdict").
uncertified() {
  jq -S 'del(.traceability.date, .traceability.command_line, .certificate, .tolerance.reason,
    .error.max.upper_bound, .error.min.lower_bound)' "$1"
}
# The first report's certified intervals hold the second's measured extremes, and are at
# most the width asked wide.
bounds_hold() {
  /usr/bin/python3 -c '
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
c = a["certificate"]
w = c["width_asked"]
ok = c["max"]["bound"] >= b["certificate"]["max"]["measured"] and c["min"]["bound"] <= b["certificate"]["min"]["measured"]
ok = ok and (c["unresolved"] > 0 or (c["max_width"] <= w and c["min_width"] <= w))
sys.exit(0 if ok else 1)' "$1" "$2"
}
samples_of() { "$NCVERIFY" inspect "$1" --json | jq '.meta.records.count // .meta.sampling.samples'; }

# The whole job, file by file.
"$NCVERIFY" -q sample w.stl -o w.samples --step 0.05%
"$NCVERIFY" -q grid-build n.stl -o n.grid
"$NCVERIFY" -q distance w.samples n.grid -o w.dist
S=$(samples_of w.dist)
check "the job has many samples ($S)" test "$S" -gt 100000
check "the samples file is about its mesh's size ($(size w.samples) against $(size w.stl))" \
  test "$(size w.samples)" -lt "$(size w.stl)"
check "the distance file holds 12 bytes a sample ($(size w.dist) for $S)" \
  test "$(size w.dist)" -le $((12 * S + 4096))
"$NCVERIFY" stats w.dist --tol 0.15 --format json -o whole.json
"$NCVERIFY" -q colorize w.dist -o whole.ply --tol 0.15

# Three shards, each sampled, measured and read back together.
for k in 1 2 3; do
  "$NCVERIFY" -q sample w.stl -o "w$k.samples" --step 0.05% --shard "$k/3"
  "$NCVERIFY" -q distance "w$k.samples" n.grid -o "w$k.dist"
done
total=$(($(samples_of w1.dist) + $(samples_of w2.dist) + $(samples_of w3.dist)))
check "the shards split the samples ($total of $S)" test "$total" -eq "$S"
"$NCVERIFY" stats w3.dist w1.dist w2.dist --tol 0.15 --format json -o shards.json
check "stats of the shards equal the whole job's, to the bit, but for the certified bounds" \
  test "$(uncertified shards.json)" = "$(uncertified whole.json)"
check "the shards' certified bounds hold the whole job's measured extremes" bounds_hold shards.json whole.json
check "the whole job's certified bounds hold the shards' measured extremes" bounds_hold whole.json shards.json
"$NCVERIFY" -q colorize w1.dist w2.dist w3.dist -o shards.ply --tol 0.15
check "the coloured PLY of the shards equals the whole job's" cmp -s shards.ply whole.ply
expect_bad_input "a shard missing" "shard 2/3 of the forward direction is missing" "" \
  "$NCVERIFY" stats w1.dist w3.dist
expect_bad_input "a shard twice" "are both shard 1/3" "" "$NCVERIFY" stats w1.dist w1.dist w2.dist w3.dist
expect_bad_input "a shard with the whole job" "" "" "$NCVERIFY" stats w.dist w1.dist
for bad in 0/3 4/3 1/0 1/100001 x/3 1/3/3; do
  expect_bad_input "--shard $bad" "--shard" "bad.samples" \
    "$NCVERIFY" sample w.stl -o bad.samples --shard "$bad"
done

# The link: the samples file is found beside the distance file, or given with --samples; a
# samples file that is not the one measured is refused.
mkdir moved away
cp w.dist moved/
cd away
expect_bad_input "a distance file whose samples file is not where it says" "w.samples" "" \
  "$NCVERIFY" stats ../moved/w.dist
cd ..
"$NCVERIFY" stats moved/w.dist --samples w.samples --tol 0.15 --format json -o moved.json
check "--samples finds it" same_results moved.json whole.json
cp w.samples moved/
"$NCVERIFY" stats moved/w.dist --tol 0.15 --format json -o beside.json
check "a samples file moved along with it is found beside it" same_results beside.json whole.json
"$NCVERIFY" -q sample w.stl -o other.samples --step 0.06%
expect_bad_input "another samples file" "not the samples file" "" \
  "$NCVERIFY" stats w.dist --samples other.samples
cp other.samples moved/w.samples
expect_bad_input "a samples file replaced since" "not the samples file" "" \
  "$NCVERIFY" stats moved/w.dist

# Samples through a pipe: the distance file holds them and stands alone.
"$NCVERIFY" -q sample w.stl -o - --step 0.05% | "$NCVERIFY" -q distance - n.grid -o piped.dist
check "a piped job's distance file holds its samples" \
  test "$("$NCVERIFY" inspect piped.dist --json | jq -r .meta.samples_file.embedded)" = true
mv piped.dist alone.dist
"$NCVERIFY" stats alone.dist --tol 0.15 --format json -o piped.json
check "and reads alone, with the whole job's results" \
  test "$(jq -c .error piped.json)" = "$(jq -c .error whole.json)"

# run --keep: all keeps every step's file; reports only the reports and pictures; none
# writes nothing and prints the report. The verdict and report are the same.
"$NCVERIFY" -q run w.stl n.stl --tol 0.15 -d all >/dev/null
"$NCVERIFY" -q run w.stl n.stl --tol 0.15 -d reports --keep reports >/dev/null
"$NCVERIFY" -q run w.stl n.stl --tol 0.15 -d none --keep none --format json >none.json
check "--keep all: the intermediate files" test -s all/w.samples -a -s all/w.dist -a -s all/n.grid \
  -a -s all/w.reverse.dist
check "--keep reports: no intermediate file" test -z "$(ls reports | grep -E '\.(samples|grid|dist)$')"
check "--keep reports: the reports and pictures" test -s reports/w.report.json -a -s reports/w.ply
check "--keep reports: the same report" same_results reports/w.report.json all/w.report.json
check "--keep none: no folder" test ! -e none
check "--keep none: the report on standard output" \
  test "$(jq -c .error none.json)" = "$(jq -c .error all/w.report.json)"
finish
