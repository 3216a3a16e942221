#!/usr/bin/env bash
# Interrupted runs (SIGINT, SIGTERM) leave no partial output and no temporary file behind,
# and exit with 128 + the signal, so a Makefile never takes a truncated file as up to date.
. "$(dirname "$0")/lib.sh"
cd "$WORK"
write_box_stl box.stl 10 10 10

# Starts a command, sends it a signal as soon as a file matching PATTERN exists, and prints
# its exit status. Python, not the shell: a Popen child is never reaped before its status
# is asked for, so its process id cannot be reused by an unrelated process (a compiler of a
# concurrent build) before the signal is sent, as a shell's background job's can.
# Usage: send_signal.py SIGNAL PATTERN STDIN STDERR command...; STDIN "pipe" holds standard
# input open without writing to it (a producer that has not finished), "null" gives
# /dev/null; the command's standard error goes to the file STDERR.
cat >send_signal.py <<'PY'
import glob, signal, subprocess, sys, time
name, pattern, stdin, stderr, *command = sys.argv[1:]
child = subprocess.Popen(command, stdin=subprocess.PIPE if stdin == "pipe" else subprocess.DEVNULL,
                         stderr=open(stderr, "w"))
while not glob.glob(pattern):
    if child.poll() is not None:
        print(f"ended with status {child.returncode} before {pattern} appeared")
        sys.exit(1)
    time.sleep(0.005)
child.send_signal(getattr(signal, name))
print(child.wait())
PY

# interrupt NAME SIGNAL STATUS OUTPUT STDIN command...: the exit status must be STATUS,
# standard error the one line that says so, and neither OUTPUT nor its temporary left.
interrupt() {
  local name=$1 signal=$2 want=$3 output=$4 stdin=$5
  shift 5
  local got
  got=$(/usr/bin/python3 send_signal.py "$signal" "$output.tmp.*" "$stdin" stderr.txt "$@")
  check "$name: exit status $got is $want" test "$got" = "$want"
  check "$name: no output nor temporary left ($(compgen -G "$output*" | tr '\n' ' '))" \
    test -z "$(compgen -G "$output*")"
  check "$name: one line on stderr says so" \
    test "$(cat stderr.txt)" = "ncverify: interrupted; no partial output left"
}

# A long run: sampling at a tiny step, forced past the memory guard (2 x 10^6 samples a
# second; the temporary output exists from the start, since outputs are opened first).
interrupt "sample at a tiny step, SIGINT" SIGINT 130 big.samples null \
  "$NCVERIFY" -q sample box.stl -o big.samples --step 0.006 --force
interrupt "sample at a tiny step, SIGTERM" SIGTERM 143 big.samples null \
  "$NCVERIFY" -q sample box.stl -o big.samples --step 0.006 --force

# A run blocked on its input (a pipe whose writer has not finished): the temporary output
# is certainly pending when the signal comes.
interrupt "sample waiting on standard input, SIGINT" SIGINT 130 piped.samples pipe \
  "$NCVERIFY" -q sample - -o piped.samples

# `run` keeps complete intermediates only: interrupted while it measures (its samples file,
# small since it holds no points, is complete), it leaves no distance file and no temporary.
got=$(/usr/bin/python3 send_signal.py SIGINT part/box.samples null stderr.txt \
  "$NCVERIFY" -q run box.stl box.stl -d part --step 0.006 --force)
check "run interrupted while measuring: exit status $got is 130" test "$got" = 130
check "run: the complete samples file stays" test -s part/box.samples
check "run: no distance file, report nor temporary left" \
  test -z "$(compgen -G 'part/*.dist*')$(compgen -G 'part/*.report.*')$(compgen -G 'part/*.tmp.*')"
check "run: the interruption is the one line on stderr (besides the same mesh twice)" \
  test "$(grep -v 'is the nominal (box.stl) itself' stderr.txt)" = \
  "ncverify: interrupted; no partial output left"

# SIGBUS is what a mapped input (input_bytes.hpp) raises when another program truncates it
# while it is read: bad input, so one error line and exit status 2, and no output left.
# Sent here as the truncation would raise it (a real truncation is a race to time).
got=$(/usr/bin/python3 send_signal.py SIGBUS 'big.samples.tmp.*' null stderr.txt \
  "$NCVERIFY" -q sample box.stl -o big.samples --step 0.006 --force)
check "SIGBUS: exit status $got is 2" test "$got" = 2
check "SIGBUS: no output nor temporary left" test -z "$(compgen -G 'big.samples*')"
check "SIGBUS: one line on stderr" test "$(wc -l <stderr.txt)" = 1
check "SIGBUS: the line says an input was truncated" \
  grep -q "^ncverify: error: an input file was truncated" stderr.txt
finish
