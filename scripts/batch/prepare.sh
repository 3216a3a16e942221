#!/bin/bash
# Prepares a batch of samples/Makefile to run on many machines (scripts/slurm/submit.sh,
# scripts/parallel/verify_parts.sh):  prepare.sh PARTS OUT [VARIABLE=value ...]
# Writes OUT/batch/: make.args (how every task calls make: the Makefile, PARTS and OUT as
# absolute paths, the variables given), grids.txt, shards.txt (empty unless SHARDS > 1) and
# parts.txt (the tasks of the phases, one a line: a target, then the files an earlier task
# must have brought up to date),
# summary.txt (the last task) and log/. It also writes the batch's params files now, once,
# before many machines read them. Prints the batch folder. PARTS and OUT must be on a
# filesystem every machine sees at the same path, as must NCVERIFY.
set -euo pipefail
if [ $# -lt 2 ]; then
  echo "usage: $0 PARTS OUT [VARIABLE=value ...]" >&2
  exit 2
fi
for assignment in "${@:3}"; do
  case $assignment in
    [A-Z]*=*) ;;
    *) echo "prepare: '$assignment' is not a VARIABLE=value of samples/Makefile" >&2; exit 2 ;;
  esac
done
[ -d "$1" ] || { echo "prepare: no parts folder $1" >&2; exit 2; }
parts=$(realpath "$1")
mkdir -p "$2"
out=$(realpath "$2")
shift 2

batch=$out/batch
mkdir -p "$batch/log"
makefile=$(realpath "$(dirname "$0")/../../samples/Makefile")
printf '%s\n' -f "$makefile" "PARTS=$parts" "OUT=$out" "$@" >"$batch/make.args"
mapfile -t args <"$batch/make.args"
unset MAKEFLAGS MAKELEVEL
make -s "${args[@]}" params
make -s "${args[@]}" list-grids >"$batch/grids.txt"
make -s "${args[@]}" list-shards >"$batch/shards.txt"
make -s "${args[@]}" list-parts >"$batch/parts.txt"
echo summary >"$batch/summary.txt"
echo "$batch"
