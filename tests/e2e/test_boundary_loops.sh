#!/usr/bin/env bash
# grid-build names the holes of an open nominal: how many boundary loops, each one's edges,
# length and where, in its log and in the grid file's header (inspect); a nominal OpenMesh
# cannot hold (a third face on an edge) says its loops are not traced; a closed one has none.
# An old grid file gets one clear line.
. "$(dirname "$0")/lib.sh"
cd "$WORK"

# The 4 x 2 x 1 box of lib.sh (triangles 2 and 3 its top, 0 and 1 its bottom) with faces
# taken away or added: its 50-byte facet records copied.
write_box_stl closed.stl 4 2 1
/usr/bin/python3 - <<'PY'
import struct
data = open('closed.stl', 'rb').read()
facets = [data[84 + 50 * i:134 + 50 * i] for i in range(12)]
fin = struct.pack('<12f', 0, 0, 0, 0, 0, 0, 4, 0, 0, 2, -3, 0) + b'\0\0'  # on edge {0, 1}
for name, chosen in (('lidless.stl', facets[:2] + facets[4:]),  # the top removed: a 4 x 2 hole
                     ('tube.stl', facets[4:]),                   # top and bottom: two holes
                     ('fin.stl', facets + [fin])):               # a third face on an edge
    open(name, 'wb').write(data[:80] + struct.pack('<I', len(chosen)) + b''.join(chosen))
PY

check "grid-build of a lidless box" "$NCVERIFY" grid-build lidless.stl -o lidless.grid 2>lidless.log
check "its log names one loop" grep -qF "lidless.stl: open: 1 boundary loop of 4 edges in all" lidless.log
check "with its edges, length and place" \
  grep -qF "loop 1: 4 edges, length 12, through (" lidless.log
check "and box" grep -qF "box (0, 0, 1) to (4, 2, 1)" lidless.log
"$NCVERIFY" inspect lidless.grid --json >lidless.json
check "inspect lists the loop" /usr/bin/python3 -c '
import json, sys
n = json.load(open("lidless.json"))["meta"]["nominal"]
loops = n["boundary_loops"]
assert n["topology_from"] == "openmesh", n["topology_from"]
assert loops["count"] == 1 and len(loops["listed"]) == 1, loops
loop = loops["listed"][0]
assert loop["edges"] == 4 and loop["length"] == 12, loop
assert loop["bbox_min"] == [0, 0, 1] and loop["bbox_max"] == [4, 2, 1], loop
'
check "inspect's text shows it" grep -qF '"boundary_loops":{"count":1' <("$NCVERIFY" inspect lidless.grid)

check "grid-build of a tube" "$NCVERIFY" grid-build tube.stl -o tube.grid 2>tube.log
check "two loops" grep -qF "tube.stl: open: 2 boundary loops of 8 edges in all" tube.log
check "each 12 long" test "$(grep -c "edges, length 12, through" tube.log)" -eq 2

check "grid-build of a closed box" "$NCVERIFY" grid-build closed.stl -o closed.grid 2>closed.log
check "no loop on a closed box" bash -c '! grep -q "boundary loop" closed.log'
check "closed box: no loop in the header" /usr/bin/python3 -c '
import json, subprocess, sys
n = json.loads(subprocess.check_output([sys.argv[1], "inspect", "closed.grid", "--json"]))["meta"]["nominal"]
assert n["boundary_loops"] == {"count": 0, "listed": []}, n["boundary_loops"]
' "$NCVERIFY"

check "grid-build of a finned box" "$NCVERIFY" grid-build fin.stl -o fin.grid 2>fin.log
check "a fin: loops not traced, winding number" \
  grep -qF "fin.stl: 2 boundary edges; loops not traced (OpenMesh cannot hold this mesh as it is)" fin.log
check "fin: from the arrays" grep -qF '"topology_from":"arrays"' <("$NCVERIFY" inspect fin.grid)

# The distances through the stored pseudonormals equal those of run, which builds them in
# process.
cp closed.stl part.stl
"$NCVERIFY" sample part.stl -o part.samples 2>/dev/null
"$NCVERIFY" distance part.samples lidless.grid -o part.dist 2>/dev/null
"$NCVERIFY" run part.stl lidless.stl --one-sided -d run -q >/dev/null 2>&1
check "a stored grid measures as run does" \
  cmp <("$NCVERIFY" inspect part.dist --csv) <("$NCVERIFY" inspect run/part.dist --csv)

# A grid file of format version 2 (the version field set back) gets one line naming it.
/usr/bin/python3 -c '
import struct
b = bytearray(open("lidless.grid", "rb").read()); struct.pack_into("<I", b, 12, 2)
open("old.grid", "wb").write(b)'
expect_bad_input "an old grid file" \
  "old.grid: grid file format version 2 is older than this ncverify reads (version 3): make it again with this ncverify" \
  "" "$NCVERIFY" distance part.samples old.grid -o part2.dist

finish
