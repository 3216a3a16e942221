#!/usr/bin/env bash
# Regenerates the committed sample parts in samples/parts/ (mould core nominal and its
# roughing, semi-finishing and finishing workpieces at the small size, the analytic boxes, and
# manifest.json describing them). With the argument "large", also writes the paper-scale set
# (about 215 k, 470 k and 1.24 M triangles, some 100 MB) into samples/large/, which git ignores.
# Uses $NCGEN when set, else builds ncgen in build/ (Release) first.
# Usage: scripts/make_samples.sh [large]
set -euo pipefail
cd "$(dirname "$0")/.."

case "${1:-}" in
  "" | large) ;;
  *) echo "usage: $0 [large]" >&2; exit 2 ;;
esac

ncgen="${NCGEN:-}"
if [ -z "$ncgen" ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
  cmake --build build --target ncgen >&2
  ncgen=build/tools/ncgen/ncgen
fi

rm -rf samples/parts
"$ncgen" all --seed 1 --size small --out samples/parts
if [ "${1:-}" = large ]; then
  rm -rf samples/large
  "$ncgen" all --seed 1 --size large --out samples/large
fi
