#!/usr/bin/env bash
# fcompare on inputs whose differences are known by construction.
. "$(dirname "$0")/lib.sh"

# Two unit squares, the second lifted by 0.25: every point is exactly 0.25 from the
# other surface, so Hausdorff = RMS = 0.25.
square() {
  printf 'OFF\n4 2 0\n0 0 %s\n1 0 %s\n1 1 %s\n0 1 %s\n3 0 1 2\n3 0 2 3\n' "$1" "$1" "$1" "$1"
}
square 0 >"$WORK/a.off"
square 0.25 >"$WORK/b.off"

case_ "identical meshes"
run fcompare "$WORK/a.off" "$WORK/a.off"
expect_status 0
check "hausdorff 0" grep -qx "hausdorff 0" "$out"

case_ "lifted square: within a loose tolerance"
run fcompare --tol 0.3 "$WORK/a.off" "$WORK/b.off"
expect_status 0
check "hausdorff 0.25" grep -qx "hausdorff 0.25" "$out"
check "rms 0.25" grep -qx "rms 0.25" "$out"

case_ "lifted square: outside a tight tolerance"
run fcompare --tol 0.1 "$WORK/a.off" "$WORK/b.off"
expect_status 1
expect_stderr_has "^fcompare: hausdorff = 0.25 exceeds 0.1"

case_ "per-metric threshold replaces the default"
run fcompare -t 'hausdorff<=0.3' -t 'rms<=0.26' "$WORK/a.off" "$WORK/b.off" --report "$WORK/r.json"
expect_status 0
check "report has both checks" test "$(jq '[.checks[] | select(.metric=="rms" or .metric=="hausdorff")] | length' "$WORK/r.json")" = 2
check "report rms" test "$(jq .metrics.rms "$WORK/r.json")" = "0.25"

case_ "different counts fail unless ignored"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n' >"$WORK/tri.off"
run fcompare --tol 1 "$WORK/a.off" "$WORK/tri.off"
expect_status 1
expect_stderr_has "vertex_count_diff"
run fcompare --tol 1 --ignore-counts --ignore-topology "$WORK/a.off" "$WORK/tri.off"
expect_status 0

# Images: 2x2 grey PGMs differing by 3 in one pixel: RMSE = sqrt(9/4) = 1.5,
# PSNR = 20 log10(255/1.5) = 20 log10(170) = 44.60898, max abs 3.
printf 'P2\n2 2\n255\n10 20\n30 40\n' >"$WORK/a.pgm"
printf 'P2\n2 2\n255\n10 20\n30 43\n' >"$WORK/b.pgm"
# The octahedron (+-1 on each axis), and a copy with its vertex list reversed (faces
# renumbered to match): the same surface, so the order-independent measures are 0; vertex
# i against vertex i, the reversal pairs (1,0,0) with (0,0,-1) (difference 1) and
# (0,1,0) with (0,-1,0): largest coordinate difference 2.
octahedron() {
  printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n'
  printf '3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n'
}
octahedron >"$WORK/oct.off"
awk 'NR==1 || NR==2 {print; next} NR<=8 {v[NR-3]=$0; if (NR==8) for (i=5;i>=0;--i) print v[i]; next}
     {printf "3 %d %d %d\n", 5-$2, 5-$3, 5-$4}' "$WORK/oct.off" >"$WORK/oct_reversed.off"

case_ "Edgebreaker round trip (ebcode | ebdecode, lossless): clean by default, no order-dependent metric"
"$FEST_BIN/ebcode" --qp 0 <"$WORK/oct.off" | "$FEST_BIN/ebdecode" --to off >"$WORK/oct_eb.off"
check "round trip written" test -s "$WORK/oct_eb.off"
run fcompare "$WORK/oct.off" "$WORK/oct_eb.off"
expect_status 0
check "hausdorff 0" grep -qx "hausdorff 0" "$out"
check "no vertex_max_abs without --ordered" sh -c "! grep -q '^vertex_max_abs' '$out'"

case_ "a permuted copy: order-independent measures 0; --ordered reports the permutation's 2"
run fcompare "$WORK/oct.off" "$WORK/oct_reversed.off"
expect_status 0
check "hausdorff 0" grep -qx "hausdorff 0" "$out"
check "no vertex_max_abs" sh -c "! grep -q '^vertex_max_abs' '$out'"
run fcompare --ordered "$WORK/oct.off" "$WORK/oct_reversed.off"
expect_status 0
check "vertex_max_abs 2" grep -qx "vertex_max_abs 2" "$out"
run fcompare --ordered -t 'vertex_max_abs<=0' "$WORK/oct.off" "$WORK/oct_reversed.off"
expect_status 1
expect_stderr_has "vertex_max_abs = 2 exceeds 0"

case_ "a check on vertex_max_abs without --ordered is a usage error naming the measured metrics"
run fcompare -t 'vertex_max_abs<=0' "$WORK/oct.off" "$WORK/oct_reversed.off"
expect_status 2
expect_stderr_has "vertex_max_abs"

case_ "images: RMSE, PSNR, max abs"
run fcompare "$WORK/a.pgm" "$WORK/b.pgm" -t 'max_abs<=3' -t 'psnr>=44.6' --report "$WORK/img.json"
expect_status 0
check "rmse 1.5" grep -qx "rmse 1.5" "$out"
check "psnr" test "$(jq '.metrics.psnr * 1000 | floor' "$WORK/img.json")" = "44608"
run fcompare "$WORK/a.pgm" "$WORK/b.pgm" -t 'psnr>=50'
expect_status 1
expect_stderr_has "psnr = 44.6"

case_ "images of different sizes differ (status 1)"
printf 'P2\n1 1\n255\n10\n' >"$WORK/c.pgm"
run fcompare "$WORK/a.pgm" "$WORK/c.pgm"
expect_status 1

# Label volumes 4x1x1: a = 1 1 2 0, b = 1 2 2 0 -> Dice 2/3 for both labels.
printf 'NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 1 1\nencoding: ascii\n\n1 1 2 0\n' >"$WORK/a.nrrd"
printf 'NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 1 1\nencoding: ascii\n\n1 2 2 0\n' >"$WORK/b.nrrd"
case_ "volumes: Dice per label"
run fcompare "$WORK/a.nrrd" "$WORK/b.nrrd" -t 'dice>=0.66' -t 'max_abs<=1' --report "$WORK/vol.json"
expect_status 0
check "dice 2/3" test "$(jq '.details.dice_per_label["1"] * 3 | round' "$WORK/vol.json")" = "2"
run fcompare "$WORK/a.nrrd" "$WORK/b.nrrd" -t 'dice>=0.9'
expect_status 1

case_ "tables: max abs per column"
printf 'x,y\n1,2\n3,4\n' >"$WORK/a.csv"
printf 'x,y\n1,2.5\n3,4\n' >"$WORK/b.csv"
run fcompare "$WORK/a.csv" "$WORK/b.csv" --tol 0.5
expect_status 0
run fcompare "$WORK/a.csv" "$WORK/b.csv" --tol 0.4
expect_status 1
expect_stderr_has "max_abs = 0.5 exceeds 0.4"

# The committed two-tetrahedron grid, and copies with one velocity component changed by
# 0.25 and with the cells' shared face reordered.
vtu="$FEST_FIXTURES/dataset/rotating_tets.vtu"
sed 's/^          -1 1 0$/          -1 1.25 0/' "$vtu" >"$WORK/moved.vtu"
sed 's/^          1 2 3 4$/          1 3 2 4/' "$vtu" >"$WORK/flipped.vtu"
case_ "datasets: identical through another format"
"$FEST_BIN/fconv" --to vtk <"$vtu" >"$WORK/tets.vtk"
run fcompare "$vtu" "$WORK/tets.vtk"
expect_status 0
check "no cell differences" grep -qx "cell_diffs 0" "$out"
case_ "datasets: an array value off by 0.25"
run fcompare "$vtu" "$WORK/moved.vtu" --report "$WORK/ds.json"
expect_status 1
expect_stderr_has "max_abs = 0.25 exceeds 0"
check "the array is named" test "$(jq '.details.arrays["point:velocity"]' "$WORK/ds.json")" = "0.25"
run fcompare --tol 0.25 "$vtu" "$WORK/moved.vtu"
expect_status 0
case_ "datasets: a reordered cell"
run fcompare "$vtu" "$WORK/flipped.vtu"
expect_status 1
expect_stderr_has "cell_diffs = 1 exceeds 0"

case_ "JSON: numbers by tolerance, structure exactly"
printf '{"a": 1, "b": [1, 2], "s": "x"}' >"$WORK/a.json"
printf '{"b": [1, 2.5], "a": 1, "s": "x"}' >"$WORK/b.json"
printf '{"a": 1, "b": [1, 2], "s": "y"}' >"$WORK/c.json"
run fcompare "$WORK/a.json" "$WORK/b.json" --tol 0.5
expect_status 0
run fcompare "$WORK/a.json" "$WORK/b.json"
expect_status 1
run fcompare "$WORK/a.json" "$WORK/c.json" --tol 1 --report "$WORK/j.json"
expect_status 1
check "first structural difference" test "$(jq -r .details.first_structural_diff "$WORK/j.json")" = "/s"

# README's golden-file example: 2x2 grey images differing by 1 in one pixel:
# RMSE = sqrt(1/4) = 0.5, PSNR = 20 log10(255/0.5) = 54.15 dB, max abs 1.
printf 'P2\n2 2\n255\n10 20\n30 40\n' | "$FEST_BIN/fconv" --to png -o "$WORK/render.png"
printf 'P2\n2 2\n255\n10 20\n30 41\n' | "$FEST_BIN/fconv" --to png -o "$WORK/golden.png"
case_ "an explicit criterion replaces the defaults of its family (README example)"
run fcompare "$WORK/render.png" "$WORK/golden.png" -t 'psnr>=40' --report "$WORK/readme.json"
expect_status 0
check "psnr 54.15" test "$(jq '.metrics.psnr * 100 | floor' "$WORK/readme.json")" = "5415"
check "only the asked check" test "$(jq -c '[.checks[].metric]' "$WORK/readme.json")" = '["psnr"]'
run fcompare "$WORK/render.png" "$WORK/golden.png" -t 'psnr>=60'
expect_status 1
expect_stderr_has "psnr = 54.1"
case_ "an explicit --tol stays beside a criterion of its family"
run fcompare "$WORK/render.png" "$WORK/golden.png" --tol 0 -t 'psnr>=40'
expect_status 1
expect_stderr_has "max_abs = 1 exceeds 0"

# RGB against RGBA: the same colours, the alpha of the second compared with opaque.
printf 'P3\n2 1\n255\n10 20 30 40 50 60\n' >"$WORK/rgb.ppm"
printf 'P7\nWIDTH 2\nHEIGHT 1\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n' >"$WORK/rgba.pam"
printf '\012\024\036\377\050\062\074\377' >>"$WORK/rgba.pam"
cp "$WORK/rgba.pam" "$WORK/rgba_half.pam"
printf '\200' | dd of="$WORK/rgba_half.pam" bs=1 seek=$(( $(stat -c %s "$WORK/rgba.pam") - 1 )) conv=notrunc status=none
case_ "RGB against opaque RGBA: equal colours, alpha reported apart"
run fcompare "$WORK/rgb.ppm" "$WORK/rgba.pam" --report "$WORK/alpha.json"
expect_status 0
check "alpha measured in b" test "$(jq -r .details.alpha.in "$WORK/alpha.json")" = "b"
check "colour max abs 0" test "$(jq .metrics.max_abs "$WORK/alpha.json")" = "0"
case_ "RGB against RGBA with a half-transparent pixel: alpha differs by 255-128"
run fcompare "$WORK/rgb.ppm" "$WORK/rgba_half.pam" --report "$WORK/alpha2.json"
expect_status 1
expect_stderr_has "alpha_max_abs = 127 exceeds 0"
check "colour still equal" test "$(jq .metrics.max_abs "$WORK/alpha2.json")" = "0"

case_ "bad usage and bad input"
run fcompare "$WORK/a.off" "$WORK/a.pgm"
expect_clean_failure 3 fcompare
run fcompare -t 'hausdorff=1' "$WORK/a.off" "$WORK/a.off"
expect_clean_failure 2 fcompare
run fcompare -t 'dice>=1' "$WORK/a.off" "$WORK/a.off"
expect_clean_failure 2 fcompare
run fcompare --tol -1 "$WORK/a.off" "$WORK/a.off"
expect_clean_failure 2 fcompare
run_stdin /dev/null fcompare - "$WORK/a.off"
expect_clean_failure 3 fcompare

finish
