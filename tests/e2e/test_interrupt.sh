#!/usr/bin/env bash
# Interrupted runs (SIGINT, SIGTERM) leave no partial output and no temporary file behind,
# and exit with 128 + the signal, so a Makefile never takes a truncated file as up to date.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
write_box_stl box.stl 10 10 10

# wait_for GLOB PID: until a file matching GLOB exists (true) or PID has ended (false).
wait_for() {
  local glob=$1 pid=$2
  while kill -0 "$pid" 2>/dev/null; do
    compgen -G "$glob" >/dev/null && return 0
    sleep 0.01
  done
  return 1
}

# interrupt NAME SIGNAL STATUS OUTPUT_GLOB command...: starts the command in the background,
# sends SIGNAL as soon as its temporary output exists, then checks the exit status and
# that nothing matching OUTPUT_GLOB (the output or its temporary) is left.
interrupt() {
  local name=$1 signal=$2 want=$3 glob=$4
  shift 4
  "$@" 2>"$name.err" &
  local pid=$!
  if ! wait_for "$glob.tmp.*" "$pid"; then
    wait "$pid"
    fail "$name: ended (status $?) before its temporary output appeared"
    return
  fi
  kill "-$signal" "$pid"
  wait "$pid"
  local got=$?
  check "$name: exit status $got is $want" test "$got" -eq "$want"
  check "$name: no output nor temporary left ($(compgen -G "$glob*" | tr '\n' ' '))" \
    test -z "$(compgen -G "$glob*")"
  check "$name: nothing on stderr" test ! -s "$name.err"
}

# A long run: sampling at a tiny step, forced past the memory guard (2 x 10^6 samples a
# second; the temporary output exists from the start, since outputs are opened first).
interrupt "sample at a tiny step, SIGINT" INT 130 big.samples \
  "$NCVERIFY" -q sample box.stl -o big.samples --step 0.006 --force
interrupt "sample at a tiny step, SIGTERM" TERM 143 big.samples \
  "$NCVERIFY" -q sample box.stl -o big.samples --step 0.006 --force

# A run blocked on its input (a pipe whose writer has not finished): the temporary output
# is certainly pending when the signal comes.
mkfifo slow.fifo
sleep 30 >slow.fifo &
writer=$!
# (The redirection goes inside: a background job's standard input is /dev/null otherwise.)
interrupt "sample waiting on standard input, SIGINT" INT 130 piped.samples \
  sh -c 'exec "$@" <slow.fifo' sh "$NCVERIFY" -q sample - -o piped.samples
kill "$writer" 2>/dev/null

# `run` keeps complete intermediates only: the file being written when the signal comes
# goes, with its temporary.
interrupt "run at a tiny step, SIGINT" INT 130 part/box.samples \
  "$NCVERIFY" -q run box.stl box.stl -d part --step 0.006 --force
check "run: no temporary left in its folder" test -z "$(compgen -G 'part/*.tmp.*')"
finish
