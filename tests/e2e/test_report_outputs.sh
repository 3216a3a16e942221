#!/usr/bin/env bash
# What run, stats, colorize and report write for people and for further work: the PLY shows
# every sample (the worst point in the picture) with a region id per vertex, --coarse the
# vertices alone; every region and the histogram as CSV; units and rounded numbers in the
# text; the traceability block in the JSON; the report subcommand's HTML page.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
py() { /usr/bin/python3 -c "$@"; }

# Reads a binary PLY written by ncverify: vertex count, and per vertex the signed error and
# the region id.
cat >ply.py <<'PY'
import struct, sys
def read(path):
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    header = data[:end].decode().splitlines()
    vertices = int(next(l for l in header if l.startswith('element vertex')).split()[2])
    props = [l.split()[2] for l in header if l.startswith('property ') and 'list' not in l]
    assert props == ['x', 'y', 'z', 'red', 'green', 'blue', 'quality', 'scalar_signed_distance',
                     'scalar_region'], props
    record = struct.Struct('<3f3B2fi')
    rows = [record.unpack_from(data, end + k * record.size) for k in range(vertices)]
    return vertices, [r[6] for r in rows], [r[8] for r in rows]
PY

SOURCE_DATE_EPOCH=1767225600 "$NCVERIFY" -q run "$PARTS/core_finishing.stl" "$PARTS/core_nominal.stl" \
  -d fin --tol 0.15 --step 0.3% >fin.txt 2>fin.err
check "run fails the gouged part" test $? -eq 1
for f in report.html regions.csv histogram.csv report.json report.txt ply legend.svg histogram.svg; do
  check "run writes core_finishing.$f" test -s "fin/core_finishing.$f"
done

check "the PLY shows every sample, the worst point and the region of each" py "
import json, sys; sys.path.insert(0, '.'); import ply
r = json.load(open('fin/core_finishing.report.json'))
n, values, regions = ply.read('fin/core_finishing.ply')
assert n == r['sampling']['samples'], (n, r['sampling']['samples'])
import struct
f32 = lambda v: struct.unpack('<f', struct.pack('<f', v))[0]
assert max(values) == f32(r['error']['max']['value']) and min(values) == f32(r['error']['min']['value'])
total = r['region_counts']['excess'] + r['region_counts']['gouge']
assert set(regions) == set(range(total + 1)), (sorted(set(regions))[:5], total)
for v, k in zip(values, regions):
    assert (k == 0) == (-0.15 <= v <= 0.15), (v, k)
"
"$NCVERIFY" -q colorize fin/core_finishing.dist -o coarse.ply --coarse --tol 0.15
check "--coarse writes the workpiece's vertices alone" py "
import sys; sys.path.insert(0, '.'); import ply, struct
n, values, regions = ply.read('coarse.ply')
stl = open('$PARTS/core_finishing.stl', 'rb').read()
triangles = struct.unpack_from('<I', stl, 80)[0]
corners = {stl[84 + 50 * t + 12 + 12 * k: 84 + 50 * t + 24 + 12 * k] for t in range(triangles) for k in range(3)}
assert n == len(corners), (n, len(corners))
assert any(regions)"

check "every region is in the CSV, as many as the JSON counts, largest first" py "
import csv, json
r = json.load(open('fin/core_finishing.report.json'))
rows = list(csv.DictReader(open('fin/core_finishing.regions.csv')))
assert len(rows) == r['region_counts']['excess'] + r['region_counts']['gouge'] > 20, len(rows)
areas = [float(x['area']) for x in rows]
assert areas == sorted(areas, reverse=True)
assert float(rows[0]['extreme']) == r['regions'][0]['extreme']['value']"
check "the histogram CSV holds every bin and the whole area" py "
import csv, json
r = json.load(open('fin/core_finishing.report.json'))
rows = list(csv.DictReader(open('fin/core_finishing.histogram.csv')))
assert len(rows) == 64 + 2
assert abs(sum(float(x['area']) for x in rows) / r['workpiece']['area'] - 1) < 1e-9"
check "the JSON traces version, date, command line and inputs" py "
import json
t = json.load(open('fin/core_finishing.report.json'))['traceability']
assert t['date'] == '2026-01-01T00:00:00Z', t['date']
assert 'run' in t['command_line'] and '--tol 0.15' in t['command_line']
assert [i['role'] for i in t['inputs']] == ['workpiece', 'nominal']
assert t['inputs'][0]['path'].endswith('core_finishing.stl') and len(t['inputs'][0]['hash']) == 16"
check "the text report names the units and rounds" py "
import json
t = open('fin/core_finishing.report.txt').read()
d_max = json.load(open('fin/core_finishing.report.json'))['error']['max']['value']
assert 'max           %.4f ' % d_max in t, t
assert 'error in mm' in t and 'mm²' in t
import re
assert not re.search(r'\d\.\d{7,}', t), re.search(r'\d\.\d{7,}', t)
assert not re.search(r'e-\d\d', t)"

"$NCVERIFY" -q run "$PARTS/box_offset.stl" "$PARTS/box_nominal.stl" -d inch --tol 0.2 --step 1 \
  --units in >/dev/null
check "--units reaches the text, the pictures and the page" py "
t = open('inch/box_offset.report.txt').read()
assert ' in ' in t and 'in²' in t and ' mm' not in t, t
for f in ('legend.svg', 'histogram.svg'):
    s = open('inch/box_offset.' + f).read()
    assert 'signed error (in)' in s and '(mm)' not in s, f
h = open('inch/box_offset.report.html').read()
assert 'signed error (in)' in h and '\"units\":\"in\"' in h"

expect_status 1 "report writes the page of a distance file, exit 1 out of tolerance" \
  "$NCVERIFY" -q report fin/core_finishing.dist -o page.html --tol 0.15
check "the report subcommand's page lists every region" py "
import json
r = json.load(open('fin/core_finishing.report.json'))
h = open('page.html').read()
assert h.count('<tr data-region=') == r['region_counts']['excess'] + r['region_counts']['gouge']
assert 'FAIL' in h"
expect_status 0 "report without a tolerance" "$NCVERIFY" -q report fin/core_finishing.dist -o plain.html
check "a page without a tolerance has no verdict" grep -q "No verdict" plain.html
expect_bad_input "report of a missing file" "missing.dist" page2.html \
  "$NCVERIFY" report missing.dist -o page2.html
finish
