"""Every gouge the manifest plants in a finishing part is a gouge region of the report whose
box holds the planted centre (a flat end mill leaves a flat-bottomed disc: the extreme may be
anywhere on it), its extreme as deep as planted within 0.02 mm.

Usage: python3 check_planted_gouges.py MANIFEST.json REPORT.json [PART]  (PART: the manifest's
file name of the part, default core_finishing.stl). Exit status 1 with the gouge not found."""
import json
import sys

manifest_path, report_path = sys.argv[1], sys.argv[2]
part = sys.argv[3] if len(sys.argv) > 3 else "core_finishing.stl"
manifest = {p["file"]: p for p in json.load(open(manifest_path))["parts"]}
gouges = [g for g in json.load(open(report_path))["regions"] if g["kind"] == "gouge"]
for planted in manifest[part]["gouges"]:
    near = [g for g in gouges if g["bbox_min"][0] <= planted["x"] <= g["bbox_max"][0]
            and g["bbox_min"][1] <= planted["y"] <= g["bbox_max"][1]]
    assert near, ("not found", planted)
    deepest = min(g["extreme"]["value"] for g in near)
    assert abs(deepest + planted["depth"]) < 0.02, (deepest, planted)
