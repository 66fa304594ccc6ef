#!/bin/bash
# quatpath: closed-form answers (linear motion, a quarter turn about z, the 350-degree
# turn both ways), 30 -> 10 fps resampling, constant speed, camera output, bad input.
. "$(dirname "$0")/lib.sh"

case_ "linear path and slerp: closed form at every frame"
printf 't,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n2,4,2,0,0.7071067811865476,0,0,0.7071067811865476\n' > "$WORK/k.csv"
run quatpath "$WORK/k.csv" --fps 4 --position linear
expect_status 0
# t = k/4: position (2t, t, 0), rotation 45 t degrees about z: (cos(22.5 t deg), 0, 0, sin(22.5 t deg)).
if awk -F, 'NR>1 { t=$1; a=22.5*t*3.141592653589793/180;
     if (($2-2*t)^2+($3-t)^2+$4^2 > 1e-20 || ($5-cos(a))^2+($8-sin(a))^2+$6^2+$7^2 > 1e-24) bad=1; n++ }
     END { exit (bad || n != 9) }' "$out"; then pass; else fail "poses differ from the closed form: $(head -4 "$out")"; fi

case_ "350-degree turn: short way -5 degrees at mid-time, long way +175 degrees"
printf 't,x,y,z,qw,qx,qy,qz,way\n0,0,0,0,1,0,0,0,0\n1,0,0,0,%s,0,0,%s,0\n' "$(awk 'BEGIN{printf "%.17g", cos(175*3.141592653589793/180)}')" \
  "$(awk 'BEGIN{printf "%.17g", sin(175*3.141592653589793/180)}')" > "$WORK/turn.csv"
run quatpath "$WORK/turn.csv" --fps 2 --to jsonl
yaw=$(jq -r 'select(.t==0.5) | .quat | (2*atan2(.[3]; .[0]) * 180 / 3.141592653589793)' "$out")
# the yaw of (w,0,0,z) is 2 atan2(z, w), defined modulo 360
if awk -v y="$yaw" 'BEGIN{ d = y + 5; while (d > 180) d -= 360; while (d < -180) d += 360; exit !(d*d < 1e-18) }'; then pass; else fail "short way: yaw $yaw, expected -5"; fi
sed -i '2s/,0$/,1/' "$WORK/turn.csv"
run quatpath "$WORK/turn.csv" --fps 2 --to jsonl
yaw=$(jq -r 'select(.t==0.5) | .quat | (2*atan2(.[3]; .[0]) * 180 / 3.141592653589793)' "$out")
if awk -v y="$yaw" 'BEGIN{ d = y - 175; while (d > 180) d -= 360; while (d < -180) d += 360; exit !(d*d < 1e-18) }'; then pass; else fail "long way: yaw $yaw, expected 175"; fi
run quatpath "$WORK/turn.csv" --fps 2 --way long --to jsonl
expect_status 0

case_ "30 -> 10 fps: a 30-fps walk along x resampled keeps every third frame"
{ echo t,x,y,z,qw,qx,qy,qz; for k in $(seq 0 30); do echo "$(awk -v k=$k 'BEGIN{printf "%.17g", k/30}'),$k,0,0,1,0,0,0"; done; } > "$WORK/walk.csv"
run quatpath "$WORK/walk.csv" --fps 10 --position linear
expect_status 0
if [ "$(tail -n +2 "$out" | cut -d, -f2 | tr '\n' ' ')" = "0 3 6 9 12 15 18 21 24 27 30 " ]; then pass; else fail "x at 10 fps: $(tail -n +2 "$out" | cut -d, -f2 | tr '\n' ' ')"; fi

case_ "constant speed: equal steps along a Catmull-Rom curve within 0.1 %"
printf 't,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n1,10,0,0,1,0,0,0\n1.5,10,3,0,1,0,0,0\n4,0,5,2,1,0,0,0\n' > "$WORK/curve.csv"
run quatpath "$WORK/curve.csv" --fps 100 --constant-speed --report "$WORK/r.json"
expect_status 0
if jq -e '(.max_frame_step / .min_frame_step) < 1.001 and .max_unit_error < 1e-12' "$WORK/r.json" >/dev/null; then pass
else fail "report: $(cat "$WORK/r.json")"; fi
run quatpath "$WORK/curve.csv" --fps 100 --report "$WORK/r2.json"
if jq -e '(.max_frame_step / .min_frame_step) > 2' "$WORK/r2.json" >/dev/null; then pass; else fail "key-timed speed should vary"; fi

case_ "squad and JSON Lines keys"
printf '%s\n' '{"t":0,"pos":[0,0,0],"quat":[1,0,0,0]}' '{"t":1,"pos":[1,0,0],"quat":[0.7071067811865476,0.7071067811865476,0,0]}' \
  '{"t":2,"pos":[1,1,0],"quat":[0.5,0.5,0.5,0.5]}' > "$WORK/k.jsonl"
run quatpath "$WORK/k.jsonl" --orientation squad --position kb --fps 10 -o "$WORK/p.jsonl"
expect_status 0
if [ "$(wc -l < "$WORK/p.jsonl")" -eq 21 ]; then pass; else fail "21 frames expected"; fi

case_ "camera path for terrainlod: eye, target, up"
run quatpath "$WORK/k.csv" --fps 1 --to camera --camera-distance 10
expect_status 0
# identity orientation: looking along -z with +y up
expect_json 'select(.t==0) | [.eye, .target, .up]' '[[0,0,0],[0,0,-10],[0,1,0]]'

case_ "camera-args: volrender look-at flags"
run quatpath "$WORK/k.csv" --fps 1 --to camera-args --camera-distance 10
expect_status 0
if [ "$(head -1 "$out")" = "--eye 0,0,0 --look-at 0,0,-10 --up 0,1,0" ]; then pass; else fail "$(head -1 "$out")"; fi

case_ "golden: the Jacksboro camera flight (examples/quatpath), numbers within 1e-9 relative"
KEYS="$(cd "$(dirname "$0")/../../examples/quatpath" && pwd)/jacksboro_keys.csv"
run quatpath "$KEYS" --fps 1 --orientation squad --constant-speed --to camera --camera-distance 5000 --width 800 --height 500 --tau 8
expect_status 0
if paste <(jq -c '[.. | numbers]' "$out") <(jq -c '[.. | numbers]' "$FEST_FIXTURES/quatpath/jacksboro_cams.jsonl") |
   awk -F'\t' '{ n = split(substr($1, 2, length($1) - 2), a, ","); m = split(substr($2, 2, length($2) - 2), b, ",");
                  if (n != m) bad = 1; for (i = 1; i <= n; i++) { d = a[i] - b[i]; if (d < 0) d = -d; s = (b[i] < 0 ? -b[i] : b[i]);
                  if (d > 1e-9 * (s > 1 ? s : 1)) bad = 1 } } END { exit bad || NR != 7 }'; then pass
else fail "cameras differ from tests/data/quatpath/jacksboro_cams.jsonl"; fi

case_ "bad input: NaN key, times not increasing, one key, zero quaternion, unknown column"
printf 't,x,y,z,qw,qx,qy,qz\n0,0,nan,0,1,0,0,0\n1,1,0,0,1,0,0,0\n' > "$WORK/nan.csv"
run quatpath "$WORK/nan.csv"
expect_clean_failure 3 quatpath
expect_stderr_has "key 1 has a value that is not a finite number"
printf 't,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n2,1,0,0,1,0,0,0\n1,2,0,0,1,0,0,0\n' > "$WORK/order.csv"
run quatpath "$WORK/order.csv"
expect_clean_failure 3 quatpath
expect_stderr_has "increase strictly \(key 3"
printf 't,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n' > "$WORK/one.csv"
run quatpath "$WORK/one.csv"
expect_clean_failure 3 quatpath
printf 't,x,y,z,qw,qx,qy,qz\n0,0,0,0,0,0,0,0\n1,0,0,0,1,0,0,0\n' > "$WORK/zero.csv"
run quatpath "$WORK/zero.csv"
expect_clean_failure 3 quatpath
printf 't,x,y,z,qw,qx,qy,qz,roll\n0,0,0,0,1,0,0,0,1\n1,0,0,0,1,0,0,0,2\n' > "$WORK/extra.csv"
run quatpath "$WORK/extra.csv"
expect_clean_failure 3 quatpath
: > "$WORK/empty.csv"
run quatpath "$WORK/empty.csv"
expect_clean_failure 3 quatpath
run quatpath "$WORK/k.csv" --fps 0
expect_status 2
run quatpath "$WORK/none.csv"
expect_clean_failure 4 quatpath

finish
