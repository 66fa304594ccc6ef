# Helpers for fest's end-to-end CLI tests; every tests/cli/*.sh sources this file.
#
#   run fconv --to off in.ply        # runs bin/fconv; sets $rc, $out (stdout file), $err
#   run_stdin file fconv --to off    # the same with standard input from a file
#   expect_status 3                  # checks $rc
#   expect_clean_failure 3           # $rc, exactly one "tool: error: ..." line, no stdout
#   expect_stdout_empty / expect_stderr_has REGEX / expect_json '.vertices' 4
#   check "what" COMMAND...          # any command that must succeed
#   f=$(need_testdata meshes/bunny00.off) || exit 77   # a fetched file, or skip
#   finish                           # prints "N passed, N failed", sets the exit status
#
# Environment (set by CTest): FEST_BIN (folder of the executables), FEST_TESTDATA (real
# data from scripts/fetch-test-data.sh), FEST_FIXTURES (tests/data).
set -u
: "${FEST_BIN:?FEST_BIN must name the folder of the fest executables}"
: "${FEST_FIXTURES:=$(cd "$(dirname "${BASH_SOURCE[0]}")/../data" && pwd)}"
: "${FEST_TESTDATA:=${XDG_CACHE_HOME:-$HOME/.cache}/fest/testdata}"

WORK=$(mktemp -d "${TMPDIR:-/tmp}/fest-cli.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
out="$WORK/stdout"
err="$WORK/stderr"
rc=0
passed=0
failed=0
current=""

# Names the case that the following checks belong to (shown on failure).
case_() { current="$*"; }

pass() { passed=$((passed + 1)); }
fail() {
  failed=$((failed + 1))
  echo "FAIL [$current]: $*" >&2
  if [ -s "$err" ]; then sed 's/^/    stderr: /' "$err" | head -5 >&2; fi
}

run() {
  local tool="$1"; shift
  "$FEST_BIN/$tool" "$@" >"$out" 2>"$err"
  rc=$?
}

run_stdin() {
  local input="$1" tool="$2"; shift 2
  "$FEST_BIN/$tool" "$@" <"$input" >"$out" 2>"$err"
  rc=$?
}

expect_status() {
  if [ "$rc" -eq "$1" ]; then pass; else fail "exit status $rc, expected $1"; fi
}

expect_stdout_empty() {
  if [ ! -s "$out" ]; then pass; else fail "standard output is not empty ($(wc -c <"$out") bytes)"; fi
}

expect_stderr_has() {
  if grep -Eq -- "$1" "$err"; then pass; else fail "standard error lacks /$1/: $(head -c 300 "$err")"; fi
}

# A failure the way README "Conventions" wants it: the status, one diagnostic line naming the
# tool, and nothing on standard output.
expect_clean_failure() {
  local status="$1" tool="${2:-}"
  expect_status "$status"
  expect_stdout_empty
  local lines
  lines=$(wc -l <"$err")
  if [ "$lines" -eq 1 ]; then pass; else fail "standard error has $lines lines, expected 1"; fi
  if [ -n "$tool" ]; then expect_stderr_has "^$tool: error: "; fi
}

# expect_json FILTER VALUE: jq's output for the JSON on standard output equals VALUE.
expect_json() {
  local got
  got=$(jq -c "$1" "$out" 2>/dev/null)
  if [ "$got" = "$2" ]; then pass; else fail "jq '$1' gave '$got', expected '$2'"; fi
}

check() {
  local what="$1"; shift
  if "$@" >/dev/null 2>&1; then pass; else fail "$what"; fi
}

# need_testdata REL: prints the path; exits 77 (CTest "skipped") when data is missing.
need_testdata() {
  if [ ! -f "$FEST_TESTDATA/MANIFEST" ] || [ ! -f "$FEST_TESTDATA/$1" ]; then
    echo "skipped: real test data not fetched (scripts/fetch-test-data.sh); needs $1" >&2
    exit 77
  fi
  echo "$FEST_TESTDATA/$1"
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}
