#!/bin/bash
# Verifies every workpiece of a folder on a few machines with GNU parallel, as samples/Makefile
# does on one, and writes the same OUT/summary.csv:
#   scripts/parallel/verify_parts.sh [-S HOSTS] PARTS OUT [VARIABLE=value ...]
# HOSTS: GNU parallel's --sshlogin list, e.g. ':,host1,host2' (':' is this machine, the
# default); each host runs one task at a time, with all its cores.
# VARIABLEs are samples/Makefile's (STEP, TOL, ...). PARTS, OUT, this repository and NCVERIFY
# must be at the same path on every host (a shared filesystem), reachable by ssh without a
# password. The grids first, then the shards (SHARDS > 1), then the parts, then the summary;
# exit status the summary's.
set -euo pipefail
hosts=:
if [ "${1:-}" = -S ]; then
  hosts=$2
  shift 2
fi
if [ $# -lt 2 ]; then
  sed -n '2,11s/^# \{0,1\}//p' "$0" >&2
  exit 2
fi
scripts=$(cd "$(dirname "$0")/../batch" && pwd)
batch=$("$scripts/prepare.sh" "$@")

# run LIST: every line of BATCH/LIST as a task, one at a time per host; failures go on.
run() {
  parallel --sshlogin "$hosts" --jobs 1 --halt never --joblog "$batch/log/$1.joblog" \
    "$scripts/task.sh" "$batch" {} <"$batch/$1" || true
}
run grids.txt
run shards.txt
run parts.txt
exec "$scripts/task.sh" "$batch" summary
