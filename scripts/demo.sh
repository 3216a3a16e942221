#!/usr/bin/env bash
# Sets everything up and runs the main job on a bundled example: the finishing workpiece of
# the sample mould core (scallops and planted gouges) against its nominal, with a tolerance
# of -0.05/+0.1 mm. Outputs go to out/demo/. The part is out of tolerance on purpose (it has
# gouges); only a real error makes this script fail (a verdict, 1 fail or 3 inconclusive, does
# not).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
status=0
build/ncverify run samples/parts/core_finishing.stl samples/parts/core_nominal.stl \
  --tol -0.05:0.1 -d out/demo || status=$?
[ "$status" -le 1 ] || [ "$status" -eq 3 ] || exit "$status"
cat >&2 <<MSG

demo: the report is above; everything is in out/demo/:
  core_finishing.report.html    the report to open in a browser (or e-mail): 3D views, regions
  core_finishing.ply            coloured workpiece (open it in MeshLab or CloudCompare)
  core_finishing.reverse.ply    coloured nominal (the error measured from the nominal's side)
  core_finishing.legend.svg     colour bar    core_finishing.histogram.svg  error histogram
  core_finishing.report.txt/.json   the report    *.samples *.grid *.dist  intermediates
MSG
