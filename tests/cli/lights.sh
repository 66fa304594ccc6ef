#!/usr/bin/env bash
# lights with simulated lights and station.json handling (no device needed).
source "$(dirname "$0")/lib.sh"

cat >"$WORK/sim.json" <<'JSON'
{ "camera": {"uri": "sim:scene.json"},
  "lights": [ {"id": "L0", "uri": "sim:", "position_mm": [412.0, -80.5, 350.2], "intensity": [1, 0.97, 0.91],
               "warmup_ms": 300, "max_on_s": 120},
              {"id": "BG", "uri": "sim:", "role": "backlight"} ] }
JSON

case_ "list: id,uri,state CSV in the station's order"
run lights --station "$WORK/sim.json" list
expect_status 0
check "list CSV" diff <(printf '%s\n' 'id,uri,state' 'L0,sim:,off' 'BG,sim:,off') "$out"

case_ "CAPTURE_STATION names the station when --station is absent"
CAPTURE_STATION="$WORK/sim.json" run lights list
expect_status 0

case_ "on / off / only / pulse / hold on simulated lights"
for cmd in "on L0 BG" "off L0" "off --all" "only BG" "pulse L0 --ms 5" "hold L0 --time 0.02"; do
  # shellcheck disable=SC2086
  run lights --station "$WORK/sim.json" $cmd
  expect_status 0; expect_stdout_empty
done

case_ "unknown light id: usage error"
run lights --station "$WORK/sim.json" on L7
expect_clean_failure 2 lights
expect_stderr_has "no light 'L7'"

case_ "off needs ids or --all"
run lights --station "$WORK/sim.json" off
expect_clean_failure 2 lights

case_ "no station at all"
env -u CAPTURE_STATION "$FEST_BIN/lights" list >"$out" 2>"$err"; rc=$?
expect_clean_failure 2 lights
expect_stderr_has 'CAPTURE_STATION'

case_ "mixed kinds in one bank: usage error"
cat >"$WORK/mixed.json" <<'JSON'
{"lights": [{"id": "A", "uri": "sim:"}, {"id": "B", "uri": "gpio:chip=gpiochip0,line=3"}]}
JSON
run lights --station "$WORK/mixed.json" only A
expect_clean_failure 2 lights
expect_stderr_has 'one bank must be all gpio:, all usb-aux: or all sim:'

case_ "unknown key inside a light: bad input naming key and JSON path"
cat >"$WORK/typo.json" <<'JSON'
{"lights": [{"id": "A", "uri": "sim:"}, {"id": "B", "uri": "sim:", "actve_low": true}]}
JSON
run lights --station "$WORK/typo.json" list
expect_clean_failure 3 lights
expect_stderr_has 'unknown key "actve_low".*/lights/1'

case_ "station errors: not JSON (3), missing file (4), no lights array (3), duplicate id (3), bad active_low (3)"
printf '{"lights": [' >"$WORK/trunc.json"
run lights --station "$WORK/trunc.json" list; expect_clean_failure 3 lights
run lights --station "$WORK/nope.json" list; expect_clean_failure 4 lights
echo '{"camera": {}}' >"$WORK/nolights.json"
run lights --station "$WORK/nolights.json" list; expect_clean_failure 3 lights
echo '{"lights": [{"id": "A", "uri": "sim:"}, {"id": "A", "uri": "sim:"}]}' >"$WORK/dup.json"
run lights --station "$WORK/dup.json" list; expect_clean_failure 3 lights
echo '{"lights": [{"id": "A", "uri": "sim:", "active_low": "yes"}]}' >"$WORK/low.json"
run lights --station "$WORK/low.json" list; expect_clean_failure 3 lights

case_ "bad light URIs: usage errors"
echo '{"lights": [{"id": "A", "uri": "gpio:chip=gpiochip0"}]}' >"$WORK/u1.json"
run lights --station "$WORK/u1.json" on A; expect_clean_failure 2 lights
echo '{"lights": [{"id": "A", "uri": "exec:lampctl on"}]}' >"$WORK/u2.json"
run lights --station "$WORK/u2.json" on A; expect_clean_failure 2 lights
echo '{"lights": [{"id": "A", "uri": "sim:speed=3"}]}' >"$WORK/u3.json"
run lights --station "$WORK/u3.json" on A; expect_clean_failure 2 lights

case_ "pulse needs --ms"
run lights --station "$WORK/sim.json" pulse L0
expect_clean_failure 2 lights

case_ "conventions: --help, --version, unknown flag, missing subcommand"
run lights --help; expect_status 0
check "help names the subcommands" grep -q "Subcommands" "$out"
run lights --version; expect_status 0
check "version names fest" grep -q "(fest)" "$out"
run lights --no-such-flag; expect_clean_failure 2 lights
run lights; expect_clean_failure 2 lights

finish
