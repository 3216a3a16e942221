#!/bin/sh
# One step of a batch (samples/Makefile): run_step.sh ERRORS MAX_OK COMMAND...
# Prints the command as make would (not under make -s), runs it and shows what it printed on
# standard error. An exit status above MAX_OK (stats exits 1 for a part out of tolerance, and
# 3 for one not proven within it: results, not failures; with MAX_OK 1 both are accepted)
# keeps those messages in the file ERRORS, whose last line the summary quotes in the part's
# error row; a step that succeeds removes it.
errors=$1 max_ok=$2
shift 2
case ${MAKEFLAGS%% *} in
  *s*) ;;
  *) echo "$*" ;;
esac
"$@" 2>"$errors.tmp"
status=$?
cat "$errors.tmp" >&2
if [ "$status" -le "$max_ok" ] || { [ "$max_ok" -ge 1 ] && [ "$status" -eq 3 ]; }; then
  rm -f "$errors" "$errors.tmp"
  exit 0
fi
[ -s "$errors.tmp" ] || echo "$(basename "$1") stopped with exit status $status" >"$errors.tmp"
mv "$errors.tmp" "$errors"
exit "$status"
