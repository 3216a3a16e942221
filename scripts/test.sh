#!/usr/bin/env bash
# Sets everything up and runs the whole test suite: unit tests (Catch2) and end-to-end
# tests of the real binary, through ctest, in a Release build with warnings as errors.
# Options:  --sanitize   also build and run everything under ASan + UBSan (build-asan/)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh --no-build

run_suite() {
  local dir=$1; shift
  cmake -S . -B "$dir" -G Ninja -DNCV_WERROR=ON "$@" >/dev/null
  cmake --build "$dir"
  ctest --test-dir "$dir" --output-on-failure -j2
}

run_suite build -DCMAKE_BUILD_TYPE=Release
if [ "${1:-}" = "--sanitize" ]; then
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    run_suite build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNCV_SANITIZE=ON
fi
