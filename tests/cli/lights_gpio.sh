#!/usr/bin/env bash
# lights' real libgpiod backend without hardware (docs/lights.md §4): the unmodified
# binary runs with umockdev's preload library and tests/tools/gpiomock (an emulated
# gpiochip0 with 32 lines GPIO0..GPIO31) preloaded; the mock logs every line request and
# write with the physical level, and the cases compare that log with the sequence the
# command must produce. Skips (77) without umockdev.
source "$(dirname "$0")/lib.sh"
command -v umockdev-wrapper >/dev/null 2>&1 || { echo "skipped: umockdev not installed (apt-get install umockdev)"; exit 77; }
[ -f "$FEST_BIN/libgpiomock.so" ] || { echo "skipped: libgpiomock.so not built (needs libumockdev-dev)"; exit 77; }
export ASAN_OPTIONS=verify_asan_link_order=0
LOG="$WORK/gpio.log"

cat >"$WORK/station.json" <<'JSON'
{ "lights": [
  {"id": "L0", "uri": "gpio:chip=gpiochip0,line=GPIO17", "warmup_ms": 300},
  {"id": "L1", "uri": "gpio:chip=gpiochip0,line=5", "active_low": true},
  {"id": "BG", "uri": "gpio:chip=gpiochip0,line=GPIO27,active_low", "role": "backlight"} ] }
JSON

# Run lights on the mock chip (umockdev-wrapper's preload, then the mock); extra
# environment for the mock goes before the command: mock [VAR=VALUE...] ARGS...
mock() {
  local envs=()
  while [[ "${1:-}" == GPIOMOCK_*=* ]]; do envs+=("$1"); shift; done
  rm -f "$LOG"
  env GPIOMOCK=1 GPIOMOCK_LOG="$LOG" "${envs[@]}" LD_PRELOAD="libumockdev-preload.so.0:$FEST_BIN/libgpiomock.so" \
    "$FEST_BIN/lights" --station "${STATION:-$WORK/station.json}" "$@" >"$out" 2>"$err"
  rc=$?
}
expect_log() {
  local want; want=$(printf '%s\n' "$@")
  if [ "$(cat "$LOG" 2>/dev/null)" = "$want" ]; then pass; else fail "line log: $(tr '\n' '|' <"$LOG" 2>/dev/null), expected $(tr '\n' '|' <<<"$want")"; fi
}

case_ "on L0 (line by name): requested lit, left as set on exit"
mock on L0
expect_status 0; expect_stdout_empty
expect_log "request 17 GPIO17 1"

case_ "on L1 (line by offset, active-low): lit = physical 0"
mock on L1
expect_status 0
expect_log "request 5 GPIO5 0"

case_ "only BG: BG lit (active-low via the URI), every other light requested off"
mock only BG
expect_status 0
expect_log "request 17 GPIO17 0" "request 5 GPIO5 1" "request 27 GPIO27 0"

case_ "off --all: every line requested at its off level"
mock off --all
expect_status 0
expect_log "request 17 GPIO17 0" "request 5 GPIO5 1" "request 27 GPIO27 1"

case_ "pulse L0 --ms 20: on, then off before release"
mock pulse L0 --ms 20
expect_status 0
expect_log "request 17 GPIO17 1" "set 17 GPIO17 0"

case_ "hold L0 L1 --time 0.05: both on, both off at the end"
mock hold L0 L1 --time 0.05
expect_status 0
expect_log "request 17 GPIO17 1" "request 5 GPIO5 0" "set 17 GPIO17 0" "set 5 GPIO5 1"

case_ "hold L0 until SIGTERM: off before exit, status 0"
rm -f "$LOG"
env GPIOMOCK=1 GPIOMOCK_LOG="$LOG" LD_PRELOAD="libumockdev-preload.so.0:$FEST_BIN/libgpiomock.so" \
  "$FEST_BIN/lights" --station "$WORK/station.json" hold L0 >"$out" 2>"$err" &
pid=$!
for _ in $(seq 100); do grep -q request "$LOG" 2>/dev/null && break; sleep 0.05; done
kill -TERM "$pid"; wait "$pid"; rc=$?
expect_status 0
expect_log "request 17 GPIO17 1" "set 17 GPIO17 0"

case_ "list: line state without requesting (nothing written)"
mock GPIOMOCK_BUSY=27:gpio-fan list
expect_status 0
check "list CSV" diff <(printf '%s\n' 'id,uri,state' 'L0,"gpio:chip=gpiochip0,line=GPIO17",free' \
  'L1,"gpio:chip=gpiochip0,line=5",free' 'BG,"gpio:chip=gpiochip0,line=GPIO27,active_low",used by gpio-fan') "$out"
check "list requests nothing" test ! -s "$LOG"

case_ "line busy (EBUSY): exit 6 naming the consumer; lines already taken released off"
mock GPIOMOCK_BUSY=27:gpio-fan only L0
expect_clean_failure 6 lights
expect_stderr_has "BG: gpiochip0 line 27 \(GPIO27\) is busy, held by 'gpio-fan'"

case_ "permission denied on the chip: exit 8 naming the gpio group and udev rule"
mock GPIOMOCK_DENY=1 on L0
expect_clean_failure 8 lights
expect_stderr_has 'gpio group.*udev rule'

case_ "busy line after a lit one: the lit line is switched off again before exit"
cat >"$WORK/s4.json" <<'JSON'
{"lights": [{"id": "BG", "uri": "gpio:chip=gpiochip0,line=GPIO27"}, {"id": "L0", "uri": "gpio:line=GPIO17"}]}
JSON
STATION="$WORK/s4.json" mock GPIOMOCK_BUSY=17:gpio-fan only BG
expect_clean_failure 6 lights
expect_log "request 27 GPIO27 1" "set 27 GPIO27 0"

case_ "missing chip: exit 5"
cat >"$WORK/s2.json" <<'JSON'
{"lights": [{"id": "X", "uri": "gpio:chip=gpiochip7,line=1"}]}
JSON
STATION="$WORK/s2.json" mock on X
expect_clean_failure 5 lights
expect_stderr_has 'no GPIO chip gpiochip7'

case_ "missing line name / offset: exit 5"
cat >"$WORK/s3.json" <<'JSON'
{"lights": [{"id": "X", "uri": "gpio:chip=gpiochip0,line=LIGHT9"}, {"id": "Y", "uri": "gpio:line=40"}]}
JSON
STATION="$WORK/s3.json" mock on X
expect_clean_failure 5 lights
expect_stderr_has 'no line named LIGHT9'
STATION="$WORK/s3.json" mock on Y
expect_clean_failure 5 lights
expect_stderr_has 'has no line 40 \(it has 32 lines\)'

finish
