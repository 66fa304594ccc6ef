#!/usr/bin/env bash
# capture plan/run/selftest and hdrmerge --manifest on the simulated station
# (docs/capture.md §2-3, docs/hdrmerge.md §5, docs/capture.md §6): a whole session, its files against their recorded
# SHA-256 (checked with sha256sum, an independent program), the rig JSON's light
# positions against the frame change of docs/capture.md §1 worked by hand, the silhouette mask's area
# against the sphere's projection, faults mid-session (unplug -> 5, stuck move -> 7) and
# --resume ending identical to an uninterrupted run except timestamps, bad input.
source "$(dirname "$0")/lib.sh"
D="$FEST_FIXTURES/capture"
cp "$D/small_scene.json" "$D/small_station.json" "$D/small_plan.json" "$WORK/"
S="$WORK/small_station.json" P="$WORK/small_plan.json"
station_with() {  # station_with URI > file: the small station with another turntable URI
  jq --arg u "$1" '.turntable.uri = $u' "$S"
}

case_ "capture plan from flags"
run capture plan --angles 24 --lights L0 --bracket 1/1000:1:12 --silhouette BG --lightcal 2 --dark 1
expect_status 0
expect_json '.angles_deg | length' 24
expect_json '.angles_deg[3]' 45
expect_json '.exposures_s | length' 12
expect_json '.exposures_s[11]' 2.048
expect_json '.per_view.silhouette.lights_on' '["BG"]'
expect_json '.per_view.lightcal.count' 2

case_ "dry run: the plan, its shots and an estimate, no session"
run capture run --station "$S" --plan "$P" -o "$WORK/never" --dry-run
expect_status 0
expect_json '.shots' 52
expect_json '.files[1]' '"a000/L0/e00.png"'
expect_json '.estimate_s > 0' true
check "dry run creates nothing" test ! -e "$WORK/never"

case_ "a whole simulated session"
# The session is named by its folder as given (-o sess): runs from two folders compare equal.
mkdir -p "$WORK/a" "$WORK/b"
cd "$WORK/a"
run capture run --station "$S" --plan "$P" -o sess
expect_status 0
expect_json '.status' '"complete"'
expect_json '.shots | length' 52
expect_json '[.shots[] | select(.kind == "hdr")] | length' 48
expect_json '.sets | length' 4
expect_json '.sets[1].shots' '[14,15,16,17,18,19,20,21,22,23,24,25]'
expect_json '.shots[14].file' '"a001/L0/e00.png"'
expect_json '.shots[14].angle_deg' 90
expect_json '.shots[14].angle_steps' 12800
expect_json '.shots[25].exposure_s' 2.048
expect_json '.turntable.steps_per_rev' 51200
cp "$out" "$WORK/a.json"
check "manifest.json equals the manifest on stdout" cmp "$out" "$WORK/a/sess/manifest.json"
# Every file hashes to its recorded SHA-256 (sha256sum's own format: "HASH  FILE").
jq -r '.shots[] | "\(.sha256)  \(.file)"' "$out" > "$WORK/sums"
check "sha256sum agrees with the manifest" bash -c "cd '$WORK/a/sess' && sha256sum --quiet -c '$WORK/sums'"
check "journal: header + 52 shots" test "$(wc -l < "$WORK/a/sess/manifest.journal")" -eq 53
check "16-bit PNG shots" bash -c "file '$WORK/a/sess/a002/L0/e05.png' | grep -q '16-bit/color RGB'"

case_ "hdrmerge --manifest: EXRs, masks and the rig JSON"
run hdrmerge --manifest "$WORK/a/sess/manifest.json"
expect_status 0
cp "$out" "$WORK/rig.json"
expect_json '.frame' '"turntable"'
expect_json '.images | length' 4
expect_json '.images[1].file' '"hdr/a001_L0.exr"'
expect_json '.images[1].mask' '"hdr/a001_mask.png"'
expect_json '.images[1].angle_deg' 90
expect_json '.images[0].camera.t' '[0,60,500]'
expect_json '.images[0].camera.K' '[250,0,79.5,0,250,59.5,0,0,1]'
# q = (300,-250,200) in C, t_T0 = (0,60,500), R_T0 = [1 0 0; 0 0 -1; 0 1 0]:
# R_T0^T (q - t_T0) = (300, -300, 310); at 90 deg Rz(-90) maps (x, y) to (y, -x).
expect_json '.images[0].light.position | map(. * 1000 | round / 1000)' '[300,-300,310]'
expect_json '.images[1].light.position | map(. * 1000 | round / 1000)' '[-300,-300,310]'
expect_json '.images[2].light.position | map(. * 1000 | round / 1000)' '[-300,300,310]'
# camera R at 90 deg: R_T0 Rz(90) = [0 -1 0; 0 0 -1; 1 0 0]
expect_json '.images[1].camera.R | map(. * 1e9 | round / 1e9)' '[0,-1,0,0,0,-1,1,0,0]'
check "EXR written" test -s "$WORK/a/sess/hdr/a003_L0.exr"
check "EXR has the valid channel and attributes" bash -c \
  "grep -aq 'valid' '$WORK/a/sess/hdr/a000_L0.exr' && grep -aq 'responseSha256' '$WORK/a/sess/hdr/a000_L0.exr' && grep -aq 'turntableAngleDeg' '$WORK/a/sess/hdr/a000_L0.exr'"
# Mask area: a sphere of radius 50 mm whose centre is 500.1 mm away projects to a disc of
# radius f r / sqrt(d^2 - r^2) = 250 * 50 / 497.6 = 25.12 px: area 1982 px (+- 3 %).
area=$(python3 - "$WORK/a/sess/hdr/a000_mask.png" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
pos, idat, w, h = 8, b'', 0, 0
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR': w, h = struct.unpack('>II', body[:8])
    if kind == b'IDAT': idat += body
    pos += 12 + n
raw, prev, count = zlib.decompress(idat), bytearray(w), 0
for y in range(h):
    f, line = raw[y * (w + 1)], bytearray(raw[y * (w + 1) + 1:(y + 1) * (w + 1)])
    for x in range(w):
        a = line[x - 1] if x else 0
        b, c = prev[x], (prev[x - 1] if x else 0)
        p = a + b - c
        pred = [0, a, b, (a + b) // 2, a if abs(p - a) <= min(abs(p - b), abs(p - c)) else (b if abs(p - b) <= abs(p - c) else c)][f]
        line[x] = (line[x] + pred) & 255
    count += sum(1 for v in line if v)
    prev = line
print(count)
PY
)
check "mask area $area px within 3 % of 1982" python3 -c "import sys; sys.exit(0 if abs($area - 1982) <= 0.03 * 1982 else 1)"

case_ "hdrmerge sheet: a contact sheet of the merged EXRs"
run hdrmerge sheet "$WORK/a/sess/hdr/a000_L0.exr" "$WORK/a/sess/hdr/a001_L0.exr" --columns 2 --width 80 -o "$WORK/sheet.png"
expect_status 0
check "sheet is a 160x60 PNG" bash -c "file '$WORK/sheet.png' | grep -q '160 x 60'"

case_ "SIGTERM mid-session: exit 1, aborted manifest, the journal intact"
cd "$WORK"
jq '.angles_deg = {"count": 200}' "$P" > "$WORK/long_plan.json"
"$FEST_BIN/capture" run --station "$S" --plan "$WORK/long_plan.json" -o "$WORK/term" >"$out" 2>"$err" &
pid=$!
for _ in $(seq 100); do [ -s "$WORK/term/manifest.json" ] && break; sleep 0.1; done
kill -TERM "$pid"; wait "$pid"; rc=$?
expect_clean_failure 1 capture
expect_stderr_has "interrupted by a signal"
check "aborted manifest after SIGTERM" test "$(jq -r .status "$WORK/term/manifest.json")" = aborted
check "journal ends with the abort" bash -c "tail -1 '$WORK/term/manifest.journal' | jq -e .abort"

case_ "unplug mid-session: exit 5, aborted manifest, nothing on stdout"
station_with "sim:steps=51200,speed=90,unplug_at=60" > "$WORK/unplug.json"
cd "$WORK/b"
run capture run --station "$WORK/unplug.json" --plan "$P" -o sess
expect_clean_failure 5 capture
expect_stderr_has "unplugged"
check "aborted manifest" test "$(jq -r .status "$WORK/b/sess/manifest.json")" = aborted
check "failing step named" bash -c "jq -e '.failure.step | test(\"move to angle 1\")' '$WORK/b/sess/manifest.json'"
check "abort in the journal" bash -c "tail -1 '$WORK/b/sess/manifest.journal' | jq -e .abort"
kept=$(jq '.shots | length' "$WORK/b/sess/manifest.json")
check "the first view kept ($kept shots)" test "$kept" -eq 13
check "hdrmerge refuses an aborted session" bash -c "! '$FEST_BIN/hdrmerge' --manifest '$WORK/b/sess/manifest.json' >/dev/null 2>&1"

case_ "--resume completes it, identical to the uninterrupted run but for timestamps"
touch -d '2000-01-01' "$WORK/b/sess/a000/L0/e00.png"
run capture run --station "$S" --plan "$P" -o sess --resume
expect_status 0
norm='del(.started) | del(.shots[].time)'
check "same manifest" cmp <(jq -S "$norm" "$out") <(jq -S "$norm" "$WORK/a.json")
check "kept shots were not re-taken" test "$(stat -c %Y "$WORK/b/sess/a000/L0/e00.png")" -lt 1000000000
check "journal: one resume line" test "$(grep -c '"resume"' "$WORK/b/sess/manifest.journal")" -eq 1

case_ "--resume after a crash in the middle of a journal line"
head -c -40 "$WORK/b/sess/manifest.journal" > "$WORK/torn" && cat "$WORK/torn" > "$WORK/b/sess/manifest.journal"
run capture run --station "$S" --plan "$P" -o sess --resume
expect_status 0
check "same manifest after a torn journal" cmp <(jq -S "$norm" "$out") <(jq -S "$norm" "$WORK/a.json")
check "the journal replays cleanly again" bash -c "jq -c . '$WORK/b/sess/manifest.journal' > /dev/null"

case_ "--resume re-takes a damaged shot"
printf 'x' >> "$WORK/b/sess/a002/L0/e03.png"
run capture run --station "$S" --plan "$P" -o sess --resume
expect_status 0
check "same manifest after the re-take" cmp <(jq -S "$norm" "$out") <(jq -S "$norm" "$WORK/a.json")

case_ "the pipeline of capture(1): capture run | hdrmerge --manifest -"
rm -rf "$WORK/b/sess/hdr"
run_stdin "$WORK/a.json" hdrmerge --manifest - -o "$WORK/b/sess/hdr"
expect_status 0
expect_json '.session' '"sess"'
expect_json '.images | length' 4
check "rig files resolve from the session" test -s "$WORK/b/sess/hdr/a003_L0.exr"
cd "$WORK"

case_ "exec: camera (an external command writes each picture)"
jq --arg u "exec:cp '$WORK/a/sess/a001/L0/e06.png' {out} && test {exposure_s} != 0" '.camera.uri = $u' "$S" > "$WORK/exec.json"
printf '{"angles_deg": [0], "lights": ["L0"], "exposures_s": [0.001, 0.004]}' > "$WORK/two.json"
run capture run --station "$WORK/exec.json" --plan "$WORK/two.json" -o "$WORK/exec"
expect_status 0
expect_json '[.shots[].bits]' '[16,16]'
expect_json '.camera.width' 160
jq --arg u "exec:false {out}" '.camera.uri = $u' "$S" > "$WORK/exec_fail.json"
run capture run --station "$WORK/exec_fail.json" --plan "$WORK/two.json" -o "$WORK/exec_fail"
expect_clean_failure 6 capture
expect_stderr_has "exec camera: the command failed"

case_ "png_compression 0 stores the shots"
jq '.camera.png_compression = 0' "$S" > "$WORK/stored.json"
run capture run --station "$WORK/stored.json" --plan "$WORK/two.json" -o "$WORK/stored"
expect_status 0
check "a stored 16-bit RGB shot holds at least its 160 x 120 x 6 bytes" \
  test "$(stat -c %s "$WORK/stored/a000/L0/e01.png")" -ge 115200
jq '.camera.png_compression = 10' "$S" > "$WORK/level10.json"
run capture run --station "$WORK/level10.json" --plan "$WORK/two.json" -o "$WORK/level10"
expect_clean_failure 3 capture
expect_stderr_has "camera.png_compression"

case_ "v4l2: camera that is not there: exit 5"
jq '.camera.uri = "v4l2:/dev/fest-no-such-video,fourcc=Y16"' "$S" > "$WORK/v4l2.json"
run capture run --station "$WORK/v4l2.json" --plan "$WORK/two.json" -o "$WORK/v4l2"
expect_clean_failure 5 capture
expect_stderr_has "v4l2 camera: no device /dev/fest-no-such-video"
jq '.camera.uri = "v4l2:/dev/null,gain=3"' "$S" > "$WORK/v4l2_key.json"
run capture run --station "$WORK/v4l2_key.json" --plan "$WORK/two.json" -o "$WORK/v4l2_key"
expect_clean_failure 2 capture

case_ "v4l2: a node that is not a V4L2 device: one line, exit 6"
# /dev/null opens but answers VIDIOC_QUERYCAP with ENOTTY, as any non-video node does.
jq '.camera.uri = "v4l2:/dev/null"' "$S" > "$WORK/v4l2_null.json"
run capture run --station "$WORK/v4l2_null.json" --plan "$WORK/two.json" -o "$WORK/v4l2_null"
expect_clean_failure 6 capture
expect_stderr_has "v4l2 camera: /dev/null is not a V4L2 device"
jq '.camera.uri = "v4l2:/dev/null,fourcc=H264"' "$S" > "$WORK/v4l2_h264.json"
run capture run --station "$WORK/v4l2_h264.json" --plan "$WORK/two.json" -o "$WORK/v4l2_h264"
expect_clean_failure 2 capture
expect_stderr_has "fourcc 'H264' is not a format fest converts .YUYV, MJPG, GREY, RGB3, Y16."

case_ "a move that never completes: exit 7"
station_with "sim:steps=51200,speed=90,fail_at=3" > "$WORK/stuck.json"
run capture run --station "$WORK/stuck.json" --plan "$P" -o "$WORK/stuck"
expect_clean_failure 7 capture
check "aborted manifest" test "$(jq -r .status "$WORK/stuck/manifest.json")" = aborted

case_ "selftest on the simulated station"
run capture selftest --station "$S"
expect_status 0
expect_json '.ok' true
expect_json '.lights | length' 2

case_ "repeat: every exposure taken N times, hdrmerge averages the takes"
run capture plan --angles 1 --lights L0 --bracket 1/250:1:8 --repeat 4
expect_status 0
expect_json '.repeat' 4
cp "$out" "$WORK/four.json"
"$FEST_BIN/capture" plan --angles 1 --lights L0 --bracket 1/250:1:8 > "$WORK/once.json"
# A noisy camera (2 8-bit DN of read noise) and the same without noise; the response
# comes from the noiseless shots at 8 bits, so that only the noise differs.
jq '.response.noise_dn = 512' "$WORK/small_scene.json" > "$WORK/noisy_scene.json"
jq '.response.noise_dn = 0' "$WORK/small_scene.json" > "$WORK/clean_scene.json"
jq '.camera.uri = "sim:noisy_scene.json"' "$S" > "$WORK/noisy.json"
jq '.camera.uri = "sim:clean_scene.json"' "$S" > "$WORK/clean.json"
jq '.camera.format = "png8"' "$WORK/clean.json" > "$WORK/clean8.json"
R="$WORK/rep"
mkdir -p "$R"
run capture run --station "$WORK/noisy.json" --plan "$WORK/four.json" -o "$R/four"
expect_status 0
expect_json '.shots | length' 32
expect_json '.shots[5].file' '"a000/L0/e01_r1.png"'
expect_json '.shots[5].repeat_index' 1
expect_json '[.shots[4:8][] | .exposure_s] | unique' '[0.008]'
expect_json '.sets[0].shots | length' 32
check "takes of one exposure carry their own noise" \
  test "$(jq -r '[.shots[4:8][] | .sha256] | unique | length' "$out")" -eq 4
for s in once:noisy:one four:clean:fourclean once:clean:clean once:clean8:clean8; do
  IFS=: read -r plan station name <<< "$s"
  "$FEST_BIN/capture" run --station "$WORK/$station.json" --plan "$WORK/$plan.json" -o "$R/$name" > /dev/null
done
"$FEST_BIN/hdrmerge" calibrate "$R"/clean8/a000/L0/e0*.png -t 0.004,0.008,0.016,0.032,0.064,0.128,0.256,0.512 \
  -o "$WORK/response.csv"
for name in four one fourclean clean; do
  run hdrmerge --manifest "$R/$name/manifest.json" --response "$WORK/response.csv" --float
  expect_status 0
done
# Identical takes (no noise) average to themselves: the same radiance as one take.
check "noiseless takes merge like one take" \
  "$FEST_BIN/fcompare" -q "$R/clean/hdr/a000_L0.exr" "$R/fourclean/hdr/a000_L0.exr"
# Noisy takes: the mean of 4 has half the read noise (8-bit rounding and the response's
# slope add a floor): the radiance error against the noiseless merge must shrink.
rms_of() { "$FEST_BIN/fcompare" "$R/clean/hdr/a000_L0.exr" "$1" 2> /dev/null | awk '$1 == "rmse" {print $2}'; }
e1=$(rms_of "$R/one/hdr/a000_L0.exr") e4=$(rms_of "$R/four/hdr/a000_L0.exr")
check "4 takes: radiance RMS error $e4 below 0.9 x one take's $e1" python3 -c "import sys; sys.exit(0 if $e4 < 0.9 * $e1 else 1)"
run capture plan --angles 1 --repeat 0
expect_clean_failure 2 capture

case_ "bad input"
jq '. + {"expsoures_s": [1]}' "$P" > "$WORK/typo.json"
run capture run --station "$S" --plan "$WORK/typo.json" -o "$WORK/t1"
expect_clean_failure 3 capture
expect_stderr_has 'unknown key "expsoures_s" \(did you mean "exposures_s"\?\).*typo.json'
jq 'del(.turntable)' "$S" > "$WORK/noturn.json"
run capture run --station "$WORK/noturn.json" --plan "$P" -o "$WORK/t2"
expect_clean_failure 3 capture
expect_stderr_has 'turntable: missing'
jq '.lights[0].position_mm = [1, 2]' "$S" > "$WORK/badpos.json"
run capture run --station "$WORK/badpos.json" --plan "$P" -o "$WORK/t3"
expect_clean_failure 3 capture
expect_stderr_has 'lights\[0\]\.position_mm'
jq '.camera.format = "jpeg"' "$S" > "$WORK/jpeg.json"
run capture run --station "$WORK/jpeg.json" --plan "$P" -o "$WORK/t4"
expect_clean_failure 2 capture
expect_stderr_has 'JPEG'
check "nothing written for a refused JPEG station" test ! -e "$WORK/t4"
run capture run --station "$S" --plan "$P" -o "$WORK/nonexistent" --resume
expect_clean_failure 4 capture
expect_stderr_has 'cannot resume'
run capture run --station "$S" --plan "$P" -o "$WORK/a/sess"
expect_clean_failure 4 capture
expect_stderr_has 'already holds a session'
jq '.exposures_s.count = 11' "$P" > "$WORK/other_plan.json"
run capture run --station "$S" --plan "$WORK/other_plan.json" -o "$WORK/a/sess" --resume
expect_clean_failure 3 capture
expect_stderr_has 'plan differs'
run capture run --plan "$P" -o "$WORK/t5"
expect_clean_failure 2 capture
jq '.turntable.uri = "usb:1209:0001"' "$S" > "$WORK/usb.json"
run capture run --station "$WORK/usb.json" --plan "$P" -o "$WORK/t6"
expect_clean_failure 5 capture
check "the failed open is in an aborted manifest" test "$(jq -r .failure.step "$WORK/t6/manifest.json")" = "open devices"
run capture plan --angles 0
expect_clean_failure 2 capture
printf '{"version": 1, "status": "complete", "shots": [], "sets": [' > "$WORK/broken.json"
run hdrmerge --manifest "$WORK/broken.json"
expect_clean_failure 3 hdrmerge

finish
