#!/usr/bin/env bash
# turntable's gpio-stepper backend (step/dir driver on GPIO lines, libgpiod v1) on the
# emulated gpiochip of tests/tools/gpiomock (docs/lights.md §4): pulse counts and the
# order of DIR and STEP writes are asserted, not the timing. Skips (77) without umockdev.
source "$(dirname "$0")/lib.sh"
command -v umockdev-wrapper >/dev/null 2>&1 || { echo "skipped: umockdev not installed (apt-get install umockdev)"; exit 77; }
[ -f "$FEST_BIN/libgpiomock.so" ] || { echo "skipped: libgpiomock.so not built (needs libumockdev-dev)"; exit 77; }
export ASAN_OPTIONS=verify_asan_link_order=0
LOG="$WORK/gpio.log"
# 200 steps/rev: 90 deg = 50 steps, 2 deg of backlash margin = round(1.11) = 1 step.
DEV="gpio-stepper:chip=gpiochip0,step=17,dir=GPIO27,en=22,home=23,steps=200,speed=4000,accel=40000"

mock() {
  local envs=()
  while [[ "${1:-}" == GPIOMOCK_*=* ]]; do envs+=("$1"); shift; done
  rm -f "$LOG"
  env GPIOMOCK=1 GPIOMOCK_LOG="$LOG" "${envs[@]}" LD_PRELOAD="libumockdev-preload.so.0:$FEST_BIN/libgpiomock.so" \
    "$FEST_BIN/turntable" "$@" >"$out" 2>"$err"
  rc=$?
}
pulses() { grep -c '^set 17 GPIO17 1$' "$LOG"; }
expect_pulses() { local n; n=$(pulses); if [ "$n" = "$1" ]; then pass; else fail "$n STEP pulses, expected $1"; fi; }
# Line number in the log of the first match of a pattern.
first() { grep -n -m1 -- "$1" "$LOG" | cut -d: -f1; }

case_ "lines requested: STEP and DIR low, EN enabled (active low: physical 0), HOME as input"
mock --device "$DEV" status --json
expect_status 0
check "requests" diff <(printf '%s\n' 'request 17 GPIO17 0' 'request 27 GPIO27 0' 'request 22 GPIO22 0' 'request-input 23 GPIO23 0') "$LOG"

case_ "move 90: 50 pulses, DIR raised (ccw) before the first STEP edge, every pulse back low"
mock --device "$DEV" move 90 --settle-ms 0 --json
expect_status 0
expect_json '[.steps,.angle_deg]' '[50,90]'
expect_pulses 50
check "50 falling STEP edges" test "$(grep -c '^set 17 GPIO17 0$' "$LOG")" = 50
d=$(first '^set 27 GPIO27 1$'); s=$(first '^set 17 GPIO17 1$')
if [ -n "$d" ] && [ -n "$s" ] && [ "$d" -lt "$s" ]; then pass; else fail "DIR (line $d) not before STEP (line $s)"; fi

case_ "move -45 with ccw approach: 26 steps cw (DIR stays low), then 1 step ccw"
mock --device "$DEV" move -45 --settle-ms 0 --json
expect_json '[.steps,.overshoot]' '[-25,true]'
expect_pulses 27
check "DIR goes high once" test "$(grep -c '^set 27' "$LOG")" = 1
d=$(first '^set 27 GPIO27 1$')
check "26 pulses before the DIR change" test "$(head -n "${d:-0}" "$LOG" | grep -c '^set 17 GPIO17 1$')" = 26

case_ "home: steps until the switch closes after 30 pulses; position 0, homed"
mock GPIOMOCK_HOME=23:17:30 --device "$DEV" home --json
expect_status 0
expect_json '[.homed,.position_steps,.state]' '[true,0,"idle"]'
expect_pulses 30

case_ "home --cw: DIR stays low"
mock GPIOMOCK_HOME=23:17:5 --device "$DEV" home --cw
expect_status 0
check "no DIR write" test "$(grep -c '^set 27' "$LOG")" = 0

case_ "no home switch found within 1.1 turns (221 steps): fault 2, exit 6"
mock --device "$DEV" home
expect_clean_failure 6 turntable
expect_stderr_has 'fault 2 \(home switch not found\)'
expect_pulses 221

case_ "disable: EN inactive (physical 1)"
mock --device "$DEV" disable
expect_status 0
check "EN written high" grep -q '^set 22 GPIO22 1$' "$LOG"

case_ "STEP line busy: exit 6 naming the holder"
mock GPIOMOCK_BUSY=17:pigpio --device "$DEV" status
expect_clean_failure 6 turntable
expect_stderr_has "STEP: gpiochip0 line 17 \(GPIO17\) is busy, held by 'pigpio'"

case_ "no home line configured: home is a device error"
mock --device "gpio-stepper:step=17,dir=27,steps=200" home
expect_clean_failure 6 turntable

case_ "URI errors: missing dir, unknown key, zero steps"
mock --device "gpio-stepper:step=17" info; expect_clean_failure 2 turntable
mock --device "gpio-stepper:step=17,dir=27,micro=16" info; expect_clean_failure 2 turntable
mock --device "gpio-stepper:step=17,dir=27,steps=0" info; expect_clean_failure 2 turntable

finish
