#!/bin/sh
# Writes OUT/summary.csv for a batch of samples/Makefile (its `summary` target):
#   summary.sh OUT NCVERIFY PARTS_DIR [NAME NOMINAL]...
# One row per part in the order given: the part's CSV row from `ncverify stats` when make (-q)
# says it is up to date with the batch's inputs and parameters; otherwise an error row (verdict
# `error`, the reason in the last column, `message`). The file is CSV only (header and rows);
# the counts and every part not passing go to standard error. Exit status 0 when every part
# passes, 1 otherwise. MAKE_COMMAND and MAKEFILE (the environment) say how to ask make.
set -u
out=$1 ncverify=$2 parts=$3
shift 3
header="$($ncverify stats --csv-header),message" || exit 2
summary=$out/summary.csv
tmp=$summary.tmp.$$
trap 'rm -f "$tmp" "$tmp.parts" "$tmp.fresh"' EXIT

# Ask make with the batch's variables only: a flag such as -B (remake everything) or -n would
# make every row look out of date.
case "${MAKEFLAGS:-}" in
  *" -- "*) MAKEFLAGS="-- ${MAKEFLAGS#* -- }" ;;
  *) MAKEFLAGS= ;;
esac
export MAKEFLAGS

# The parts, NAME NOMINAL a line (make allows no spaces in file names).
parts_list=$tmp.parts
while [ $# -ge 2 ]; do
  printf '%s %s\n' "$1" "$2"
  shift 2
done >"$parts_list"

# The rows make (-q) finds up to date, one make per core.
fresh=$tmp.fresh
while read -r name nominal; do
  printf '%s\n' "$out/$name.csv"
done <"$parts_list" | xargs -r -P "$(nproc)" -I{} sh -c \
  '"$MAKE_COMMAND" -f "$MAKEFILE" -q "$1" >/dev/null 2>&1 && printf "%s\n" "$1"' up_to_date {} \
  >"$fresh"
up_to_date() {
  grep -qxF -- "$1" "$fresh"
}

# The first step of the part's chain that failed, as "STEP: its last message line".
failed_step() {
  name=$1 grid=$(basename "$2" .stl).grid
  for made in "$name.samples" "$grid" "$name.dist" "$name.reverse.samples" \
    "$name.reverse.grid" "$name.reverse.dist" "$name.csv"; do
    [ -s "$out/errors/$made" ] || continue
    case $made in
      *.reverse.samples) step="reverse sample" ;;
      *.reverse.grid) step="reverse grid-build" ;;
      *.reverse.dist) step="reverse distance" ;;
      *.samples) step=sample ;;
      *.grid) step=grid-build ;;
      *.dist) step=distance ;;
      *) step=stats ;;
    esac
    line=$(grep -v '^[[:space:]]*$' "$out/errors/$made" | tail -n 1)
    echo "$step: ${line#ncverify: }"
    return
  done
  echo "no result up to date with these inputs and parameters (not run, failed or interrupted: see the batch's log)"
}

# A row with the part's name and paths, verdict `error` and the message; the measures empty.
error_row() {
  ROW_PART=$1 ROW_WORKPIECE=$parts/$1.stl ROW_NOMINAL=$2 ROW_MESSAGE=$3 \
    awk -F, -v OFS=, '
      function quoted(text) { gsub(/"/, "\"\"", text); return "\"" text "\"" }
      {
        for (i = 1; i <= NF; i++) {
          if ($i == "part") $i = quoted(ENVIRON["ROW_PART"])
          else if ($i == "workpiece") $i = quoted(ENVIRON["ROW_WORKPIECE"])
          else if ($i == "nominal") $i = quoted(ENVIRON["ROW_NOMINAL"])
          else if ($i == "verdict") $i = "error"
          else if ($i == "message") $i = quoted(ENVIRON["ROW_MESSAGE"])
          else $i = ""
        }
        print
      }' <<HEADER
$header
HEADER
}

{
  echo "$header"
  while read -r name nominal; do
    if [ ! -f "$nominal" ]; then
      error_row "$name" "$nominal" "no nominal: $nominal does not exist"
    elif up_to_date "$out/$name.csv"; then
      echo "$(cat "$out/$name.csv"),"
    else
      error_row "$name" "$nominal" "$(failed_step "$name" "$nominal")"
    fi
  done <"$parts_list"
} >"$tmp" || exit 2
mv "$tmp" "$summary" || exit 2

# The counts of each verdict, and the parts not passing, from the file itself.
awk -v summary="$summary" '
  function split_csv(line, fields,    n, i, c, field, quoted) {
    n = 0; field = ""; quoted = 0
    for (i = 1; i <= length(line); i++) {
      c = substr(line, i, 1)
      if (quoted) {
        if (c != "\"") field = field c
        else if (substr(line, i + 1, 1) == "\"") { field = field c; i++ }
        else quoted = 0
      } else if (c == "\"") quoted = 1
      else if (c == ",") { fields[++n] = field; field = "" }
      else field = field c
    }
    fields[++n] = field
    return n
  }
  NR == 1 {
    n = split_csv($0, column)
    for (i = 1; i <= n; i++) index_of[column[i]] = i
    next
  }
  {
    split_csv($0, field)
    verdict = field[index_of["verdict"]]
    if (!(verdict in count) && verdict != "pass" && verdict != "fail") order[++kinds] = verdict
    count[verdict]++
    parts++
    if (verdict != "pass") {
      not_passing++
      note = field[index_of["message"]]
      print field[index_of["part"]] ": " verdict (note == "" ? "" : ": " note) > "/dev/stderr"
    }
  }
  END {
    line = (count["pass"] + 0) " pass, " (count["fail"] + 0) " fail"
    for (k = 1; k <= kinds; k++) line = line ", " count[order[k]] " " order[k]
    if (parts == 0) line = "no workpieces"
    print "summary " summary ": " line > "/dev/stderr"
    exit (parts == 0 || not_passing > 0) ? 1 : 0
  }' "$summary"
