#!/usr/bin/env bash
# brdffit --threads on every subcommand that takes it: a negative count is a usage error
# with the words every fest tool uses (lib/cli add_threads), before any input is read.
source "$(dirname "$0")/lib.sh"

for sub in synth lumitexels register render export fit cluster project normals factor; do
  case_ "brdffit $sub --threads -1 is a usage error"
  run brdffit "$sub" --threads -1 -o "$WORK/never"
  expect_clean_failure 2 brdffit
  expect_stderr_has "^brdffit: error: --threads must be 0 \(all cores\) or positive, not -1"
  check "$sub: nothing written" test ! -e "$WORK/never"
done

case_ "brdffit fit --threads 0 (all cores) is accepted"
printf '0,0,1,0,0,1,0.5,0.5,0.5\n0.6,0,0.8,0,0,1,0.4,0.4,0.4\n' >"$WORK/s.csv"
run brdffit fit "$WORK/s.csv" --threads 0 --starts 1 -o "$WORK/fit.json"
if [ "$rc" -ne 2 ]; then pass; else fail "exit status 2 for --threads 0"; fi

finish
