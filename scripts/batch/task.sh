#!/bin/bash
# One task of a batch prepared by prepare.sh, on whichever machine runs it:
#   task.sh BATCH 'TARGET [UP_TO_DATE ...]'
# (one line of BATCH/grids.txt, parts.txt or summary.txt, as one argument). Makes TARGET with
# the batch's Makefile and variables (BATCH/make.args), after checking that every UP_TO_DATE
# file, which an earlier task makes, is up to date: a task never rebuilds another task's output
# (a grid rebuilt by every part of its family at once would waste the work and leave make's
# timestamps out of order). Under Slurm, ncverify uses the task's CPUs (THREADS).
set -uo pipefail
batch=$1
read -r -a task <<<"$2"
mapfile -t args <"$batch/make.args"
unset MAKEFLAGS MAKELEVEL
if [ -n "${SLURM_CPUS_PER_TASK:-}" ]; then
  args=("THREADS=$SLURM_CPUS_PER_TASK" "${args[@]}") # a THREADS the user gave comes later, and wins
fi
for needed in "${task[@]:1}"; do
  if ! make -s "${args[@]}" -q "$needed" 2>/dev/null; then
    echo "ncverify batch: $needed is not up to date (its task failed or did not run), so ${task[0]} is not made" >&2
    exit 1
  fi
done
exec make --no-print-directory "${args[@]}" "${task[0]}"
