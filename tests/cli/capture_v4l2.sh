#!/usr/bin/env bash
# capture's V4L2 camera end to end, on a virtual camera (tests/tools/v4l2mock.cpp, loaded
# with LD_PRELOAD: no camera or v4l2loopback module in CI). The virtual camera sends
# flat frames of luma Y = 16 + exposure in units of 100 us and neutral chroma, so each
# shot's grey level follows from the BT.601 limited-range equation 255/219 (Y - 16):
# 1 ms -> Y = 26 -> 11.64 -> 12, 4 ms -> Y = 56 -> 46.58 -> 47; as GREY (full range,
# no conversion) the levels are Y itself. It applies a new exposure two frames late,
# which the station's flush_frames = 1 covers (the tool drops the frame in flight).
source "$(dirname "$0")/lib.sh"
MOCK="$FEST_BIN/libv4l2mock.so"
[ -f "$MOCK" ] || { echo "skipped: libv4l2mock.so not built"; exit 77; }
export ASAN_OPTIONS=verify_asan_link_order=0
D="$FEST_FIXTURES/capture"
cp "$D/small_scene.json" "$D/small_station.json" "$WORK/"
NODE="$WORK/video0"  # a plain file: the node the tool checks for; the mock answers its ioctls
: >"$NODE"
LOG="$WORK/ioctl.log"
station() {  # station URI-OPTIONS FLUSH > file
  jq --arg u "v4l2:$NODE$1" --argjson f "$2" \
    '.camera.uri = $u | .camera.format = "png8" | .camera.flush_frames = $f' "$WORK/small_station.json"
}
printf '{"angles_deg": [0, 90], "lights": ["L0"], "exposures_s": [0.001, 0.004]}' >"$WORK/plan.json"
flat() {  # flat LEVEL > 32 x 16 PPM of that grey
  python3 -c "import sys; sys.stdout.buffer.write(b'P6 32 16 255\n' + bytes([$1]) * (32 * 16 * 3))"
}
flat 12 >"$WORK/g12.ppm"; flat 47 >"$WORK/g47.ppm"; flat 26 >"$WORK/g26.ppm"; flat 56 >"$WORK/g56.ppm"
mock_run() {  # mock_run [V4L2MOCK_*=VALUE...] capture-ARGS...
  local envs=()
  while [[ "${1:-}" == V4L2MOCK_*=* ]]; do envs+=("$1"); shift; done
  rm -f "$LOG"
  env V4L2MOCK_PATH="$NODE" V4L2MOCK_LOG="$LOG" "${envs[@]}" LD_PRELOAD="$MOCK" \
    "$FEST_BIN/capture" "$@" >"$out" 2>"$err"
  rc=$?
}
same() { "$FEST_BIN/fcompare" -q --tol 0 "$1" "$2"; }

case_ "a session on a YUYV camera: BT.601 levels, the driver's size, buffers given back"
station "" 1 >"$WORK/yuyv.json"
mock_run run --station "$WORK/yuyv.json" --plan "$WORK/plan.json" -o "$WORK/yuyv"
expect_status 0
expect_json '.status' '"complete"'
expect_json '.camera.name' "\"v4l2:$NODE (fest virtual camera)\""
expect_json '.camera.bits' 8
expect_json '[.shots[].bits]' '[8,8,8,8]'
check "1 ms: Y 26 -> 12" same "$WORK/yuyv/a000/L0/e00.png" "$WORK/g12.ppm"
check "4 ms: Y 56 -> 47" same "$WORK/yuyv/a000/L0/e01.png" "$WORK/g47.ppm"
check "second view, 1 ms" same "$WORK/yuyv/a001/L0/e00.png" "$WORK/g12.ppm"
check "second view, 4 ms" same "$WORK/yuyv/a001/L0/e01.png" "$WORK/g47.ppm"
check "the size comes from the negotiated format: exposure set before streaming starts" \
  test "$(head -3 "$LOG" | tr '\n' ' ')" = "reqbufs 4 exposure 10 streamon 0 "
check "exposures set in units of 100 us" test "$(grep exposure "$LOG" | cut -d' ' -f2 | tr '\n' ' ')" = "10 40 10 40 "
check "streaming stopped and buffers freed at the end" test "$(tail -2 "$LOG" | tr '\n' ' ')" = "streamoff 0 reqbufs 0 "

case_ "GREY is full range: the levels are the luma itself"
station ",fourcc=GREY" 1 >"$WORK/grey.json"
mock_run V4L2MOCK_FORMATS=MJPG,YUYV,GREY run --station "$WORK/grey.json" --plan "$WORK/plan.json" -o "$WORK/grey"
expect_status 0
check "1 ms: 26" same "$WORK/grey/a000/L0/e00.png" "$WORK/g26.ppm"
check "4 ms: 56" same "$WORK/grey/a001/L0/e01.png" "$WORK/g56.ppm"

case_ "without flush_frames the late sensor shows: the 4 ms shot still has the 1 ms level"
station "" 0 >"$WORK/noflush.json"
mock_run run --station "$WORK/noflush.json" --plan "$WORK/plan.json" -o "$WORK/noflush"
expect_status 0
check "4 ms shot taken from a 1 ms frame" same "$WORK/noflush/a000/L0/e01.png" "$WORK/g12.ppm"

case_ "a camera that stops sending: one line, exit 7"
mock_run V4L2MOCK_STALL=1 run --station "$WORK/yuyv.json" --plan "$WORK/plan.json" -o "$WORK/stall"
expect_clean_failure 7 capture
expect_stderr_has "v4l2 camera: $NODE did not deliver a frame in 5"

case_ "a camera without a format fest converts: one line, exit 6"
mock_run V4L2MOCK_FORMATS=NV12,H264 run --station "$WORK/yuyv.json" --plan "$WORK/plan.json" -o "$WORK/nv12"
expect_clean_failure 6 capture
expect_stderr_has "offers none of the formats fest converts .it offers NV12, H264"

case_ "a fourcc the camera does not offer: one line, exit 6"
station ",fourcc=MJPG" 1 >"$WORK/mjpg.json"
mock_run V4L2MOCK_FORMATS=YUYV run --station "$WORK/mjpg.json" --plan "$WORK/plan.json" -o "$WORK/mjpg"
expect_clean_failure 6 capture
expect_stderr_has "does not offer fourcc MJPG .it offers YUYV."

case_ "selftest through the virtual camera"
mock_run selftest --station "$WORK/yuyv.json"
expect_json '.camera.width' 32
expect_json '.camera.height' 16

finish
