#!/usr/bin/env bash
# The generator's second family (ncgen all --family decimated, small size) verified as a user
# would: the planted gouges found as negative errors where and as deep as the manifest says,
# a random triangle order changing no result, and the parts far from the origin giving the
# near parts' results up to the float STL's rounding there (2^-11 mm at z = 5,000 mm).
. "$(dirname "$0")/lib.sh"
cd "$WORK"
if [ ! -x "$NCGEN" ]; then echo "ncgen not built" >&2; exit 1; fi

"$NCGEN" -q all --seed 1 --size small --family decimated --out parts
"$NCGEN" -q workpiece --seed 1 --size small --stage finishing --mesher decimate --shuffle \
  -o shuffled.stl
check "the family's nine files and manifest are written" test "$(ls parts | wc -l)" -eq 9

run() { # workpiece nominal name
  "$NCVERIFY" -q run "$1" "$2" -d "$3" --tol -0.05:0.1 --regions 1000 --format json >"$3.json"
}
run parts/core_finishing.stl parts/core_nominal.stl near
run shuffled.stl parts/core_nominal.stl shuffled
run parts/core_finishing_far.stl parts/core_nominal_far.stl far
run parts/core_roughing.stl parts/core_nominal.stl roughing

check "the finishing part fails on its gouges, the roughing part leaves millimetres" \
  /usr/bin/python3 -c "
import json
near, rough = (json.load(open(f + '.json')) for f in ('near', 'roughing'))
assert near['verdict'] == 'fail' and near['error']['min']['value'] < -0.25, near['error']['min']
assert rough['error']['max']['value'] > 2 and rough['error']['mean'] > 0.3, rough['error']"
check "every planted gouge is a gouge region at the manifest's place and depth" \
  /usr/bin/python3 "$NCV_SOURCE_DIR/tests/e2e/check_planted_gouges.py" parts/manifest.json near.json
check "the shuffled part gives the same errors, both directions" /usr/bin/python3 -c "
import json
a, b = (json.load(open(f + '.json')) for f in ('near', 'shuffled'))
for d in ('error',):
    for k in ('max', 'min'):
        assert a[d][k]['value'] == b[d][k]['value'], (k, a[d][k], b[d][k])
        assert a['reverse'][d][k]['value'] == b['reverse'][d][k]['value'], k
assert abs(a['error']['mean'] - b['error']['mean']) < 1e-12
assert a['verdict'] == b['verdict']"
check "far from the origin: the same results up to the STL's rounding" /usr/bin/python3 -c "
import json
a, b = (json.load(open(f + '.json')) for f in ('near', 'far'))
for r in (lambda j: j['error'], lambda j: j['reverse']['error']):
    for k in ('max', 'min'):
        assert abs(r(a)[k]['value'] - r(b)[k]['value']) < 1e-3, (k, r(a)[k], r(b)[k])
    assert abs(r(a)['mean'] - r(b)['mean']) < 1e-4
assert a['verdict'] == b['verdict']
assert abs(a['tolerance']['share_within'] - b['tolerance']['share_within']) < 1e-3"
finish
