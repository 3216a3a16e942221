#!/usr/bin/env bash
# Sets everything up and runs the main job on a bundled example: the finishing workpiece of
# the sample mould core against its nominal. Outputs go to out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
mkdir -p out/demo
build/ncverify sample samples/parts/core_finishing.stl -o out/demo/core_finishing.samples
build/ncverify inspect out/demo/core_finishing.samples
echo "demo: outputs are in out/demo/" >&2
