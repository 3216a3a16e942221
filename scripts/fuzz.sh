#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan, in build-fuzz/) and runs each for a
# bounded time, two at a time, starting from its committed seed corpus (fuzz/corpus/, which
# also holds every input that once crashed a target); inputs the fuzzer finds go to
# build-fuzz/corpus/, never into the checkout. Any crash, sanitizer report, leak, timeout
# (10 s for one input) or allocation beyond 2 GB fails the run and leaves the reproducer in
# build-fuzz/artifacts/TARGET/ (see fuzz/README.md).
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET [TARGET...]]   (default: 60 s, every target)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
[ $# -gt 0 ] && shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] ||
  targets=(samples_file grid_file distance_file mesh stl tolerance sampling_step command_line)

CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DNCV_FUZZ=ON -DNCV_SANITIZE=ON \
  -DNCV_WERROR=ON -DNCV_GENERATOR=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz --target fuzz_targets

dictionary() {
  case $1 in
    mesh | stl) echo fuzz/dict/mesh.dict ;;
    tolerance | sampling_step) echo fuzz/dict/number.dict ;;
    command_line) echo fuzz/dict/command_line.dict ;;
    *) echo fuzz/dict/container.dict ;;
  esac
}

# Runs one target; its verdict goes to build-fuzz/results/TARGET, its log beside it.
fuzz_target() {
  local target=$1
  local log=build-fuzz/results/$target.log
  mkdir -p "build-fuzz/corpus/$target" "build-fuzz/artifacts/$target"
  if "build-fuzz/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=2048 -dict="$(dictionary "$target")" \
    -print_final_stats=1 -artifact_prefix="build-fuzz/artifacts/$target/" \
    "build-fuzz/corpus/$target" "fuzz/corpus/$target" >"$log" 2>&1; then
    local runs
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
    echo "fuzz_$target: $runs executions in $seconds s, no crash" >"build-fuzz/results/$target"
  else
    echo "fuzz_$target: FAILED, see $log and build-fuzz/artifacts/$target/" \
      >"build-fuzz/results/$target"
  fi
}

rm -rf build-fuzz/results
mkdir -p build-fuzz/results
for target in "${targets[@]}"; do
  # Two fuzzers at once: one per core of the CI machine.
  while [ "$(jobs -rp | wc -l)" -ge 2 ]; do wait -n || true; done
  fuzz_target "$target" &
done
wait

status=0
for target in "${targets[@]}"; do
  cat "build-fuzz/results/$target"
  if grep -q FAILED "build-fuzz/results/$target"; then
    grep -E 'ERROR|SUMMARY|runtime error|Test unit written' "build-fuzz/results/$target.log" >&2 || true
    status=1
  fi
done
exit $status
