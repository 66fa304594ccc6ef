#!/usr/bin/env bash
# resample: the chapter's figures (docs/resample.md "Figures reproduced") from the mathematics, linear light, the zone
# plate against the Z1 table of docs/resample.md "Figures reproduced", properties, and bad input.
. "$(dirname "$0")/lib.sh"

R="$FEST_BIN/resample"
F="$FEST_BIN/fconv"

# near FILTER VALUE TOL: |jq FILTER on stdout − VALUE| ≤ TOL
near() {
  local got
  got=$(jq -r "$1" "$out" 2>/dev/null)
  if awk -v g="$got" -v e="$2" -v t="$3" 'BEGIN { d = g - e; if (d < 0) d = -d; exit !(g != "" && d <= t) }'; then
    pass
  else
    fail "jq '$1' gave '$got', expected $2 ± $3"
  fi
}

# --- C1/C2: Fig. 10.10, box prefilter and box display at f = 1.375 f_S -------------------
case_ "chain1d Fig. 10.10: box prefilter, box display, f = 1.375"
run resample chain1d --prefilter box --recon box --freq 1.375
expect_status 0
near '.results[0].P' -0.21388 1e-5                 # sinc(1.375)
near '.results[0].aliases[2].amplitude' -0.16772 1e-5   # k = 1, frequency 0.375
near '.results[0].aliases[3].amplitude' -0.10063 1e-5   # k = 2, frequency −0.625
near '.results[0].A0' 0.045743 1e-5                # sinc(1.375)²
near '.results[0].alias_rms' 0.208918 1e-5
near '.results[0].mse' 0.954253 1e-5

case_ "chain1d ideal low-pass removes the signal (fig. 10.10's f)"
run resample chain1d --prefilter ideal --recon box --freq 1.375
near '.results[0].A0' 0 1e-12
near '.results[0].mse' 1 1e-12

case_ "chain1d: the dual prefilter beats box, ideal and p = r for a tent display (§10.5)"
run resample chain1d --prefilter dual:tent --recon tent --freq 0.25
near '.results[0].mse' 0.0145 1e-4
run resample chain1d --prefilter box --recon tent --freq 0.25
near '.results[0].mse' 0.0808 1e-4
run resample chain1d --prefilter dual:bspline --recon bspline --freq 0.25
near '.results[0].mse' 0.0002 1e-4

case_ "chain1d --edge: Fig. 10.2 non-linear reconstruction"
run resample chain1d --edge 0.37
near '.recovered[0]' 0.37 1e-12
run resample chain1d --edge 0.2,1.7
near '.recovered[0]' 0.285714285714 1e-9   # 2/7
near '.recovered[1]' 1.625 1e-9

# --- kernel responses against closed forms ------------------------------------------------
case_ "kernel box: K(f) = sinc(f), no overshoot"
run resample kernel --filter box
expect_status 0
near '."K_0.25"' 0.900316 1e-4   # sin(π/4)/(π/4)
near '."K_0.5"' 0.636620 1e-4    # 2/π
near '.stop_max' 0.300105 1e-4   # |sinc(0.75)|
near '.overshoot' 0 1e-9

case_ "kernel triangle and bspline: sinc² and sinc⁴"
run resample kernel --filter triangle
near '."K_0.5"' 0.405285 1e-4    # (2/π)²
run resample kernel --filter bspline
near '."K_0.5"' 0.164256 1e-4    # (2/π)⁴
near '."K_0.25"' 0.657040 1e-4   # sinc(¼)⁴

case_ "kernel lanczos3: passband, stopband and overshoot"
run resample kernel --filter lanczos3
near '."K_0.25"' 1.0114 1e-4
near '."K_0.5"' 0.5017 1e-4
near '.stop_max' 0.0114 1e-4
near '.overshoot' 0.0731 1e-4

case_ "kernel --csv tables"
run resample kernel --filter mitchell --csv
expect_status 0
check "CSV header x,k" grep -qx "x,k" "$out"
check "401 rows" test "$(wc -l <"$out")" -eq 402

# --- G1: linear light on a 1-pixel checkerboard --------------------------------------------
awk 'BEGIN { print "P2\n512 512\n255"; for (y = 0; y < 512; y++) { s = ""; for (x = 0; x < 512; x++) s = s ((x + y) % 2 ? "255 " : "0 "); print s } }' >"$WORK/cb.pgm"
"$F" "$WORK/cb.pgm" -o "$WORK/cb.png"
histogram() { "$F" --to pgm --ascii <"$1" | awk 'NR > 3 { for (i = 1; i <= NF; i++) c[$i]++ } END { for (k in c) print k ":" c[k] }'; }

case_ "checkerboard halved in linear light is 188 everywhere (§10.4.4)"
run resample resize "$WORK/cb.png" --size 256x256 --filter box
expect_status 0
cp "$out" "$WORK/half.png"
check "every pixel 188" test "$(histogram "$WORK/half.png")" = "188:65536"

case_ "checkerboard halved as codes is 128 (--colorspace codes)"
run resample resize "$WORK/cb.png" --size 256x256 --filter box --colorspace codes
cp "$out" "$WORK/half_codes.png"
check "every pixel 128" test "$(histogram "$WORK/half_codes.png")" = "128:65536"

# --- zone plate 2048² -> 256² (docs/resample.md, Figures reproduced), targets ±10 % (AE) and ±0.01 (PR) -----------------------
"$R" render --scene zoneplate --param numax=0.125 --size 2048x2048 --spp 4 --pattern regular -o "$WORK/zp.pfm"
zone() {
  case_ "zone plate 2048² -> 256² with $1 (AE $2, PR $3)"
  "$R" resize --size 256x256 --filter "$1" <"$WORK/zp.pfm" >"$WORK/zp_$1.pfm"
  run_stdin "$WORK/zp_$1.pfm" resample metrics --zoneplate numax=1,width=256,height=256
  expect_status 0
  near '.ae' "$2" "$(awk -v a="$2" 'BEGIN { print a / 10 }')"
  near '.pr' "$3" 0.01
}
zone point 0.9726 0.9990
zone box 0.0842 0.9357
zone mitchell 0.0082 0.9090
zone lanczos3 0.0144 1.0093

case_ "metrics --zoneplate on an image of another size"
run_stdin "$WORK/zp_box.pfm" resample metrics --zoneplate numax=1,width=512,height=512
expect_clean_failure 3 resample

# --- properties --------------------------------------------------------------------------
case_ "identity resize of 8-bit codes is bit-exact"
run resample resize "$WORK/cb.png" --size 512x512 --filter lanczos3 --colorspace codes -o "$WORK/same.png"
expect_status 0
run fcompare "$WORK/cb.png" "$WORK/same.png"
expect_status 0

case_ "formats in and out: 16-bit PNG identity, EXR half, float TIFF, PGM on stdout"
"$R" render --scene siemens --size 64x64 --spp 4 --depth 16 -o "$WORK/s16.png"
run resample resize "$WORK/s16.png" --size 64x64 --filter box -o "$WORK/s16b.png"
check "16-bit box identity is bit-exact" cmp "$WORK/s16.png" "$WORK/s16b.png"
run resample resize "$WORK/s16.png" --size 32x32 --depth f16 -o "$WORK/h.exr"
expect_status 0
run fconv --info "$WORK/h.exr"
expect_json '.width' '32'
run resample resize "$WORK/h.exr" --size 16x16 --to tiff -o "$WORK/f.tif"
run fconv --info "$WORK/f.tif"
expect_json '.depth' '"float32"'
run resample resize "$WORK/s16.png" --size 32x32 --to pgm
check "16-bit PGM on standard output" test "$(head -c 2 "$out")" = "P5"
run resample resize "$WORK/h.exr" --size 16x16 --depth f16 --to png
expect_clean_failure 2 resample

case_ "threads 1 and 2 give identical bytes"
"$R" resize --size 301x177 --filter lanczos3 --threads 1 <"$WORK/zp.pfm" >"$WORK/t1.pfm"
"$R" resize --size 301x177 --filter lanczos3 --threads 2 <"$WORK/zp.pfm" >"$WORK/t2.pfm"
check "bitwise equal" cmp "$WORK/t1.pfm" "$WORK/t2.pfm"

case_ "a file streamed a band at a time gives the bytes of the whole-file read (standard input)"
# Files of raw Netpbm/PFM stream through the passes; standard input is read whole first.
"$R" resize "$WORK/zp.pfm" --size 301x177 --filter lanczos3 --threads 2 -o "$WORK/s1.pfm"
check "PFM, bitwise equal" cmp "$WORK/s1.pfm" "$WORK/t1.pfm"
"$R" render --scene zoneplate --size 300x200 --spp 1 --depth 16 --to pgm -o "$WORK/s16.pgm"
"$R" resize "$WORK/s16.pgm" --size 97x61 --filter mitchell --edge reflect -o "$WORK/s2.pgm"
"$R" resize --size 97x61 --filter mitchell --edge reflect --to pgm <"$WORK/s16.pgm" >"$WORK/s3.pgm"
check "16-bit PGM, reflect edges, bitwise equal" cmp "$WORK/s2.pgm" "$WORK/s3.pgm"
"$R" resize "$WORK/s16.pgm" --size 97x61 --filter lanczos3 --edge wrap --depth 8 -o "$WORK/s4.pgm"
"$R" resize --size 97x61 --filter lanczos3 --edge wrap --depth 8 --to pgm <"$WORK/s16.pgm" >"$WORK/s5.pgm"
check "wrap edges (whole-image passes), bitwise equal" cmp "$WORK/s4.pgm" "$WORK/s5.pgm"

case_ "a named pipe is read whole, with the bytes of the streamed file"
mkfifo "$WORK/pipe.pgm"
cat "$WORK/s16.pgm" >"$WORK/pipe.pgm" &
"$R" resize "$WORK/pipe.pgm" --size 97x61 --filter mitchell --edge reflect -o "$WORK/s6.pgm"
wait
check "bitwise equal" cmp "$WORK/s2.pgm" "$WORK/s6.pgm"

case_ "render is reproducible for a seed and differs for another"
"$R" render --scene edges --size 64x64 --spp 16 --pattern jitter --seed 7 >"$WORK/e1.pfm"
"$R" render --scene edges --size 64x64 --spp 16 --pattern jitter --seed 7 --threads 1 >"$WORK/e2.pfm"
"$R" render --scene edges --size 64x64 --spp 16 --pattern jitter --seed 8 >"$WORK/e3.pfm"
check "same seed, same bytes" cmp "$WORK/e1.pfm" "$WORK/e2.pfm"
check "other seed, other bytes" bash -c "! cmp -s '$WORK/e1.pfm' '$WORK/e3.pfm'"

case_ "metrics against a reference: identical images"
run_stdin "$WORK/e1.pfm" resample metrics --ref "$WORK/e2.pfm"
expect_json '.rmse' '0'
expect_json '.n_pixels' '4096'

case_ "display lcd replicates pixels"
run resample display "$WORK/half.png" --model lcd --factor 2 -o "$WORK/shown.png"
expect_status 0
check "512x512 of 188" test "$(histogram "$WORK/shown.png")" = "188:262144"

"$R" render --scene siemens --size 512x512 --spp 4 -o "$WORK/star.pfm"
display_rmse() {  # prefilter display: the A -> D error of the 2-D chain (§10.5 in 2-D)
  "$R" resize --size 64x64 --filter "$1" <"$WORK/star.pfm" | "$R" display --model "$2" --factor 8 |
    "$R" metrics --ref "$WORK/star.pfm" | jq .rmse
}
case_ "the dual prefilter has the smallest error on its own display (§10.5, 2-D)"
for d in tent gaussian:sigma=0.4; do
  dual=$(display_rmse "dual:$d" "$d")
  for other in box lanczos3 "$d"; do
    e=$(display_rmse "$other" "$d")
    check "dual:$d ($dual) < $other ($e) on a $d display" awk -v a="$dual" -v b="$e" 'BEGIN { exit !(a < b) }'
  done
done

"$R" render --scene sine --param f=0.1 --size 1000x2 --spp 64 --pattern regular -o "$WORK/sine.pfm"
case_ "spectrum: a box-filtered sine keeps sinc(f) of its amplitude"
run resample metrics "$WORK/sine.pfm" --beat 0.1,0
near '.beat_power' 0.120937 2e-4   # (½ sinc(0.1))² / 2

case_ "beat of two gratings appears when filtering ignores gamma (§10.4.4)"
"$R" render --scene sine --param f=0.30,f2=0.32 --size 1000x8 --spp 16 --depth 8 -o "$WORK/beat.png"
codes=$("$R" resize "$WORK/beat.png" --size 500x4 --filter box --colorspace codes | "$R" metrics --beat 0.6,0.64 | jq .beat_power)
linear=$("$R" resize "$WORK/beat.png" --size 500x4 --filter box | "$R" metrics --beat 0.6,0.64 | jq .beat_power)
check "beat power in codes ($codes) > 100 x linear light ($linear)" awk -v a="$codes" -v b="$linear" 'BEGIN { exit !(a > 100 * b) }'

"$R" render --scene point --param w=1000,zoom=1 --pixel-filter box --size 64x64 -o "$WORK/spot.exr"
case_ "--hicomp keeps an HDR highlight from ringing below zero"
"$R" resize "$WORK/spot.exr" --size 16x16 --filter lanczos3 -o "$WORK/ring.pfm"
run fconv --info "$WORK/ring.pfm"
check "lanczos3 rings negative without it" jq -e '.min[0] < -1' "$out"
"$R" resize "$WORK/spot.exr" --size 16x16 --filter lanczos3 --hicomp -o "$WORK/noring.pfm"
run fconv --info "$WORK/noring.pfm"
check "non-negative with --hicomp" jq -e '.min[0] >= 0' "$out"

case_ "mipkernel: Σw = 1, periodic with 2^L, not shift-invariant (fig. 10.12)"
run resample mipkernel --level 3 --pos 12.0,20.0,14.4
expect_status 0
check "weights sum to 1" awk -F, 'NR > 1 { a += $2; b += $3; c += $4 } END { exit !(a > 0.999999 && a < 1.000001 && c > 0.999999 && c < 1.000001) }' "$out"
# x = 12: t = 1, φ = 0 -> block 1 (texels 8..15) with 1/8 each; x = 20 is the same shifted by 8.
check "x = 12 is one block of 1/8" awk -F, 'NR > 1 && $1 >= 8 && $1 < 16 && $2 != 0.125 { bad = 1 } END { exit bad }' "$out"
check "x + 8 shifts by 8" awk -F, 'NR > 1 { w12[$1] = $2; w20[$1] = $3 } END { for (i in w12) if (w12[i] != w20[i + 8] + 0) exit 1 }' "$out"

case_ "mip build writes levels down to 1x1"
run resample mip build "$WORK/half.png" -o "$WORK/lvl"
expect_status 0
check "level 8 is 1x1" test "$("$F" --info "$WORK/lvl_8.png" | jq -c '[.width, .height]')" = "[1,1]"

case_ "normalmip keeps the slope variance of a sine height field (§10.7)"
"$R" render --scene sine --param f=0.0625 --size 1024x1024 --spp 1 --pattern regular -o "$WORK/h.pfm"
run resample normalmip --height-map --height-scale 2 "$WORK/h.pfm" -o "$WORK/nm"
expect_status 0
run fconv --info "$WORK/nm_4_cov.exr"
near '.max[0]' 0.0732233 2e-6   # sin²(2π/16)/2
near '.min[0]' 0.0732233 2e-6
near '.max[1]' 0 1e-6
run resample normalmip --height-map --height-scale 2 --naive "$WORK/h.pfm" -o "$WORK/naive"
run fconv --info "$WORK/naive_4_cov.exr"
near '.max[0]' 0 1e-12

case_ "texture: EWA and trilinear beat the aliasing lookups on an oblique checker plane (§10.6, small)"
awk 'BEGIN { print "P2\n256 256\n255"; for (y = 0; y < 256; y++) { s = ""; for (x = 0; x < 256; x++) s = s ((int(x / 8) + int(y / 8)) % 2 ? "255 " : "0 "); print s } }' >"$WORK/chk.pgm"
MAP=plane:h=1,pitch=30,fov=60,period=16
"$R" texture --tex "$WORK/chk.pgm" --map $MAP --size 64x48 --aniso-mask 4 -o "$WORK/mask.pgm"
"$R" texture --tex "$WORK/chk.pgm" --map $MAP --size 64x48 --ground-truth -o "$WORK/gt.pfm"
for m in nearest bilinear trilinear aniso:1 aniso:16 ewa; do
  "$R" texture --tex "$WORK/chk.pgm" --map $MAP --size 64x48 --method $m -o "$WORK/tex_$m.pfm"
  eval "rmse_${m%%:*}${m#*:}=$("$R" metrics "$WORK/tex_$m.pfm" --ref "$WORK/gt.pfm" --mask "$WORK/mask.pgm" | jq .rmse)"
done
lt() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }
check "ewa < trilinear ($rmse_ewaewa < $rmse_trilineartrilinear)" lt "$rmse_ewaewa" "$rmse_trilineartrilinear"
check "ewa < aniso:16" lt "$rmse_ewaewa" "$rmse_aniso16"
check "trilinear < bilinear" lt "$rmse_trilineartrilinear" "$rmse_bilinearbilinear"
check "trilinear < nearest" lt "$rmse_trilineartrilinear" "$rmse_nearestnearest"
check "aniso:1 is trilinear" cmp "$WORK/tex_aniso:1.pfm" "$WORK/tex_trilinear.pfm"

case_ "texture without a mapping, and --uv with one channel"
run resample texture --tex "$WORK/chk.pgm" --size 64x48
expect_clean_failure 2 resample
run resample texture --tex "$WORK/chk.pgm" --uv "$WORK/chk.pgm" --size 256x256
expect_clean_failure 3 resample

# --- bad input -----------------------------------------------------------------------------
case_ "empty standard input"
run_stdin /dev/null resample resize --size 10x10
expect_clean_failure 3 resample

"$R" render --scene zoneplate --size 64x64 --spp 1 --depth 8 -o "$WORK/zp64.png"
"$R" render --scene zoneplate --size 64x64 --spp 1 -o "$WORK/zp64.exr"
head -c 300 "$WORK/zp64.png" >"$WORK/trunc.png"
head -c 400 "$WORK/zp64.exr" >"$WORK/trunc.exr"
head -c 2000 "$WORK/zp.pfm" >"$WORK/trunc.pfm"
for f in trunc.png trunc.exr trunc.pfm; do
  case_ "truncated input $f"
  run resample resize "$WORK/$f" --size 10x10
  expect_clean_failure 3 resample
done

case_ "PFM of zero size"
printf 'Pf\n0 10\n-1.0\n' >"$WORK/zero.pfm"
run resample resize "$WORK/zero.pfm" --size 10x10
expect_clean_failure 3 resample

case_ "PFM header claiming more than 2^31 pixels"
printf 'Pf\n65536 65536\n-1.0\n' >"$WORK/huge.pfm"
head -c 4096 /dev/zero >>"$WORK/huge.pfm"
run resample resize "$WORK/huge.pfm" --size 10x10
expect_clean_failure 3 resample

for args in "--size 0x10" "--size 65536x65537" "--scale -1" "--filter lanczos:a=0" "--filter nosuchkernel" "--size 10x10 --edge nowhere"; do
  case_ "usage error: $args"
  # shellcheck disable=SC2086
  run resample resize "$WORK/zp64.png" $args
  expect_clean_failure 2 resample
done

case_ "unknown kernel in kernel and chain1d"
run resample kernel --filter nosuch
expect_clean_failure 2 resample
run resample chain1d --prefilter box --recon nosuch --freq 0.1
expect_clean_failure 2 resample

case_ "output into a folder that does not exist"
run resample resize "$WORK/zp64.png" --size 10x10 -o "$WORK/no/such/dir/out.png"
expect_clean_failure 4 resample

finish
