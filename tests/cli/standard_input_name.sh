#!/usr/bin/env bash
# One name for standard input in every message (issue 31): a bad input piped into a tool
# ("-", or no file argument) is named "standard input" -- never "stdin", "<stdin>" or "-".
# The inputs are made here: a few bytes that no reader accepts, or text with the wrong
# header for the reader at hand.
. "$(dirname "$0")/lib.sh"

printf 'garbage\001\n' >"$WORK/garbage"
printf 'a,b\n1,2\n' >"$WORK/wrong.csv"
"$FEST_BIN/lmfsim" gen chain --n 2 >"$WORK/c2.json"

# named STATUS TOOL ARGS... (standard input from $stdin_file): a one-line failure that
# names standard input as such and never by another spelling.
named() {
  local status="$1" tool="$2"; shift 2
  run_stdin "$stdin_file" "$tool" "$@"
  expect_clean_failure "$status" "$tool"
  expect_stderr_has '[(]standard input[):,]'
  check "no other spelling of standard input" bash -c "! grep -Eq '\\bstdin\\b|<stdin>|\\(-\\)' '$err'"
  check "named once" test "$(grep -o 'standard input' "$err" | wc -l)" -eq 1
  check "no library text" bash -c "! grep -Eq 'last read|json\\.exception|syntax error while parsing' '$err'"
}

stdin_file="$WORK/garbage"
case_ "lbmsim run: a case that is not JSON";            named 3 lbmsim run -
case_ "fluidsim run: a scene that is not JSON";         named 3 fluidsim run -o "$WORK/f%d.nrrd"
case_ "fluidsim render: no frame";                      named 3 fluidsim render - -o "$WORK/r.png"
case_ "fluidsim interp: no NRRD frame";                 named 3 fluidsim interp - "$WORK/garbage" --alpha 0.5 -o "$WORK/i.nrrd"
case_ "volrender mip: no volume";                       named 3 volrender mip - -o "$WORK/v.png"
case_ "isosurf exact: no volume";                       named 3 isosurf exact - --iso 0.5 -o "$WORK/s.ply"
case_ "volwave decode: no .vw stream";                  named 3 volwave decode - -o "$WORK/w.nii"
case_ "lmfsim export: no trajectory";                   named 3 lmfsim export --scene "$WORK/c2.json" --ply "$WORK/ply"
case_ "radiosity render: no mesh (was named twice)";    named 3 radiosity render - -o "$WORK/m.png"
stdin_file="$WORK/wrong.csv"
case_ "quatpath: a key table without its columns";       named 3 quatpath -
case_ "patnet markov: a transcript without its columns"; named 3 patnet markov -

finish
