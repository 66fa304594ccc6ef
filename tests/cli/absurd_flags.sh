#!/usr/bin/env bash
# Absurd numbers on the command line (issue 31): NaN, infinities and values beyond what
# a run can hold are refused before any work, exit 2, one line naming the flag and its
# range in plain numbers; derived sizes are checked in double, never wrapped.
. "$(dirname "$0")/lib.sh"

# refuse STATUS REGEX TOOL ARGS...: a clean failure (one line, no standard output) whose
# message matches REGEX, and no "out of memory", no 300-digit number.
refuse() {
  local status="$1" regex="$2"; shift 2
  local tool="$1"
  run "$@" </dev/null
  expect_clean_failure "$status" "$tool"
  expect_stderr_has "$regex"
  check "no number of 20 digits or more" bash -c "! grep -Eq '[0-9]{20}' '$err'"
}

printf '{}\n' >"$WORK/a.json"
case_ "fcompare --tol nan: a usage error, not a failed comparison"
refuse 2 '^fcompare: error: --tol: must be 0 or more, not nan' fcompare --tol nan "$WORK/a.json" "$WORK/a.json"
case_ "fcompare --tol -1: the range in plain numbers"
refuse 2 '^fcompare: error: --tol: must be 0 or more, not -1' fcompare --tol -1 "$WORK/a.json" "$WORK/a.json"
case_ "fcompare --tol inf: no infinity where none is meant"
refuse 2 '--tol: must be 0 or more, not inf' fcompare --tol inf "$WORK/a.json" "$WORK/a.json"

case_ "fluidsim run --tol nan: its help says [1e-15, 1]"
refuse 2 '^fluidsim: error: --tol: must be in \[1e-15, 1\], not nan' fluidsim run --tol nan
case_ "fluidsim render --sigma inf"
refuse 2 '--sigma: must be in \[0, 1000000000\], not inf' fluidsim render --sigma inf

case_ "facefit fit --components -5"
refuse 2 '^facefit: error: --components: must be 0 or more, not -5' facefit fit --components -5
case_ "facefit fit --noise-sigma 1e308 (eta = sigma^2 would overflow)"
refuse 2 '^facefit: error: --noise-sigma: must be in \[0, 1000000\], not 1e308' facefit fit --noise-sigma 1e308

case_ "lmfsim gen chain --n 1000000000: refused up front"
refuse 2 '^lmfsim: error: --n: must be in \[1, 1000000\], not 1000000000' lmfsim gen chain --n 1000000000
"$FEST_BIN/lmfsim" gen chain --n 2 >"$WORK/c2.json"
case_ "lmfsim run --t-end 1e308: the step count is bounded, not wrapped"
run_stdin "$WORK/c2.json" lmfsim run --t-end 1e308
expect_clean_failure 2 lmfsim
expect_stderr_has '--t-end 1e\+308 / --dt 0.001 is more than 1e308 steps; a run takes at most 1000000000'
case_ "lmfsim run: 1e10 steps of --dt"
run_stdin "$WORK/c2.json" lmfsim run --t-end 1e5 --dt 1e-5
expect_clean_failure 2 lmfsim
expect_stderr_has 'is 1e\+10 steps; a run takes at most 1000000000'
case_ "lmfsim reduced --t-end 1e308"
run_stdin "$WORK/c2.json" lmfsim reduced --chain --t-end 1e308
expect_clean_failure 2 lmfsim
case_ "lmfsim run --dt nan"
run_stdin "$WORK/c2.json" lmfsim run --dt nan
expect_clean_failure 2 lmfsim
expect_stderr_has '--dt: must be a finite number, not nan'

case_ "segbrain synth --noise 1e308"
refuse 2 '^segbrain: error: --noise: must be in \[0, 10\], not 1e308' segbrain synth -o "$WORK/p.nii" --truth "$WORK/t.nii" --noise 1e308
case_ "segbrain synth --size 100000,100000,100000: refused before allocating, naming the limit"
refuse 2 '^segbrain: error: a phantom of --size 100000,100000,100000 voxels needs 3.2e\+16 bytes; this machine holds [0-9.]+ GB' \
  segbrain synth -o "$WORK/p.nii" --truth "$WORK/t.nii" --size 100000,100000,100000
check "no phantom written" test ! -e "$WORK/p.nii"
case_ "segbrain synth --size 1e30,1,1: a count too large to convert"
refuse 2 '--size expects 3 whole numbers in \[1, 2147483647\]' segbrain synth -o "$WORK/p.nii" --truth "$WORK/t.nii" --size 1e30,1,1

printf 'P5\n4 4\n255\n' >"$WORK/im.pgm"
head -c 16 /dev/zero >>"$WORK/im.pgm"
case_ "resample resize --width -1: says the width must be positive"
refuse 2 '^resample: error: --width: must be a positive number, not -1' resample resize "$WORK/im.pgm" --width -1 -o "$WORK/o.pgm"
case_ "resample resize --scale 1e308: the derived size, not a wrapped dimension"
refuse 2 '^resample: error: --scale gives an image of more than 1e308 pixels a side: more than the 2147483648 \(2\^31\) pixels' \
  resample resize "$WORK/im.pgm" --scale 1e308 -o "$WORK/o.pgm"
case_ "resample resize --scale 30000: 120000x120000 pixels"
refuse 2 '--scale gives an image of 120000x120000 pixels: more than the 2147483648' resample resize "$WORK/im.pgm" --scale 30000 -o "$WORK/o.pgm"
case_ "resample resize --width 2000000000 (height follows the aspect ratio)"
refuse 2 '--width gives an image of 2e\+09x2e\+09 pixels' resample resize "$WORK/im.pgm" --width 2000000000 -o "$WORK/o.pgm"
case_ "resample resize --scale nan"
refuse 2 '--scale: must be a positive number, not nan' resample resize "$WORK/im.pgm" --scale nan -o "$WORK/o.pgm"
check "no image written" test ! -e "$WORK/o.pgm"

case_ "a number of 400 digits is quoted shortened"
run fcompare --tol "-$(printf '1%.0s' $(seq 400))" "$WORK/a.json" "$WORK/a.json"
expect_clean_failure 2 fcompare
expect_stderr_has '--tol: must be 0 or more, not -1{36}\.\.\. '
check "not all 400" bash -c "! grep -Eq '1{60}' '$err'"

# Integer flags (issue 31): every count, size and iteration limit states its range; a
# negative value, a zero where none is meant, 1e308 and a 19-digit number are all refused
# by that range, before any file is read.
# int_flag RANGE TOOL ARGS... -- FLAG: FLAG with -1, 0 (when below the range), 1e308 and a
# 19-digit whole number appended to ARGS; each a usage error naming FLAG and RANGE.
int_flag() {
  local range="$1"; shift
  local args=() flag lo
  while [ "$1" != "--" ]; do args+=("$1"); shift; done
  flag="$2"
  lo="${range%%,*}"; lo="${lo#\[}"
  local values=(-1 1e308 9999999999999999999)
  [ "$lo" -gt 0 ] && values+=(0)
  local re_range
  re_range=$(printf '%s' "$range" | sed 's/\[/\\[/; s/\]/\\]/')
  for v in "${values[@]}"; do
    case_ "${args[*]} $flag $v: refused with its range $range"
    refuse 2 "^${args[0]}: error: $flag: must be in $re_range, not ${v:0:20}" "${args[@]}" "$flag" "$v"
  done
}
int_flag '[1, 3]' brdffit fit x.ltx -- --lobes
int_flag '[1, 4]' brdffit fit x.ltx -- --starts
int_flag '[1, 10000]' brdffit cluster x.ltx -- --split-iters
int_flag '[0, 10000]' brdffit cluster x.ltx -- --global-iters
int_flag '[1, 64]' brdffit project x.ltx -- --basis
int_flag '[3, 65535]' brdffit normals x.ltx -- --normal-min-samples
int_flag '[1, 1000]' brdffit normals x.ltx -- --alternate
int_flag '[1, 2147483647]' decimate x.ply -- --faces
int_flag '[0, 100000000]' decimate x.ply -- --samples
int_flag '[1, 1000]' facefit fit -- --iterations
int_flag '[2, 100000]' facefit synth -o "$WORK/faces" -- --faces
int_flag '[16, 2048]' facefit synth -o "$WORK/faces" -- --resolution
int_flag '[1, 1000000000]' feshape fit x.xyz -- --max-iter
int_flag '[0, 20]' feshape fit x.xyz -- --levels
int_flag '[6, 100000000]' feshape fit x.xyz -- --max-nodes
int_flag '[1, 10000000]' feshape sample -- --n
int_flag '[0, 2147483647]' fluidsim render x.nrrd -- --index
int_flag '[1, 1000000000]' lmfsim run -- --every
int_flag '[1, 64]' resample display x.pgm -- --factor
int_flag '[0, 40]' resample mip x.pgm -o "$WORK/m.pgm" -- --levels
int_flag '[1, 65536]' resample render -- --spp
int_flag '[1, 1000000]' resample chain1d -- --terms
int_flag '[1, 2]' resample mipkernel -- --dims
int_flag '[1, 100000000]' segbrain run -- --max-depth
int_flag '[4, 4096]' terrainlod build x.tif -o "$WORK/t.tlp" -- --tile
int_flag '[0, 15]' terrainlod decode x.tlp --tile 0/0/0 -- --mask
int_flag '[0, 1000000]' terrainlod verify x.tlp -- --cameras
int_flag '[0, 86400000]' turntable move 90 -- --settle-ms
case_ "ffd init --dims 2,100000,2: every count in [2, 64]"
refuse 2 '^ffd: error: --dims: must be in \[2, 64\], not 100000' ffd init x.ply --dims 2,100000,2
case_ "volwave encode --roi-box with a negative index"
refuse 2 '^volwave: error: --roi-box: must be in \[0, 2147483647\], not -1' volwave encode x.nii --lossless --roi-box=-1,0,0,5,5,5

# fcompare's thresholds (-t): NaN and infinities would make the check mean nothing.
for t in 'psnr>=nan' 'psnr>=inf' 'rmse<=-inf' 'psnr>=1e999'; do
  case_ "fcompare -t '$t': a usage error naming the threshold"
  refuse 2 "^fcompare: error: threshold '$(printf '%s' "$t" | sed 's/[]\[().*^$+?{}|]/\\&/g')': the value must be a finite number" \
    fcompare -t "$t" "$WORK/a.json" "$WORK/a.json"
done
case_ "fcompare -t 'psnr>=abc': not a number at all"
refuse 2 "^fcompare: error: threshold 'psnr>=abc' is not METRIC<=VALUE or METRIC>=VALUE" fcompare -t 'psnr>=abc' "$WORK/a.json" "$WORK/a.json"
case_ "fcompare --samples -1"
refuse 2 '^fcompare: error: --samples: must be in \[0, 100000000\], not -1' fcompare --samples -1 "$WORK/a.json" "$WORK/a.json"

finish
