#!/usr/bin/env bash
# Every bad input, through the real binary: exit 2, exactly one line on stderr naming the
# file and the problem, and no output (nor temporary) left behind. docs/ROBUSTNESS.md lists
# the cases and what ncverify does with each.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
write_box_stl box.stl 10 10 10
"$NCVERIFY" -q sample box.stl -o good.samples --step 2
"$NCVERIFY" -q grid-build box.stl -o good.grid
"$NCVERIFY" -q distance good.samples good.grid -o good.dist 2>/dev/null  # warns: box vs itself

# Peak resident memory (kB) of a command, which must fail: no count a file states may make
# ncverify allocate for it.
peak_kb() {
  /usr/bin/time -f "%M" -o mem.txt "$@" >/dev/null 2>&1
  tail -1 mem.txt
}
# limited COMMAND...: runs with memory capped at 2 GB (address space, or each allocation
# under AddressSanitizer, whose shadow takes terabytes of address space), so that memory
# reserved for a count a file claims fails loudly even if it is never touched.
limited() {
  if ldd "$NCVERIFY" | grep -q libasan; then
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}max_allocation_size_mb=2048" "$@"
  else
    (ulimit -v 2097152 && exec "$@")
  fi
}
# small_peak COMMAND...: the command's peak stays within 32 MB of the binary's own footprint
# (a run that fails at once; the sanitizer runtimes alone take some 60 MB).
head -c 84 /dev/zero >baseline.stl
baseline_kb=$(peak_kb "$NCVERIFY" sample baseline.stl -o baseline.out)
small_peak() { test $(($(peak_kb "$@") - baseline_kb)) -lt 32768; }

# ---------------------------------------------------------------- meshes
: >empty.stl
expect_bad_input "empty file" "empty.stl: empty file" out1 "$NCVERIFY" sample empty.stl -o out1
expect_bad_input "empty nominal" "empty.stl: empty file" out1 "$NCVERIFY" grid-build empty.stl -o out1
head -c 84 /dev/zero >zero.stl
expect_bad_input "zero triangles" "zero.stl: binary STL with no triangles" out2 \
  "$NCVERIFY" sample zero.stl -o out2
head -c 400 box.stl >cut.stl
expect_bad_input "binary STL cut mid-triangle" "cut.stl: not a valid binary STL: its header claims 12 triangles" \
  out3 "$NCVERIFY" sample cut.stl -o out3
/usr/bin/python3 -c "
import struct; open('huge.stl','wb').write(b'x'*80 + struct.pack('<I', 2000000000) + b'\1'*940)"
expect_bad_input "header claims 2e9 triangles in 1 kB" "huge.stl: not a valid binary STL: its header claims 2000000000 triangles" \
  out4 limited "$NCVERIFY" sample huge.stl -o out4
check "no huge allocation for 2e9 claimed triangles" small_peak "$NCVERIFY" sample huge.stl -o out4
printf 'solid part\ngarbage garbage\n' >garbage.stl
expect_bad_input "ASCII STL with garbage" "garbage.stl: ASCII STL, line 2: expected 'facet' or 'endsolid', found 'garbage'" \
  out5 "$NCVERIFY" sample garbage.stl -o out5
head -c 3000 /dev/urandom >random.stl
expect_bad_input "random bytes" "random.stl:" out6 "$NCVERIFY" sample random.stl -o out6
printf '\x89PNG\r\n\x1a\n' >image.stl
head -c 500 /dev/urandom >>image.stl
expect_bad_input "PNG renamed .stl" "image.stl: is a PNG image, not a mesh" out7 "$NCVERIFY" sample image.stl -o out7
for value in nan inf; do
  /usr/bin/python3 - "$value" <<'PY'
import struct, sys
with open(sys.argv[1] + '.stl', 'wb') as f:
    f.write(b'\0' * 80 + struct.pack('<I', 1))
    f.write(struct.pack('<12f', 0, 0, 0, 0, 0, 0, 1, float(sys.argv[1]), 0, 0, 1, 0) + b'\0\0')
PY
  expect_bad_input "$value coordinate (binary STL)" "$value.stl: triangle 0 has a NaN or infinite coordinate" \
    out8 "$NCVERIFY" sample "$value.stl" -o out8
done
printf 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 -inf 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n' >inf_ascii.stl
expect_bad_input "Inf coordinate (ASCII STL)" "inf_ascii.stl: triangle 0 has a NaN or infinite coordinate" \
  out8 "$NCVERIFY" grid-build inf_ascii.stl -o out8
expect_bad_input "missing file" "nothere.stl: No such file" out9 "$NCVERIFY" sample nothere.stl -o out9
mkdir folder.stl
expect_bad_input "a folder as input" "folder.stl: is a directory" out9 "$NCVERIFY" sample folder.stl -o out9
expect_bad_input "intermediate given as a mesh" "good.samples: is an ncverify intermediate file, not a mesh" \
  out14 "$NCVERIFY" sample good.samples -o out14

# PLY, OFF and OBJ: structure, counts and indices (OpenMesh used to hang or misread these).
ply_head='ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\n'
printf "${ply_head}end_headEr\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n" >misspelt.ply
expect_bad_input "PLY header without end_header" "misspelt.ply: PLY, line 9: unexpected header line starting with 'end_headEr'" \
  out10 timeout 20 "$NCVERIFY" sample misspelt.ply -o out10
printf "${ply_head}end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n" >badindex.ply
expect_bad_input "PLY face naming a missing vertex" "badindex.ply: PLY: a face refers to vertex 7, but there are 3 vertices" \
  out10 "$NCVERIFY" sample badindex.ply -o out10
printf 'ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\nproperty double x\nproperty double y\nproperty double z\nend_header\n' >claims.ply
head -c 900 /dev/zero >>claims.ply
expect_bad_input "binary PLY claiming 4e9 vertices in 1 kB" "claims.ply: PLY, at byte 1023: the data ends early (truncated?)" \
  out10 limited "$NCVERIFY" sample claims.ply -o out10
check "no huge allocation for 4e9 claimed PLY vertices" small_peak "$NCVERIFY" sample claims.ply -o out10
printf 'OFF\n2000000000 3000000000 0\n0 0 0\n' >claims.off
expect_bad_input "OFF claiming 2e9 vertices" "claims.off: OFF, line 3: the file ends before the last vertex (truncated?)" \
  out10 limited timeout 20 "$NCVERIFY" sample claims.off -o out10
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' >badindex.obj
expect_bad_input "OBJ face naming a missing vertex" "badindex.obj: OBJ: a face refers to vertex 3, but there are 3 vertices" \
  out10 "$NCVERIFY" sample badindex.obj -o out10

# ---------------------------------------------------------------- options
expect_bad_input "step zero" "--step: invalid step '0'" out10 "$NCVERIFY" sample box.stl -o out10 --step 0
expect_bad_input "negative step" "--step: invalid step '-1'" out11 "$NCVERIFY" sample box.stl -o out11 --step=-1
expect_bad_input "NaN step" "--step: invalid step 'nan'" out12 "$NCVERIFY" sample box.stl -o out12 --step nan
expect_bad_input "step that is not a number" "--step: invalid step '0.1mm'" out12 "$NCVERIFY" sample box.stl -o out12 --step 0.1mm
expect_bad_input "step beyond double" "--step: invalid step '1e999%'" out12 "$NCVERIFY" sample box.stl -o out12 --step 1e999%
expect_bad_input "absurd sample count" "use a larger step, or --force" out13 \
  "$NCVERIFY" sample box.stl -o out13 --step 1e-6
expect_bad_input "tolerance that does not parse" "--tol: tolerance 'abc': 'abc' is not a number" "" \
  "$NCVERIFY" stats good.dist --tol abc
expect_bad_input "tolerance with an empty limit" "--tol: tolerance '0.1:': '' is not a number" "" \
  "$NCVERIFY" stats good.dist --tol 0.1:
expect_bad_input "tolerance upside down" "--tol: tolerance '1:-1': the lower limit exceeds the upper limit" "" \
  "$NCVERIFY" stats good.dist --tol 1:-1
expect_bad_input "run refuses a bad tolerance before any work" "--tol: tolerance '0,1': unexpected ',1' after the number" \
  runout "$NCVERIFY" run box.stl box.stl -d runout --tol 0,1
expect_bad_input "colour range that does not parse" "--range: range 'wide': 'wide' is not a number" out15 \
  "$NCVERIFY" colorize good.dist -o out15 --range wide
expect_bad_input "colour range of no width" "--range: range '1:1' has no width" out15 \
  "$NCVERIFY" colorize good.dist -o out15 --range 1:1
expect_bad_input "colour range upside down" "--range: range '1:-1': the lower limit exceeds the upper limit" out15 \
  "$NCVERIFY" colorize good.dist -o out15 --range 1:-1
expect_bad_input "histogram range of no width" "--histogram-range: range '0' has no width" "" \
  "$NCVERIFY" stats good.dist --histogram-range 0
expect_bad_input "negative record count" "--head: '-5' is not a whole number from 0 to" out15 \
  "$NCVERIFY" inspect good.dist --csv --head -5 -o out15
expect_bad_input "cell size zero" "--cell: '0' is not a positive length" out15 \
  "$NCVERIFY" grid-build box.stl -o out15 --cell 0
expect_bad_input "unknown option" "unknown option '--stepp' for sample; did you mean '--step'?" out15 \
  "$NCVERIFY" sample box.stl -o out15 --stepp
expect_bad_input "unknown command" "unknown command 'stat'; did you mean 'stats'?" "" \
  "$NCVERIFY" stat good.dist
expect_bad_input "unknown command after a global option" "unknown command 'frobnicate'" "" \
  "$NCVERIFY" -j 2 frobnicate
# run checks its inputs and output paths before it creates anything, and a run that fails
# later takes back what it wrote: no file, no empty folder.
expect_bad_input "run with a missing workpiece" "missing.stl: No such file or directory" runout \
  "$NCVERIFY" run missing.stl box.stl -d runout/deeper
write_box_stl taller.stl 10 10 10.5
expect_bad_input "run with a legend path that cannot be written" "nowhere/l.svg: cannot write" runout \
  "$NCVERIFY" run taller.stl box.stl -d runout --legend nowhere/l.svg
expect_bad_input "run into a folder under a file" "cannot write: box.stl is not a folder" "" \
  "$NCVERIFY" run taller.stl box.stl -d box.stl/out
expect_bad_input "run that fails at its last output" "/dev/full: cannot write" runout \
  "$NCVERIFY" -q run taller.stl box.stl -d runout/deeper --timings /dev/full
expect_bad_input "an option without its value" "--tol needs a value" runout \
  "$NCVERIFY" run box.stl box.stl -d runout --tol
expect_bad_input "histogram bins beyond the range" "--bins: '100000000' is not a whole number from 1 to 100000" "" \
  "$NCVERIFY" stats good.dist --bins 100000000
expect_bad_input "zero histogram bins" "--bins: '0' is not a whole number from 1 to 100000" "" \
  "$NCVERIFY" stats good.dist --bins 0
expect_bad_input "regions beyond the range" "--regions: '-1' is not a whole number from 0 to 1000000" "" \
  "$NCVERIFY" stats good.dist --regions -1
expect_bad_input "threads that are not a number" "--threads: 'abc' is not a whole number from 0 to 4096" "" \
  "$NCVERIFY" -j abc stats good.dist
expect_bad_input "histogram range upside down, named a range" "--histogram-range: range '1:0': the lower limit exceeds the upper limit" "" \
  "$NCVERIFY" stats good.dist --histogram-range 1:0
expect_bad_input "histogram range wider than a double" "is wider than a double can hold" "" \
  "$NCVERIFY" stats good.dist --histogram-range -1e308:1e308
expect_bad_input "a step beyond NCV_MEMORY_BUDGET" "would need about 3.2 MB of memory (the budget is 1.0 MB)" out15 \
  env NCV_MEMORY_BUDGET=1000000 "$NCVERIFY" sample box.stl -o out15 --step 1%
expect_bad_input "a step beyond 80 % of a Slurm job's --mem" "(the budget is 838.9 kB)" out15 \
  env SLURM_MEM_PER_NODE=1 "$NCVERIFY" sample box.stl -o out15 --step 1%
expect_bad_input "a step beyond the diagonal" "invalid step '200%': at most 100% of the bounding-box diagonal" out15 \
  "$NCVERIFY" sample box.stl -o out15 --step 200%
expect_bad_input "a step so small the count saturates" "(more than 1.8e19 samples)" out15 \
  "$NCVERIFY" sample box.stl -o out15 --step 1e-300

# ---------------------------------------------------------------- intermediate files
size=$(stat -c %s good.samples)
head -c $((size / 2)) good.samples >truncated.samples
expect_bad_input "truncated samples file" "truncated.samples: truncated: the header says $size bytes" "" \
  "$NCVERIFY" inspect truncated.samples
cp good.samples flipped.samples
printf '\x55' | dd of=flipped.samples bs=1 seek=$((size - 100)) conv=notrunc status=none
expect_bad_input "flipped byte (samples)" "flipped.samples: content hash mismatch" out16 \
  "$NCVERIFY" distance flipped.samples good.grid -o out16
cp good.grid flipped.grid
printf '\x01' | dd of=flipped.grid bs=1 seek=200 conv=notrunc status=none
expect_bad_input "flipped byte (grid)" "flipped.grid: content hash mismatch" out16 \
  "$NCVERIFY" distance good.samples flipped.grid -o out16
expect_bad_input "a mesh is not an intermediate file" "box.stl: not an ncverify file" "" "$NCVERIFY" inspect box.stl
expect_bad_input "grid given as the samples" "good.grid: is a grid file, expected a samples file" out16 \
  "$NCVERIFY" distance good.grid good.grid -o out16
expect_bad_input "samples given as the distances" "good.samples: is a samples file, expected a distance file" "" \
  "$NCVERIFY" stats good.samples
cp good.samples newer.samples
printf '\x09' | dd of=newer.samples bs=1 seek=12 conv=notrunc status=none
expect_bad_input "newer format version" "newer.samples: samples file format version 9 is newer than this ncverify reads" "" \
  "$NCVERIFY" inspect newer.samples

# Files that cannot belong together: the workpiece 5 km from a 10 mm nominal.
/usr/bin/python3 - <<'PY'
import struct
data = open('box.stl', 'rb').read()
out = bytearray(data[:84])
for t in range(12):
    facet = data[84 + 50 * t:134 + 50 * t]
    v = list(struct.unpack('<12f', facet[:48]))
    for k in range(3):
        v[3 + 3 * k] += 5000
    out += struct.pack('<12f', *v) + facet[48:]
open('far.stl', 'wb').write(out)
PY
"$NCVERIFY" -q grid-build far.stl -o far.grid
expect_bad_input "samples and grid of different parts" "box.stl: the workpiece lies 4990 from the nominal far.stl, farther than the size of either part" \
  out17 "$NCVERIFY" distance good.samples far.grid -o out17
expect_bad_input "run with parts that do not belong together" "they do not belong together" "" \
  "$NCVERIFY" run box.stl far.stl -d apart --step 2
check "run leaves no distance file for parts that do not belong together" test ! -e apart/box.dist

# ---------------------------------------------------------------- pipes
expect_bad_input "stdin closed at once" "standard input: empty file" out18 \
  "$NCVERIFY" sample - -o out18 </dev/null
head -c 500 box.stl | expect_bad_input "stdin cut short (mesh)" "standard input: not a valid binary STL: its header claims 12 triangles" \
  out18 "$NCVERIFY" sample - -o out18
head -c 1000 good.samples | expect_bad_input "stdin cut short (samples)" "standard input: truncated" out18 \
  "$NCVERIFY" distance - good.grid -o out18
"$NCVERIFY" sample empty.stl -o - 2>/dev/null | expect_bad_input "producer failed upstream" \
  "standard input: empty file, expected an ncverify samples file" out18 "$NCVERIFY" distance - good.grid -o out18
# A reader that stops early: ncverify ends quietly by SIGPIPE, as Unix tools do (the CSV of
# 160 k samples is far more than a pipe buffers).
"$NCVERIFY" -q sample box.stl -o fine.samples --step 0.05
"$NCVERIFY" inspect --csv fine.samples 2>pipe.err | head -1 >/dev/null
status=${PIPESTATUS[0]}
check "stdout closed early: killed quietly by SIGPIPE (status 141)" test "$status" -eq 141 -a ! -s pipe.err

# ---------------------------------------------------------------- outputs
expect_bad_input "output folder missing" "nowhere/out.samples: cannot write: No such file or directory" "" \
  "$NCVERIFY" sample box.stl -o nowhere/out.samples
expect_bad_input "output to /dev/full" "/dev/full: cannot write: No space left on device" "" \
  "$NCVERIFY" sample box.stl -o /dev/full --step 2
expect_bad_input "legend to a missing folder: no coloured mesh either" "nowhere/legend.svg: cannot write" \
  colored.ply "$NCVERIFY" colorize good.dist -o colored.ply --legend nowhere/legend.svg
expect_bad_input "histogram to a missing folder: no report either" "nowhere/histogram.svg: cannot write" \
  report.txt "$NCVERIFY" stats good.dist -o report.txt --histogram-svg nowhere/histogram.svg
expect_bad_input "output is a folder" "folder.stl: cannot write: Is a directory" "" \
  "$NCVERIFY" sample box.stl -o folder.stl --step 2
# Root writes anywhere, so the read-only case runs as nobody when the suite runs as root.
mkdir ro && chmod 555 ro && chmod 755 "$WORK"
as_other=()
[ "$(id -u)" -ne 0 ] || as_other=(setpriv --reuid=65534 --regid=65534 --clear-groups)
expect_bad_input "read-only folder" "ro/out.samples: cannot write: Permission denied" "" \
  "${as_other[@]}" "$NCVERIFY" sample box.stl -o ro/out.samples --step 2
check "nothing written into the read-only folder" test -z "$(ls -A ro)"
finish
