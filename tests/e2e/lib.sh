# Shared helpers of the end-to-end tests: each test_*.sh sources this file, runs the real
# ncverify binary ($NCVERIFY, set by ctest) and ends with a 'N passed, N failed' line.
set -u
NCVERIFY=${NCVERIFY:-$(dirname "$0")/../../build/ncverify}
NCV_SOURCE_DIR=${NCV_SOURCE_DIR:-$(cd "$(dirname "$0")/../.." && pwd)}
WORK=$(mktemp -d "${TMPDIR:-/tmp}/ncverify-e2e.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
passed=0
failed=0

pass() { passed=$((passed + 1)); }
fail() { failed=$((failed + 1)); echo "FAIL: $*" >&2; }

# check "description" command...: the command must succeed.
check() {
  local what=$1; shift
  if "$@"; then pass; else fail "$what"; fi
}

# expect_status N "description" command...: exit status must be N.
expect_status() {
  local want=$1 what=$2; shift 2
  "$@" >"$WORK/out" 2>"$WORK/err"
  local got=$?
  if [ "$got" -eq "$want" ]; then pass; else fail "$what: exit $got, wanted $want ($(head -c 300 "$WORK/err"))"; fi
}

# expect_bad_input "description" "stderr fragment" output-path command...: exit 2, exactly one
# line on stderr containing the fragment, and no output file (or temporary) left behind.
expect_bad_input() {
  local what=$1 fragment=$2 output=$3; shift 3
  "$@" >"$WORK/out" 2>"$WORK/err"
  local got=$?
  local lines
  lines=$(wc -l <"$WORK/err")
  if [ "$got" -ne 2 ]; then fail "$what: exit $got, wanted 2"; return; fi
  if [ "$lines" -ne 1 ]; then fail "$what: $lines lines on stderr: $(cat "$WORK/err")"; return; fi
  if ! grep -qF -- "$fragment" "$WORK/err"; then fail "$what: stderr lacks '$fragment': $(cat "$WORK/err")"; return; fi
  if [ -n "$output" ] && compgen -G "$output*" >/dev/null; then fail "$what: left $(compgen -G "$output*")"; return; fi
  pass
}

# A binary STL of an axis-aligned box [0,a]x[0,b]x[0,c], outward-oriented (12 triangles).
write_box_stl() {
  /usr/bin/python3 - "$1" "$2" "$3" "$4" <<'PY'
import struct, sys
path, a, b, c = sys.argv[1], *map(float, sys.argv[2:])
V = [(0,0,0),(a,0,0),(a,b,0),(0,b,0),(0,0,c),(a,0,c),(a,b,c),(0,b,c)]
F = [(0,2,1),(0,3,2),(4,5,6),(4,6,7),(0,1,5),(0,5,4),(1,2,6),(1,6,5),(2,3,7),(2,7,6),(3,0,4),(3,4,7)]
with open(path, 'wb') as f:
    f.write(b'solid box'.ljust(80, b' ')); f.write(struct.pack('<I', len(F)))
    for t in F:
        f.write(struct.pack('<3f', 0, 0, 0))
        for v in t: f.write(struct.pack('<3f', *V[v]))
        f.write(b'\0\0')
PY
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}

# A report or summary CSV without the certified bound columns, which a sharded job refines
# shard by shard (docs/CERTIFICATION.md "Verdict"): what a sharded batch and the whole one
# share byte for byte.
csv_without_bounds() {
  /usr/bin/python3 -c '
import csv, sys
rows = list(csv.reader(open(sys.argv[1], newline="")))
drop = {"max_upper_bound", "min_lower_bound", "reverse_max_upper_bound", "reverse_min_lower_bound"}
keep = [i for i, name in enumerate(rows[0]) if name not in drop]
out = csv.writer(sys.stdout, lineterminator="\n")
for row in rows:
    out.writerow([row[i] for i in keep if i < len(row)])' "$1"
}
same_but_bounds() { cmp <(csv_without_bounds "$1") <(csv_without_bounds "$2"); }
