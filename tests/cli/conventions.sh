#!/usr/bin/env bash
# The behaviour README "Conventions" asks of every tool: --help and --version succeed on standard
# output; a wrong flag is status 2 with one line; a missing file is status 4.
. "$(dirname "$0")/lib.sh"

for tool in fconv fcompare; do
  case_ "$tool --help"
  run "$tool" --help
  expect_status 0
  check "$tool --help prints usage" grep -q "Usage" "$out"

  case_ "$tool --version"
  run "$tool" --version
  expect_status 0
  check "$tool --version names fest" grep -q "(fest)" "$out"

  case_ "$tool unknown flag"
  run "$tool" --no-such-flag x y
  expect_clean_failure 2 "$tool"

  case_ "$tool missing file"
  if [ "$tool" = fcompare ]; then
    run "$tool" "$WORK/does-not-exist" "$WORK/does-not-exist-either"
  else
    run "$tool" "$WORK/does-not-exist"
  fi
  expect_clean_failure 4 "$tool"
  expect_stderr_has "does-not-exist"
done

finish
