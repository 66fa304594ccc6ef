#!/usr/bin/env bash
# turntable's real libusb backend without hardware (docs/turntable.md §4): umockdev-run
# replays a TTP/1 device from a .umockdev description and a usbmon pcap written by
# tests/tools/ttp_mockdev. Replay is strictly in order and OUT data is compared byte for
# byte, so each case also asserts the exact request sequence the tool sends (a deviation
# shows up as a 1000 ms transfer timeout, exit 7). Skips (77) without umockdev-run.
source "$(dirname "$0")/lib.sh"
command -v umockdev-run >/dev/null 2>&1 || { echo "skipped: umockdev-run not installed (apt-get install umockdev)"; exit 77; }
[ -x "$FEST_BIN/ttp_mockdev" ] || { echo "skipped: ttp_mockdev not built"; exit 77; }
export ASAN_OPTIONS=verify_asan_link_order=0   # ASan behind umockdev's LD_PRELOAD

# device EXCHANGE... : writes the replay; then `tt ARGS...` runs turntable against it.
device() { sysfs=$("$FEST_BIN/ttp_mockdev" "$WORK/tt" "$@") || { fail "ttp_mockdev $*"; }; }
tt() {
  umockdev-run --device "$WORK/tt.umockdev" --pcap "$sysfs=$WORK/tt.pcap" -- \
    "$FEST_BIN/turntable" --device usb: "$@" >"$out" 2>"$err"
  rc=$?
}
# umockdev itself may print "Replay may be stuck" notes: our own message is one line.
expect_tool_error() {
  expect_status "$1"; expect_stdout_empty
  local n; n=$(grep -c '^turntable: error: ' "$err")
  if [ "$n" -eq 1 ]; then pass; else fail "expected one 'turntable: error:' line, got $n"; fi
  expect_stderr_has "$2"
}

# 3200 steps/rev: 90 deg = 800 steps; max speed 1600 steps/s = 400 in wValue (steps/s / 4).
INFO=info:steps=3200,speed=1600,accel=4000,name=Mock-table

case_ "info: GET_INFO decoded field by field"
device "$INFO"
tt info --json
expect_status 0
expect_json '[.name,.serial,.steps_per_rev,.max_speed,.max_accel,.has_home]' '["Mock-table","MOCK0001",3200,1600,4000,true]'

case_ "list: iProduct and iSerialNumber through the string descriptors"
device
tt list
expect_status 0
check "list names the serial URI" grep -q '^usb:1209:0001#MOCK0001' "$out"

case_ "status: GET_STATUS fields"
device "$INFO" status:pos=-400,target=-400,state=idle,homed=1,switch=1,seq=7
tt status --json
expect_status 0
expect_json '[.position_steps,.angle_deg,.state,.homed,.home_switch,.seq,.fault]' '[-400,-45,"idle",true,true,7,0]'

case_ "home: HOME cw, polled until idle and homed"
device "$INFO" home:cw status:state=homing status:state=homing,pos=-50 status:state=idle,homed=1,switch=1
tt home --cw --json
expect_status 0
expect_json '[.state,.homed]' '["idle",true]'

case_ "move 90: MOVE_ABS 800 at max speed, 3 status polls until idle at target"
device "$INFO" status:pos=0 status:pos=0 status:pos=0 move_abs:800,speed=1600 \
  status:pos=300,target=800,state=moving status:pos=700,target=800,state=moving status:pos=800,target=800,seq=1
tt move 90 --settle-ms 0 --json
expect_status 0
expect_json '[.steps,.angle_deg,.overshoot]' '[800,90,false]'

case_ "move -90 from 0 with ccw approach: overshoot 2 deg (18 steps) below, come back up"
device "$INFO" status:pos=0 status:pos=0 move_abs:-818,speed=1600 status:pos=-818,target=-818 \
  status:pos=-818,target=-818 status:pos=-818,target=-818 move_abs:-800,speed=1600 status:pos=-800,target=-800
tt move -90 --settle-ms 0 --json
expect_status 0
expect_json '[.steps,.overshoot]' '[-800,true]'

case_ "stop --now, zero, disable: STOP(1), SET_ZERO, ENABLE(0)"
device "$INFO" stop:now
tt stop --now; expect_status 0
device "$INFO" zero
tt zero; expect_status 0
device "$INFO" enable:0
tt disable; expect_status 0

case_ "stall: MOVE_ABS refused -> GET_STATUS fault code, exit 6"
device "$INFO" status:pos=0 status:pos=0 status:pos=0 move_abs:800,speed=1600,!stall status:state=fault,fault=1,stalled=1
tt move 90 --settle-ms 0
expect_tool_error 6 'refused MOVE_ABS \(STALL\): fault 1 \(stall detected\)'

case_ "fault reported while moving -> exit 6"
device "$INFO" status:pos=0 status:pos=0 status:pos=0 move_abs:800,speed=1600 status:pos=310,target=800,state=fault,fault=3
tt move 90 --settle-ms 0
expect_tool_error 6 'fault 3'

case_ "HOME stalls (no home switch found) -> exit 6 with fault 2"
device "$INFO" home:!stall status:state=fault,fault=2
tt home
expect_tool_error 6 'fault 2 \(home switch not found\)'

case_ "unplug mid-move (completion status -19) -> exit 5"
device "$INFO" status:pos=0 status:pos=0 status:pos=0 move_abs:800,speed=1600 status:pos=300,target=800,state=moving,!gone
tt move 90 --settle-ms 0
expect_tool_error 5 'unplugged'

case_ "device does not answer GET_STATUS -> transfer timeout (1000 ms), exit 7"
device "$INFO"
tt status
expect_tool_error 7 'did not answer GET_STATUS within 1000 ms'

case_ "short GET_STATUS reply -> exit 6 'short reply 12/16'"
device "$INFO" status:!short=12
tt status
expect_tool_error 6 'short reply 12/16'

case_ "GET_INFO from a protocol 1 device with a truncated reply -> exit 6"
device info:!short=40
tt info
expect_tool_error 6 'short reply 40/64'

case_ "a 1209:0001 device that is not TTP/1 (iProduct) -> exit 5"
device --product "Some other gadget"
tt info
expect_tool_error 5 'not a TTP/1 device'

case_ "device node not accessible -> exit 8 naming the udev rule and the plugdev group"
# The replayed node is made unreadable; root ignores file modes, so as root the case
# runs as nobody (setpriv), on copies of the replay files that nobody can read.
device "$INFO"
pdir=$(mktemp -d "${TMPDIR:-/tmp}/fest-ttp-perm.XXXXXX")
chmod 755 "$pdir"; cp "$WORK/tt.umockdev" "$WORK/tt.pcap" "$pdir"/; chmod 644 "$pdir"/*
as_user=()
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1; then
  as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups --inh-caps=-all --bounding-set=-all env HOME=/tmp TMPDIR=/tmp)
fi
if [ "$(id -u)" != 0 ] || [ ${#as_user[@]} -gt 0 ]; then
  "${as_user[@]}" umockdev-run --device "$pdir/tt.umockdev" --pcap "$sysfs=$pdir/tt.pcap" -- \
    sh -c 'chmod 000 "$UMOCKDEV_DIR/dev/bus/usb/001/002" && exec "$0" --device usb: info' "$FEST_BIN/turntable" >"$out" 2>"$err"
  rc=$?
  expect_tool_error 8 'permission denied.*70-ttp.rules.*plugdev group'
else
  echo "note: permission case not run (root without setpriv)"
fi
rm -rf "$pdir"

case_ "wrong serial -> exit 5 naming the serials found"
device
umockdev-run --device "$WORK/tt.umockdev" --pcap "$sysfs=$WORK/tt.pcap" -- \
  "$FEST_BIN/turntable" --device 'usb:1209:0001#OTHER' info >"$out" 2>"$err"; rc=$?
expect_tool_error 5 "serial 'OTHER'.*MOCK0001"

finish
