#!/usr/bin/env bash
# Paper-scale benchmark: builds the default Release configuration (no -march=native) in
# build-bench/ (or $NCV_BENCH_BUILD), generates the large sample set once into samples/large/
# (git-ignored) plus three finer tessellations of the nominal (about 170 k, 1 M and 1.7 M
# triangles),
# then runs every stage with both sampling schemes, the finishing part on 1 and 2 threads,
# the grid build on the three nominals and the growth with δ and the nominal's size, and
# prints one table with the paper's Table 1 and Table 2 figures and the performance targets
# beside the measured values. Details: docs/PERFORMANCE.md.
# The second workpiece family (ncgen all --family decimated: decimated meshes, and the same
# shuffled and far from the origin) goes into samples/large/decimated/, once; the yardstick
# and the stats phase at 1.8 M samples measure both families.
# Usage: scripts/bench.sh           (NCV_BENCH_REPS=N repetitions, default 3;
#                                     NCV_BENCH_QUICK=1 skips δ = 0.03 %;
#                                     NCV_BENCH_ONLY=yardstick runs the yardstick and the
#                                     stats at 1.8 M samples alone)
set -euo pipefail
cd "$(dirname "$0")/.."

build="${NCV_BENCH_BUILD:-build-bench}"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCV_NATIVE=OFF >&2
cmake --build "$build" --target ncverify ncgen >&2
micro="$build/bench/ncverify_microbench"
only="${NCV_BENCH_ONLY:-}"
if [ -z "$only" ] && cmake --build "$build" --target help | grep -q ncverify_microbench; then
  cmake --build "$build" --target ncverify_microbench ncverify_search_profile >&2
fi
ncgen="$build/tools/ncgen/ncgen"

large=samples/large
if [ ! -f "$large/manifest.json" ]; then
  "$ncgen" all --seed 1 --size large --out "$large" >&2
fi
if [ ! -f "$large/decimated/manifest.json" ]; then
  "$ncgen" all --seed 1 --size large --family decimated --out "$large/decimated" >&2
fi
# The same part tessellated finer (ncgen nominal --tolerance/--level).
if [ -z "$only" ]; then
  [ -f "$large/core_nominal_170k.stl" ] ||
    "$ncgen" nominal -o "$large/core_nominal_170k.stl" --tolerance 0.0045 --level 10 >&2
  [ -f "$large/core_nominal_1m.stl" ] ||
    "$ncgen" nominal -o "$large/core_nominal_1m.stl" --tolerance 0.0006 --level 11 >&2
  [ -f "$large/core_nominal_1700k.stl" ] ||
    "$ncgen" nominal -o "$large/core_nominal_1700k.stl" --tolerance 0.0003 --level 11 >&2
fi

# The yardstick: the Embree harness beside the repository (../shared/tools/embree_sd), built
# into build-embree/ where libembree-dev is installed; without it the table says so.
embree_src=../shared/tools/embree_sd
embree=build-embree/embree_sd
if [ -f "$embree_src/CMakeLists.txt" ]; then
  cmake -S "$embree_src" -B build-embree -DCMAKE_BUILD_TYPE=Release >&2 &&
    cmake --build build-embree >&2 || echo "bench: the Embree harness did not build" >&2
fi

exec /usr/bin/python3 bench/bench_table.py "$build/ncverify" "$micro" "$large" \
  "$build/bench/ncverify_search_profile" "$embree"
