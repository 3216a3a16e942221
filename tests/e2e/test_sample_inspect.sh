#!/usr/bin/env bash
# sample and inspect on real files, through pipes, and with the numpy reader of FORMATS.md.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
write_box_stl box.stl 10 20 5

check "sample writes a samples file" "$NCVERIFY" -q sample box.stl -o box.samples --step 1
check "inspect reads it" "$NCVERIFY" inspect box.samples -o header.txt
check "header names the kind" grep -q "SMPL (samples file), format version 3" header.txt
"$NCVERIFY" inspect box.samples --json >header.json
check "JSON header has the sample count" /usr/bin/python3 -c "
import json; h = json.load(open('header.json')); assert h['meta']['sampling']['samples'] > 100"
"$NCVERIFY" inspect box.samples --csv --head 3 >head.csv
check "CSV head has a header and 3 rows" test "$(wc -l <head.csv)" -eq 4
check "CSV columns" grep -q "^index,positions_x,positions_y,positions_z,owner,lattice_i,lattice_j$" head.csv

# Pipes: mesh from stdin, samples to stdout, inspect from stdin.
"$NCVERIFY" -q sample - -o - --step 1 <box.stl | "$NCVERIFY" inspect - --json >piped.json
check "stdin to stdout pipeline gives the same samples" /usr/bin/python3 -c "
import json
a = json.load(open('header.json'))['meta']; b = json.load(open('piped.json'))['meta']
assert a['sampling'] == b['sampling'] and a['mesh']['hash'] == b['mesh']['hash']"
check "logs go to stderr only" test -z "$("$NCVERIFY" sample box.stl -o quiet.samples --step 1 2>/dev/null)"

# The numpy snippet of docs/FORMATS.md reads the file, and its lattice rule regenerates the
# points and owners ncverify prints, bit for bit (the CSV's decimals round-trip).
/usr/bin/python3 "$NCV_SOURCE_DIR/docs/read_ncverify.py" box.samples >numpy.txt
check "numpy reader of FORMATS.md works" grep -q "^positions (.*) float64 (regenerated)" numpy.txt
"$NCVERIFY" inspect box.samples --csv >all.csv
check "the regenerated points are ncverify's" /usr/bin/python3 -c "
import sys; sys.path.insert(0, '$NCV_SOURCE_DIR/docs')
import numpy as np
from read_ncverify import read_ncverify, sample_points
positions, owner = sample_points(read_ncverify('box.samples')[3])
csv = np.loadtxt('all.csv', delimiter=',', skiprows=1)
assert len(csv) == len(positions) > 100
assert np.array_equal(csv[:, 1:4], positions) and np.array_equal(csv[:, 4], owner)"

# Scheme II on a mesh with only tiny triangles has fewer samples than scheme I.
"$NCVERIFY" -q sample box.stl -o i.samples --step 40 --scheme all
"$NCVERIFY" -q sample box.stl -o ii.samples --step 40 --scheme paper-ii
count() { "$NCVERIFY" inspect "$1" --json | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['meta']['sampling']['samples'])"; }
check "scheme I samples every vertex" test "$(count i.samples)" -eq 8
check "scheme II skips tiny triangles" test "$(count ii.samples)" -eq 0

expect_status 2 "binary output to a terminal is refused" script -qec "$NCVERIFY sample box.stl -o -" /dev/null
finish
