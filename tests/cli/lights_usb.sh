#!/usr/bin/env bash
# lights on the aux outputs of a TTP/1 controller (usb-aux:N, SET_AUX) through the real
# libusb backend, replayed by umockdev-run from tests/tools/ttp_mockdev's pcap: the
# exact SET_AUX mask/values each command sends is asserted by the strict replay.
source "$(dirname "$0")/lib.sh"
command -v umockdev-run >/dev/null 2>&1 || { echo "skipped: umockdev-run not installed (apt-get install umockdev)"; exit 77; }
[ -x "$FEST_BIN/ttp_mockdev" ] || { echo "skipped: ttp_mockdev not built"; exit 77; }
export ASAN_OPTIONS=verify_asan_link_order=0

cat >"$WORK/station.json" <<'JSON'
{ "turntable": {"uri": "usb:1209:0001"},
  "lights": [ {"id": "L0", "uri": "usb-aux:0"}, {"id": "L1", "uri": "usb-aux:2,usb=1209:0001#MOCK0001"},
              {"id": "BG", "uri": "usb-aux:3"} ] }
JSON
INFO=info:aux=4,name=Dome
device() { sysfs=$("$FEST_BIN/ttp_mockdev" "$WORK/tt" "$@") || fail "ttp_mockdev $*"; }
lt() {
  umockdev-run --device "$WORK/tt.umockdev" --pcap "$sysfs=$WORK/tt.pcap" -- \
    "$FEST_BIN/lights" --station "$WORK/station.json" "$@" >"$out" 2>"$err"
  rc=$?
}
expect_tool_error() {
  expect_status "$1"; expect_stdout_empty
  local n; n=$(grep -c '^lights: error: ' "$err")
  if [ "$n" -eq 1 ]; then pass; else fail "expected one 'lights: error:' line, got $n"; fi
  expect_stderr_has "$2"
}

# Outputs 0, 2, 3 = bits 0x1, 0x4, 0x8.
case_ "on L0 BG: one SET_AUX(mask 0x9, values 0x9), left on"
device "$INFO" set_aux:mask=0x9,values=0x9
lt on L0 BG
expect_status 0; expect_stdout_empty

case_ "only L1: SET_AUX(mask 0xd, values 0x4)"
device "$INFO" set_aux:mask=0xd,values=0x4
lt only L1
expect_status 0

case_ "pulse L1: on, then off before exit"
device "$INFO" set_aux:mask=0x4,values=0x4 set_aux:mask=0x4,values=0
lt pulse L1 --ms 5
expect_status 0

case_ "hold L0 --time: on, all of the bank off at the end"
device "$INFO" set_aux:mask=0x1,values=0x1 set_aux:mask=0x1,values=0
lt hold L0 --time 0.05
expect_status 0

case_ "off --all: SET_AUX(mask 0xd, values 0)"
device "$INFO" set_aux:mask=0xd,values=0
lt off --all
expect_status 0

case_ "list: no request at all (TTP/1 cannot read aux outputs back)"
device
lt list
expect_status 0
check "list CSV" diff <(printf '%s\n' 'id,uri,state' 'L0,usb-aux:0,unknown' 'L1,"usb-aux:2,usb=1209:0001#MOCK0001",unknown' 'BG,usb-aux:3,unknown') "$out"

case_ "controller with only 2 aux outputs: exit 5 naming the output"
device info:aux=2,name=Dome
lt on BG
expect_tool_error 5 'no aux output 3 \(it has 2\)'

case_ "SET_AUX refused (STALL): exit 6 with the fault code"
device "$INFO" set_aux:mask=0x1,values=0x1,!stall status:state=fault,fault=4
lt on L0
expect_tool_error 6 'refused SET_AUX \(STALL\): fault 4 \(e-stop input\)'

case_ "controller unplugged: exit 5"
device "$INFO" set_aux:mask=0x1,values=0x1,!gone
lt on L0
expect_tool_error 5 'unplugged'

case_ "bad usb-aux URIs: usage errors"
echo '{"lights": [{"id": "A", "uri": "usb-aux:16"}]}' >"$WORK/b1.json"
run lights --station "$WORK/b1.json" on A; expect_clean_failure 2 lights
echo '{"lights": [{"id": "A", "uri": "usb-aux:1,dev=1"}]}' >"$WORK/b2.json"
run lights --station "$WORK/b2.json" on A; expect_clean_failure 2 lights
echo '{"lights": [{"id": "A", "uri": "usb-aux:1"}, {"id": "B", "uri": "usb-aux:1"}]}' >"$WORK/b3.json"
run lights --station "$WORK/b3.json" only A; expect_clean_failure 2 lights
echo '{"lights": [{"id": "A", "uri": "usb-aux:1"}, {"id": "B", "uri": "usb-aux:2,usb=1209:0002"}]}' >"$WORK/b4.json"
run lights --station "$WORK/b4.json" only A; expect_clean_failure 2 lights

finish
