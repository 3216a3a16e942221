#!/usr/bin/env bash
# Odd but valid meshes, through the real binary: each must give the right numbers (known in
# closed form for these boxes) and say what it noticed. docs/ROBUSTNESS.md describes each
# behaviour.
. "$(dirname "$0")/lib.sh"
cd "$WORK"

# Meshes from boxes, sheets and their defects; binary STL (float32) or, for .ply, ASCII PLY
# with every digit of the doubles.
cat >gen.py <<'PY'
import numpy as np, struct, sys

def box(lo, hi):
    (a, b, c), (d, e, f) = lo, hi
    V = np.array([(a, b, c), (d, b, c), (d, e, c), (a, e, c),
                  (a, b, f), (d, b, f), (d, e, f), (a, e, f)], float)
    F = np.array([(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
                  (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)])
    return V, F

def square(x0, x1, z):  # facing up
    V = np.array([(x0, x0, z), (x1, x0, z), (x1, x1, z), (x0, x1, z)], float)
    return V, np.array([(0, 1, 2), (0, 2, 3)])

def sheet(size, n, z):  # n x n cells of two triangles
    t = np.linspace(0, size, n + 1)
    X, Y = np.meshgrid(t, t, indexing='ij')
    V = np.stack([X.ravel(), Y.ravel(), np.full(X.size, z)], 1)
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing='ij')
    a = (i * (n + 1) + j).ravel()
    b = a + n + 1
    return V, np.concatenate([np.stack([a, b, b + 1], 1), np.stack([a, b + 1, a + 1], 1)])

def join(*parts):
    V, F, offset = [], [], 0
    for v, f in parts:
        V.append(v); F.append(f + offset); offset += len(v)
    return np.concatenate(V), np.concatenate(F)

def write(path, V, F):
    if path.endswith('.ply'):
        with open(path, 'w') as out:
            out.write(f'ply\nformat ascii 1.0\nelement vertex {len(V)}\nproperty double x\n'
                      f'property double y\nproperty double z\nelement face {len(F)}\n'
                      'property list uchar int vertex_indices\nend_header\n')
            out.writelines(f'{x!r} {y!r} {z!r}\n' for x, y, z in V)
            out.writelines(f'3 {a} {b} {c}\n' for a, b, c in F)
        return
    rec = np.zeros(len(F), dtype=[('n', '<f4', 3), ('v', '<f4', 9), ('a', '<u2')])
    rec['v'] = V[F].reshape(-1, 9)
    with open(path, 'wb') as out:
        out.write(b'binary'.ljust(80, b' ') + struct.pack('<I', len(F)))
        out.write(rec.tobytes())

kind, path, *args = sys.argv[1:]
a = [float(x) for x in args]
if kind == 'box':                     # box x0 y0 z0 x1 y1 z1
    V, F = box(a[:3], a[3:6])
elif kind == 'defects':               # the 10 mm box plus a duplicate, a sliver and a point
    V, F = box((0, 0, 0), (10, 10, a[0]))
    V = np.concatenate([V, [(5, 0, 0)]])
    F = np.concatenate([F, F[:1], [(0, 1, 8), (3, 3, 3)]])
elif kind == 'inward':                # the 10 mm box with every triangle reversed
    V, F = box((0, 0, 0), (10, 10, 10))
    F = F[:, ::-1]
elif kind == 'open':                  # the 10 mm box without its bottom
    V, F = box((0, 0, 0), (10, 10, 10))
    F = F[2:]
elif kind == 'nonmanifold':           # two boxes of height z sharing the edge x = y = 10
    V, F = join(box((0, 0, 0), (10, 10, a[0])), box((10, 10, 0), (20, 20, a[0])))
elif kind == 'patches':               # squares over [2, 8]^2 at the given heights
    V, F = join(*[square(2, 8, z) for z in a])
elif kind == 'mixed':                 # a 1 m box and a 2 mm sheet of 2 n^2 tiny triangles
    V, F = join(box((0, 0, 0), (1000, 1000, 1000)), sheet(2, int(a[0]), -1))
write(path, V, F)
PY
gen() { /usr/bin/python3 gen.py "$@"; }

# measure NAME WORKPIECE NOMINAL [options]: `run` with the JSON report kept as NAME.json and
# stderr as NAME.err; the status is returned.
measure() {
  local name=$1 workpiece=$2 nominal=$3
  shift 3
  "$NCVERIFY" -q run "$workpiece" "$nominal" -d "$name" --format json --step 0.5 "$@" \
    >"$name.json" 2>"$name.err"
}
# value NAME KEY: a number from NAME.json (max, min, mean) or its sign method.
value() {
  /usr/bin/python3 -c "
import json, sys
d = json.load(open(sys.argv[1] + '.json'))
print({'max': d['error']['max']['value'], 'min': d['error']['min']['value'],
       'mean': d['error']['mean'], 'sign': d['distance']['sign_method']}[sys.argv[2]])" "$1" "$2"
}
# near A B TOLERANCE
near() { /usr/bin/python3 -c "import sys; a, b, t = map(float, sys.argv[1:]); sys.exit(abs(a - b) > t)" "$@"; }
# expect_numbers NAME MAX MIN: d_max and d_min within 1e-9 of the closed form.
expect_numbers() {
  check "$1: d_max $(value "$1" max) is $2" near "$(value "$1" max)" "$2" 1e-9
  check "$1: d_min $(value "$1" min) is $3" near "$(value "$1" min)" "$3" 1e-9
}
warned() { grep -q -- "$2" "$1.err"; }
silent() { test ! -s "$1.err"; }

gen box nominal.stl 0 0 0 10 10 10
gen box raised.stl 0 0 0 10 10 10.5   # the top 0.5 too high: excess
gen box lowered.stl 0 0 0 10 10 9.75  # the top 0.25 too low: gouge (heights exact in float32)
measure reference_raised raised.stl nominal.stl
measure reference_lowered lowered.stl nominal.stl
expect_numbers reference_raised 0.5 0
expect_numbers reference_lowered 0 -0.25
check "a clean closed nominal is signed by pseudonormals" test "$(value reference_raised sign)" = pseudonormal
check "a clean pair warns about nothing" silent reference_raised

# Degenerate and duplicate triangles in the nominal: a repeated triangle makes its edges
# non-manifold (winding number, said so); the sliver and the one-point triangle change
# nothing. The numbers are the clean box's, mean included.
gen defects defects.stl 10
for stage in raised lowered; do
  measure "defects_$stage" "$stage.stl" defects.stl
  check "defects ($stage): d_max as the clean box" near "$(value "defects_$stage" max)" "$(value "reference_$stage" max)" 1e-12
  check "defects ($stage): d_min as the clean box" near "$(value "defects_$stage" min)" "$(value "reference_$stage" min)" 1e-12
  check "defects ($stage): mean as the clean box" near "$(value "defects_$stage" mean)" "$(value "reference_$stage" mean)" 1e-12
done
check "defects: the duplicate is reported and the winding number used" \
  warned defects_raised "edges with more than two triangles"
check "defects: winding sign" test "$(value defects_raised sign)" = winding
# ... and in the workpiece: sampled (degenerate ones at their corners), extremes unchanged.
gen defects raised_defects.stl 10.5
measure workpiece_defects raised_defects.stl nominal.stl
expect_numbers workpiece_defects 0.5 0

# Non-manifold edges: two boxes sharing one edge.
gen nonmanifold twin.stl 10
gen nonmanifold twin_raised.stl 10.5
gen nonmanifold twin_lowered.stl 9.75
measure twin_raised twin_raised.stl twin.stl
measure twin_lowered twin_lowered.stl twin.stl
expect_numbers twin_raised 0.5 0
expect_numbers twin_lowered 0 -0.25
check "non-manifold edge reported, winding sign" warned twin_raised "edges with more than two triangles"

# An open nominal (no bottom): the generalized winding number tells inside from outside.
gen open open.stl
gen patches patches.stl 10.375 9.75
measure open patches.stl open.stl
expect_numbers open 0.375 -0.25
check "open nominal reported" warned open "boundary edges (open)"
check "open nominal: winding sign" test "$(value open sign)" = winding

# An inward-oriented nominal is detected and flipped: outside stays positive.
gen inward inward.stl
measure inward_raised raised.stl inward.stl
measure inward_lowered lowered.stl inward.stl
expect_numbers inward_raised 0.5 0
expect_numbers inward_lowered 0 -0.25
check "inward nominal flipped with a warning" warned inward_raised "oriented inward"
check "inward nominal, once flipped, signed by pseudonormals" test "$(value inward_raised sign)" = pseudonormal

# A part 1,000,000 mm from the origin: computed relative to a local origin, so a 1 um
# excess and a 2 um gouge come out to the nanometre (double-precision PLY), and the STL
# float grid's smallest step there (1/16 mm) exactly.
far=1000000
gen box far.ply $far $far $far $((far + 10)) $((far + 10)) $((far + 10))
gen box far_raised.ply $far $far $far $((far + 10)) $((far + 10)) $((far + 10)).001
gen box far_lowered.ply $far $far $far $((far + 10)) $((far + 10)) $((far + 9)).998
measure far_raised far_raised.ply far.ply
measure far_lowered far_lowered.ply far.ply
expect_numbers far_raised 0.001 0
expect_numbers far_lowered 0 -0.002
gen box far.stl $far $far $far $((far + 10)) $((far + 10)) $((far + 10))
gen box far_raised.stl $far $far $far $((far + 10)) $((far + 10)) $((far + 10)).0625
measure far_stl far_raised.stl far.stl
expect_numbers far_stl 0.0625 0

# A workpiece that does not overlap the nominal at all (5 mm beside it): a warning, and the
# distances, 5 to 15 mm, all positive.
gen box beside.stl 15 0 0 25 10 10
measure beside nominal.stl beside.stl
expect_numbers beside 15 5
check "no overlap: warned" warned beside "barely overlap (0 %"

# Mixed-up inputs are measured, with one warning each in a two-sided run: a workpiece in
# inches against a nominal in millimetres, and the two parts given the other way round (the
# 12-triangle box as the workpiece, the dense scallop mesh as the nominal).
gen box inches.stl 0 0 0 0.3937 0.3937 0.3937
measure inches inches.stl nominal.stl
check "inches against millimetres: named" warned inches "inches against millimetres? (the nominal is the one in mm)"
measure swapped "$NCV_SOURCE_DIR/samples/parts/box_nominal.stl" "$NCV_SOURCE_DIR/samples/parts/box_scallop.stl"
check "swapped parts: warned once" test "$(grep -c "were they given the other way round" swapped.err)" -eq 1
measure not_swapped "$NCV_SOURCE_DIR/samples/parts/box_scallop.stl" "$NCV_SOURCE_DIR/samples/parts/box_nominal.stl"
check "the right order: no such warning" test "$(grep -c "other way round" not_swapped.err)" -eq 0

# A nominal mixing huge and tiny triangles: a 1 m box and a 2 mm sheet of 245,000
# triangles make the paper's mean-area cell too small for the 1 m box; the cell grows so
# cells stay <= 8 and references <= 16 per triangle, and memory with them.
gen mixed mixed.stl 350
# Under AddressSanitizer freed memory is held back in its quarantine (up to 256 MB), so a
# peak would count every buffer the run ever freed: measured there without the quarantine,
# it is the live memory plus the sanitizer's own.
without_quarantine() {
  if ldd "$NCVERIFY" | grep -q libasan; then
    ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}quarantine_size_mb=0" "$@"
  else
    "$@"
  fi
}
without_quarantine /usr/bin/time -f "%M" -o mixed.mem "$NCVERIFY" grid-build mixed.stl \
  -o mixed.grid 2>mixed.err
check "huge and tiny triangles: cell size grown" grep -q "cell size grown" mixed.err
"$NCVERIFY" inspect mixed.grid --json >mixed.json
check "huge and tiny triangles: within the cell and reference budgets" /usr/bin/python3 -c "
import json, sys
m = json.load(open('mixed.json'))['meta']
t = m['nominal']['triangles']
sys.exit(not (m['grid']['cells'] <= 8 * t and m['grid']['references'] <= 16 * t))"
check "huge and tiny triangles: peak memory under 1 kB per triangle" test "$(tail -1 mixed.mem)" -lt 245000
# A cell size forced absurdly small grows the same way, to the minimum budget of 2^15 cells.
"$NCVERIFY" grid-build nominal.stl -o tiny_cell.grid --cell 1e-9 2>tiny_cell.err
check "--cell 1e-9: cell size grown" grep -q "cell size grown" tiny_cell.err
check "--cell 1e-9: at most 2^15 cells" test "$("$NCVERIFY" inspect tiny_cell.grid --json |
  /usr/bin/python3 -c "import json, sys; print(json.load(sys.stdin)['meta']['grid']['cells'])")" -le 32768
finish
