# pair() of the progress tests (progress_everywhere.sh, progress_realdata.sh): one command
# with and without --progress, each in a folder of its own; sourced after lib.sh.

# pair NAME [--stdin FILE] [--norm JQ] TOOL ARGS...: the command in $WORK/NAME.bar with
# --progress appended and in $WORK/NAME.plain without; both must succeed. --norm: standard
# output is JSON compared after this jq filter (timestamps); files are compared with cmp.
pair() {
  local name="$1"; shift
  local stdin=/dev/null norm=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --stdin) stdin="$2"; shift 2 ;;
      --norm) norm="$2"; shift 2 ;;
      *) break ;;
    esac
  done
  local mode extra d
  for mode in bar plain; do
    d="$WORK/$name.$mode"
    mkdir -p "$d"
    if [ -n "${SETUP:-}" ]; then (cd "$d" && eval "$SETUP"); fi
    extra=()
    if [ "$mode" = bar ]; then extra=(--progress); fi
    (cd "$d" && "$FEST_BIN/$1" "${@:2}" "${extra[@]}" <"$stdin" >"$WORK/$name.$mode.out" 2>"$WORK/$name.$mode.err")
    echo $? >"$WORK/$name.$mode.rc"
  done
  case_ "$name: --progress draws a bar to 100 %, nothing without it, the same output"
  err="$WORK/$name.bar.err"
  check "exit 0 with --progress ($(cat "$WORK/$name.bar.rc"))" test "$(cat "$WORK/$name.bar.rc")" = 0
  check "exit 0 without ($(cat "$WORK/$name.plain.rc"))" test "$(cat "$WORK/$name.plain.rc")" = 0
  check "a bar that reaches 100 %" grep -Eq '\[#+\] 100%' "$err"
  check "redrawn in place (carriage return)" grep -q $'\r' "$err"
  err="$WORK/$name.plain.err"
  check "no bar without --progress" bash -c "! grep -Eq '\] +[0-9]+%' '$err' && ! grep -q $'\r' '$err'"
  if [ -n "$norm" ]; then
    check "same standard output (jq '$norm')" cmp <(jq -S "$norm" "$WORK/$name.bar.out") <(jq -S "$norm" "$WORK/$name.plain.out")
  else
    check "same standard output" cmp "$WORK/$name.bar.out" "$WORK/$name.plain.out"
  fi
  check "same files" diff -r ${DIFF_EXCLUDE:-} "$WORK/$name.bar" "$WORK/$name.plain"
}
