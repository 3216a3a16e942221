#!/usr/bin/env bash
# The generator's parts: regenerated bit for bit (the bundled samples are what ncgen makes),
# and their verification is plausible: roughing mostly excess, finishing near zero with the
# planted gouges found where the manifest says, at the depth it says.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
PARTS="$NCV_SOURCE_DIR/samples/parts"
if [ ! -x "$NCGEN" ]; then echo "ncgen not built" >&2; exit 1; fi

"$NCGEN" -q all --seed 1 --size small --out regenerated
for part in "$PARTS"/*.stl; do
  check "$(basename "$part") regenerates identically" cmp -s "$part" "regenerated/$(basename "$part")"
done

for stage in roughing semifinishing finishing; do
  "$NCVERIFY" -q run "$PARTS/core_$stage.stl" "$PARTS/core_nominal.stl" -d "$stage" \
    --tol -0.05:0.1 --regions 1000 --format json >"$stage.json"
done
check "roughing leaves material: mean above 0.3 mm, most area in excess" /usr/bin/python3 -c "
import json; r = json.load(open('roughing.json'))
assert r['error']['mean'] > 0.3 and r['tolerance']['share_excess'] > 0.5, (r['error']['mean'], r['tolerance'])"
check "semi-finishing leaves less than roughing" /usr/bin/python3 -c "
import json; a, b = (json.load(open(f + '.json'))['error']['mean'] for f in ('roughing', 'semifinishing'))
assert 0 < b < a, (a, b)"
check "finishing is near nominal: |mean| below 0.05 mm, 90 % of the area within tolerance" /usr/bin/python3 -c "
import json; r = json.load(open('finishing.json'))
assert abs(r['error']['mean']) < 0.05 and r['tolerance']['share_within'] > 0.9, (r['error'], r['tolerance'])"
check "every planted gouge is found, where and as deep as the manifest says" \
  /usr/bin/python3 "$NCV_SOURCE_DIR/tests/e2e/check_planted_gouges.py" "$PARTS/manifest.json" \
  finishing.json
finish
