#!/usr/bin/env bash
# Regenerates the seed corpora under fuzz/corpus/ (committed; the fuzzers add to copies of
# them): small meshes in every format ncverify reads, the three intermediate files made
# from them by the real binary, and option strings. Usage: fuzz/make_corpus.sh [NCVERIFY]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
ncverify=${1:-$here/../build/ncverify}
corpus=$here/corpus
# Inputs that once crashed a target (regression-*) stay: they are replayed on every run.
find "$corpus" -type f ! -name 'regression-*' -delete 2>/dev/null || true
mkdir -p "$corpus"/{mesh,stl,samples_file,grid_file,distance_file,tolerance,sampling_step,command_line}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 - "$corpus/mesh" <<'PY'
import struct, sys, os
out = sys.argv[1]
box_v = [(0,0,0),(2,0,0),(2,1,0),(0,1,0),(0,0,1),(2,0,1),(2,1,1),(0,1,1)]
box_f = [(0,2,1),(0,3,2),(4,5,6),(4,6,7),(0,1,5),(0,5,4),(1,2,6),(1,6,5),(2,3,7),(2,7,6),(3,0,4),(3,4,7)]
tet_v = [(0,0,0),(1,0,0),(0,1,0),(0,0,1)]
tet_f = [(0,2,1),(0,1,3),(0,3,2),(1,2,3)]
def write(name, data):
    with open(os.path.join(out, name), 'wb') as f: f.write(data)
def binary_stl(V, F, header=b'binary'):
    b = header.ljust(80, b' ') + struct.pack('<I', len(F))
    for t in F:
        b += struct.pack('<3f', 0, 0, 0) + b''.join(struct.pack('<3f', *V[v]) for v in t) + b'\0\0'
    return b
def ascii_stl(V, F, name='part'):
    s = f'solid {name}\n'
    for t in F:
        s += ' facet normal 0 0 0\n  outer loop\n'
        s += ''.join(f'   vertex {V[v][0]} {V[v][1]} {V[v][2]}\n' for v in t)
        s += '  endloop\n endfacet\n'
    return (s + f'endsolid {name}\n').encode()
write('box_binary.stl', binary_stl(box_v, box_f))
write('box_binary_header_solid.stl', binary_stl(box_v, box_f, b'solid but binary'))
write('tet_ascii.stl', ascii_stl(tet_v, tet_f))
write('two_solids_ascii.stl', ascii_stl(tet_v, tet_f[:2], 'a') + ascii_stl(box_v, box_f[:2], 'b'))
write('open_sheet.stl', binary_stl([(0,0,0),(1,0,0),(1,1,0),(0,1,0)], [(0,1,2),(0,2,3)]))
write('degenerate.stl', binary_stl([(0,0,0),(1,0,0),(2,0,0),(0,1,0)], [(0,1,2),(0,1,3),(0,1,3),(0,0,0)]))
ply = 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n'
ply += 'element face 4\nproperty list uchar int vertex_indices\nend_header\n'
ply += ''.join(f'{x} {y} {z}\n' for x, y, z in tet_v) + ''.join(f'3 {a} {b} {c}\n' for a, b, c in tet_f)
write('tet_ascii.ply', ply.encode())
bply = b'ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n'
bply += b'property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n'
bply += b''.join(struct.pack('<3d', *p) for p in tet_v)
bply += b''.join(struct.pack('<B3i', 3, *t) for t in tet_f)
write('tet_binary.ply', bply)
obj = ''.join(f'v {x} {y} {z}\n' for x, y, z in box_v)
obj += 'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n'
write('box_quads.obj', obj.encode())
off = 'OFF\n4 4 6\n' + ''.join(f'{x} {y} {z}\n' for x, y, z in tet_v)
off += ''.join(f'3 {a} {b} {c}\n' for a, b, c in tet_f)
write('tet.off', off.encode())
PY
cp "$corpus"/mesh/*.stl "$corpus/stl/"

cd "$work"
cp "$corpus/mesh/box_binary.stl" box.stl
cp "$corpus/mesh/open_sheet.stl" sheet.stl
cp "$corpus/mesh/tet_ascii.stl" tet.stl
"$ncverify" -q sample box.stl -o "$corpus/samples_file/box.samples" --step 0.8
"$ncverify" -q sample tet.stl -o "$corpus/samples_file/tet_paper_ii.samples" --step 0.6 --scheme paper-ii
"$ncverify" -q grid-build box.stl -o "$corpus/grid_file/box.grid"
"$ncverify" -q grid-build sheet.stl -o "$corpus/grid_file/open_sheet.grid"
"$ncverify" -q grid-build tet.stl -o "$corpus/grid_file/tet.grid" --cell 0.3
# Samples from standard input: the distance files hold them (a linked samples file would not
# be found from the fuzzer's buffer).
"$ncverify" -q distance - "$corpus/grid_file/tet.grid" -o "$corpus/distance_file/box_vs_tet.dist" \
  <"$corpus/samples_file/box.samples"
"$ncverify" -q distance - "$corpus/grid_file/open_sheet.grid" --reverse \
  -o "$corpus/distance_file/tet_vs_sheet.dist" <"$corpus/samples_file/tet_paper_ii.samples"

printf '%s' '0.1' >"$corpus/tolerance/symmetric"
printf '%s' '-0.05:0.1' >"$corpus/tolerance/zone"
printf '%s' '1e-3:2.5E2' >"$corpus/tolerance/exponents"
printf '%s' '0.1%' >"$corpus/sampling_step/percent"
printf '%s' '0.05' >"$corpus/sampling_step/absolute"
printf '%s' '1e-3' >"$corpus/sampling_step/exponent"
# Argument vectors for fuzz_command_line, one argument a line (the files are those its
# scratch folder holds).
printf '%s' 'colorize
low.dist
-o
out.ply
--map
turbo
--range
-1:1
--legend
out.svg' >"$corpus/command_line/colorize"
printf '%s' 'distance
low.samples
box.grid
-o
out.dist
--sign
winding' >"$corpus/command_line/distance"
printf '%s' 'grid-build
box.stl
-o
out.grid
--cell
0.5' >"$corpus/command_line/grid"
printf '%s' 'inspect
low.dist
--csv
--head
3' >"$corpus/command_line/inspect"
printf '%s' 'report
low.dist
box.reverse.dist
--tol
0.1
-o
out.html' >"$corpus/command_line/report"
printf '%s' 'run
low.stl
box.stl
--tol
0.1
--step
2%
-d
outdir' >"$corpus/command_line/run"
printf '%s' '-q
run
low.stl
box.stl
--one-sided
--format
json
--keep
none
--step
3%' >"$corpus/command_line/run_one_sided_json"
printf '%s' 'sample
low.stl
-o
out.samples
--step
2%
--shard
2/3' >"$corpus/command_line/sample_shard"
printf '%s' 'stats
low.dist
box.reverse.dist
--tol
-0.1:0.1
--format
csv
--bins
8' >"$corpus/command_line/stats_both"
printf '%s' 'stat
low.dist
--tols
0.1' >"$corpus/command_line/typo"
du -sh "$corpus"/*
