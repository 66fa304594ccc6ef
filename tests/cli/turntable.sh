#!/usr/bin/env bash
# turntable with the simulated backend (sim:): the motion policy end to end, expected
# steps from steps = round(deg / 360 * S_rev) (docs/capture.md §1), and device errors.
source "$(dirname "$0")/lib.sh"

case_ "move 90 on the default 51200-step table: 12800 steps, no overshoot going ccw"
run turntable --device sim: move 90 --settle-ms 0 --json
expect_status 0
expect_json '[.steps,.angle_deg,.overshoot]' '[12800,90,false]'

case_ "move -45 with ccw approach: overshoot then back; 3200 steps/rev -> -400"
run turntable --device sim:steps=3200 move -45 --settle-ms 0 --json
expect_status 0
expect_json '[.steps,.angle_deg,.overshoot]' '[-400,-45,true]'

case_ "cw approach: going down needs no overshoot"
run turntable --device sim:steps=3200 move -45 --approach cw --settle-ms 0 --json
expect_json '.overshoot' 'false'

case_ "executed angle: 10 deg on 1000 steps/rev = round(27.78) = 28 steps = 10.08 deg (within half a step)"
run turntable --device sim:steps=1000 move 10 --settle-ms 0 --json
expect_json '[.steps,.angle_deg]' '[28,10.08]'

case_ "--approach shortest: 350 deg is reached as -10 deg"
run turntable --device sim:steps=3600 move 350 --approach shortest --settle-ms 0 --json
expect_json '[.steps,.overshoot]' '[-100,false]'

case_ "text output and --no-wait"
run turntable --device sim:steps=3600 move 36 --settle-ms 0
expect_status 0
check "text names degrees and steps" grep -q '^36.0000 deg (360 steps)$' "$out"
run turntable --device sim:steps=3600 move 36 --no-wait --json
expect_json '[.steps,.waited]' '[360,false]'

case_ "info, status, list, home, stop, zero, enable, disable"
run turntable --device sim:steps=3200 info --json
expect_json '[.steps_per_rev,.max_speed]' '[3200,800]'
run turntable --device sim: status --json
expect_json '[.position_steps,.state,.homed]' '[0,"idle",true]'
run turntable --device sim: list
expect_status 0
run turntable --device sim: home --json
expect_json '.homed' 'true'
for c in "stop" "stop --now" "zero" "enable" "disable"; do
  # shellcheck disable=SC2086
  run turntable --device sim: $c; expect_status 0; expect_stdout_empty
done

case_ "the station's turntable.uri is the default device"
echo '{"turntable": {"uri": "sim:steps=360"}, "lights": []}' >"$WORK/st.json"
run turntable --station "$WORK/st.json" move 7 --settle-ms 0 --json
expect_json '.steps' '7'
CAPTURE_STATION="$WORK/st.json" run turntable move 7 --settle-ms 0 --json
expect_json '.steps' '7'

case_ "a move that never completes times out: exit 7, STOP sent"
run turntable --device sim:fail_at=1 move 10 --settle-ms 0
expect_clean_failure 7 turntable
expect_stderr_has 'did not reach step'

case_ "device unplugged mid-move: exit 5"
run turntable --device sim:unplug_at=4 move 10 --settle-ms 0
expect_clean_failure 5 turntable
expect_stderr_has 'unplugged'

case_ "usage errors: bad URI, unknown sim key, unsupported scheme, bad approach, NaN angle"
run turntable --device gpiochip0 info; expect_clean_failure 2 turntable
run turntable --device sim:warp=9 info; expect_clean_failure 2 turntable
run turntable --device grbl:/dev/ttyACM0 info; expect_clean_failure 2 turntable
run turntable --device sim: move 10 --approach up; expect_clean_failure 2 turntable
run turntable --device sim: move nan; expect_clean_failure 2 turntable
run turntable --device usb:12345:1 info; expect_clean_failure 2 turntable
run turntable --device sim:; expect_clean_failure 2 turntable

case_ "a broken station file: exit 3"
printf '{"turntable": ' >"$WORK/bad.json"
run turntable --station "$WORK/bad.json" info
expect_clean_failure 3 turntable

case_ "conventions: --help, --version, unknown flag, missing subcommand"
run turntable --help; expect_status 0
check "help names the subcommands" grep -q "Subcommands" "$out"
run turntable --version; expect_status 0
check "version names fest" grep -q "(fest)" "$out"
run turntable --no-such-flag; expect_clean_failure 2 turntable
run turntable; expect_clean_failure 2 turntable

finish
