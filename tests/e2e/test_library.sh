#!/usr/bin/env bash
# The library for OpenMesh users: the package installed into a fresh prefix, the example
# program built against it alone in a fresh folder, and its results on bundled parts equal to
# `ncverify run`'s: the JSON report of both directions byte for byte (every number to the
# bit), the exit status, and the coloured workpiece's and nominal's colours and errors vertex
# for vertex.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"

cmake --install "$NCV_BUILD_DIR" --prefix "$WORK/prefix" >install.log 2>&1
check "the package installs" test -f prefix/include/ncverify/verify.hpp \
  -a -f prefix/lib/cmake/ncverify/ncverifyConfig.cmake -a -f prefix/bin/ncverify

generator=()
[ -n "${NCV_CMAKE_GENERATOR:-}" ] && generator=(-G "$NCV_CMAKE_GENERATOR")
compiler=()
[ -n "${NCV_CXX_COMPILER:-}" ] && compiler=(-DCMAKE_CXX_COMPILER="$NCV_CXX_COMPILER")
cp -r "$NCV_SOURCE_DIR/examples" example-src
cmake -S example-src -B example-build "${generator[@]}" "${compiler[@]}" \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$WORK/prefix" \
  -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >configure.log 2>&1
check "the example configures against the installed package ($(tail -c 300 configure.log))" \
  grep -q "Build files have been written" configure.log
cmake --build example-build >build.log 2>&1
check "the example builds ($(tail -c 300 build.log))" test -x example-build/verify_openmesh
check "with the installed headers" grep -qE -- "-(I|isystem) ?$WORK/prefix/include" \
  example-build/compile_commands.json
check "and none from the source tree" test "$(grep -c -- "$NCV_SOURCE_DIR" \
  example-build/compile_commands.json)" -eq 0
example=$WORK/example-build/verify_openmesh

# ply_vertices FILE: each vertex's colour and signed error, from the PLY the command writes
# (float x y z, uchar rgb, float quality, float scalar, int region) or the one OpenMesh writes for the
# example (float x y z, uchar rgb, double signed_error), as "r g b error(float)" lines.
ply_vertices() {
  /usr/bin/python3 - "$1" <<'PY'
import struct, sys
data = open(sys.argv[1], 'rb').read()
end = data.index(b'end_header\n') + len(b'end_header\n')
header = data[:end].decode().split('\n')
count = next(int(l.split()[2]) for l in header if l.startswith('element vertex'))
props = [l.split()[1:] for l in header if l.startswith('property ') and 'list' not in l]
layout = {'float': 'f', 'double': 'd', 'uchar': 'B', 'int': 'i', 'uint': 'I'}
fmt = '<' + ''.join(layout[kind] for kind, _ in props)
size = struct.calcsize(fmt)
names = [name for _, name in props]
for k in range(count):
    v = dict(zip(names, struct.unpack_from(fmt, data, end + k * size)))
    error = v.get('signed_error', v.get('quality'))
    print(v['red'], v['green'], v['blue'], repr(struct.unpack('<f', struct.pack('<f', error))[0]))
PY
}

# same_colors WHAT RUN_PLY EXAMPLE_PLY MESH: equal vertex for vertex, one per vertex of MESH.
same_colors() {
  ply_vertices "$2" >run.vertices
  ply_vertices "$3" >example.vertices
  check "$1: the coloured TriMesh has run's colours and errors at every vertex" \
    cmp -s run.vertices example.vertices
  check "$1: on every vertex of $4 (manifest.json)" test "$(wc -l <example.vertices)" -eq \
    "$(/usr/bin/python3 -c "import json; print(next(p['vertices'] for p in json.load(open(
      '$PARTS/manifest.json'))['parts'] if p['file'] == '$4'))")"
}

# same_as_run PART NOMINAL TOLERANCE STATUS: the example and `run` on one part.
same_as_run() {
  local part=$1 nominal=$2 tolerance=$3 status=$4
  mkdir -p "$part" && cd "$part"
  cp "$PARTS/$part.stl" "$PARTS/$nominal.stl" .
  "$NCVERIFY" -q run "$part.stl" "$nominal.stl" --tol "$tolerance" --coarse --format json -d run \
    | jq 'del(.traceability)' >run.json
  local run_status=${PIPESTATUS[0]}
  "$example" "$part.stl" "$nominal.stl" "$tolerance" colored >example.raw.json 2>example.err
  local example_status=$?
  jq 'del(.traceability)' example.raw.json >example.json
  check "$part: run exits $status" test "$run_status" -eq "$status"
  check "$part: the example exits as run does ($(head -c 300 example.err))" \
    test "$example_status" -eq "$run_status"
  check "$part: the report is run's, byte for byte (but the command line and date)" \
    cmp -s run.json example.json
  check "$part: and holds the statistics" /usr/bin/python3 -c "
import json, math; r = json.load(open('example.json'))
assert r['sampling']['samples'] > 0 and r['tolerance']['verdict'] in ('pass', 'fail')
assert all(math.isfinite(r['error'][k]['value']) for k in ('max', 'min', 'max_abs'))
assert math.isfinite(r['error']['mean']) and math.isfinite(r['error']['rms'])
assert math.isfinite(r['reverse']['error']['max']['value']) and r['hausdorff'] > 0"
  same_colors "$part" "run/$part.ply" colored.ply "$part.stl"
  same_colors "$part, reverse" "run/$part.reverse.ply" colored.reverse.ply "$nominal.stl"
  check "$part: the worst vertices are named" test "$(grep -c "worst vertex" example.err)" -eq 2
  cd "$WORK"
}

same_as_run core_finishing core_nominal -0.05:0.1 1
same_as_run box_scallop box_nominal 0.1 0

# The slot the workpiece lacks (1 wide, 10 deep) fails from the nominal's side only. Its
# nominal holds 8 triangles with a repeated corner, which OpenMesh's STL reader drops (a
# TriMesh cannot hold them), so the example measures 36 nominal triangles where run reads 44:
# the same extremes and verdict, sums that differ in rounding.
cd "$WORK" && cp "$PARTS"/slot_*.stl .
"$NCVERIFY" -q run slot_uncut.stl slot_nominal.stl --tol 0.6 --format json -d slot >slot.run.json
check "slot: run fails" test $? -eq 1
"$example" slot_uncut.stl slot_nominal.stl 0.6 slot >slot.example.json 2>/dev/null
check "slot: the example fails" test $? -eq 1
check "slot: both read half the width forward and the depth reverse" /usr/bin/python3 -c "
import json
for f in ('slot.run.json', 'slot.example.json'):
    r = json.load(open(f))
    assert r['error']['max']['value'] == 0.5 and r['reverse']['error']['max']['value'] == 10, f
    assert r['tolerance']['verdict'] == 'pass' and r['reverse']['tolerance']['verdict'] == 'fail'
assert json.load(open('slot.example.json'))['nominal']['triangles'] == 36"

expect_status 2 "an unreadable mesh is refused" "$example" missing.stl "$PARTS/box_nominal.stl" 0.1 x
finish
