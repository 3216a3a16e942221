#!/bin/bash
# Verifies every workpiece of a folder on a Slurm cluster, as samples/Makefile does on one
# machine, and writes the same OUT/summary.csv:
#   scripts/slurm/submit.sh PARTS OUT [VARIABLE=value ...] [-- SBATCH_OPTION ...]
# VARIABLEs are samples/Makefile's (STEP, TOL, SCHEME, SIGN, CELL, BINS, NCVERIFY, ...);
# SBATCH_OPTIONs go to every job (--partition, --time, --mem, --cpus-per-task: ncverify's
# threads). PARTS, OUT, this repository and NCVERIFY must be at the same path on every node.
# The steps, each starting when the one before has ended, however (afterany):
#   ncverify-grid     job arrays, one task per nominal: its grid (with SHARDS > 1, also each
#                     workpiece's grid for the reverse direction)
#   ncverify-shard    with SHARDS > 1: job arrays, one task per shard of each workpiece: its
#                     samples and distances in both directions
#   ncverify-part     job arrays, one task per workpiece: samples, distances (or the shards'
#                     put together), CSV row, PLY, HTML report
#   ncverify-summary  OUT/summary.csv; the job fails unless every part passes
# A part whose task failed gets an error row, never a stale one. Logs: OUT/batch/log/.
# Prints the job ids; the last line is the summary job's.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
scripts=$(cd "$here/../batch" && pwd)
if [ $# -lt 2 ]; then
  sed -n '2,17s/^# \{0,1\}//p' "$0" >&2
  exit 2
fi
make_args=()
sbatch_args=()
for ((i = 1; i <= $#; i++)); do
  if [ "${!i}" = "--" ]; then
    sbatch_args=("${@:i+1}")
    break
  fi
  make_args+=("${!i}")
done
batch=$("$scripts/prepare.sh" "${make_args[@]}")
log=$batch/log
max_array=$(scontrol show config 2>/dev/null | awk '$1 == "MaxArraySize" { print $3 }')
max_array=${max_array:-1001}

# sbatch_job DEPENDENCY LIST OFFSET SBATCH_OPTION...: submits task.sbatch for LIST's lines
# from OFFSET + 1 on, once DEPENDENCY (job ids joined by ':', or none) has ended; prints its id.
sbatch_job() {
  local dependency=$1 list=$2 offset=$3
  shift 3
  sbatch --parsable ${dependency:+--dependency=afterany:$dependency} "$@" "${sbatch_args[@]}" \
    "$here/task.sbatch" "$scripts" "$batch" "$list" "$offset" | cut -d';' -f1
}

# arrays NAME LIST DEPENDENCY: LIST's lines as array tasks, at most MaxArraySize an array;
# prints the arrays' job ids joined by ':' (nothing for an empty LIST).
arrays() {
  local name=$1 list=$2 dependency=$3 tasks offset count id ids=()
  tasks=$(wc -l <"$batch/$list")
  for ((offset = 0; offset < tasks; offset += max_array)); do
    count=$((tasks - offset < max_array ? tasks - offset : max_array))
    id=$(sbatch_job "$dependency" "$list" "$offset" --job-name="$name" \
      --array="0-$((count - 1))" --output="$log/$name-%A_%a.out") || return 1
    ids+=("$id")
  done
  (IFS=:; echo "${ids[*]}")
}

grids=$(arrays ncverify-grid grids.txt "")
shards=$(arrays ncverify-shard shards.txt "$grids")
parts=$(arrays ncverify-part parts.txt "$(echo "$grids:$shards" | sed 's/^:*//; s/:*$//')")
summary=$(sbatch_job "$(echo "$grids:$shards:$parts" | sed 's/::*/:/g; s/^:*//; s/:*$//')" \
  summary.txt 0 --job-name=ncverify-summary --output="$log/ncverify-summary-%j.out")
echo "grids: ${grids:-none}"
echo "shards: ${shards:-none}"
echo "parts: ${parts:-none}"
echo "$summary"
