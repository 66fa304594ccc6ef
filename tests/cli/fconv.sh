#!/usr/bin/env bash
# fconv on small hand-made inputs: conversions whose results are known exactly,
# standard input/output pipelines, and bad input.
. "$(dirname "$0")/lib.sh"

# A unit tetrahedron: 4 vertices, 4 triangles, closed, genus 0.
cat >"$WORK/tet.off" <<'MESH'
OFF
4 4 6
0 0 0
1 0 0
0 1 0
0 0 1
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
MESH

case_ "info on an OFF file"
run fconv --info "$WORK/tet.off"
expect_status 0
expect_json '.kind' '"mesh"'
expect_json '.format' '"off"'
expect_json '.vertices' '4'
expect_json '.faces' '4'
expect_json '.bbox.min' '[0,0,0]'
expect_json '.bbox.max' '[1,1,1]'

case_ "OFF -> PLY (binary) -> OBJ -> OFF through pipes keeps every coordinate"
"$FEST_BIN/fconv" --to ply <"$WORK/tet.off" | "$FEST_BIN/fconv" --to obj | "$FEST_BIN/fconv" --to off >"$WORK/back.off"
check "pipeline succeeded" test -s "$WORK/back.off"
run fcompare --ordered "$WORK/tet.off" "$WORK/back.off"
expect_status 0
check "zero Hausdorff distance" grep -qx "hausdorff 0" "$out"
check "identical vertices" grep -qx "vertex_max_abs 0" "$out"

case_ "output format from the file extension, written atomically"
run fconv "$WORK/tet.off" -o "$WORK/tet.ply"
expect_status 0
expect_stdout_empty
check "PLY written" grep -q "^ply" "$WORK/tet.ply"
check "no temporary left behind" test -z "$(ls "$WORK" | grep '\.tmp\.')"

case_ "gzip output by extension and transparent gzip input"
run fconv "$WORK/tet.off" -o "$WORK/tet.off.gz"
expect_status 0
check "gzip magic" test "$(head -c 2 "$WORK/tet.off.gz" | od -An -tx1 | tr -d ' ')" = "1f8b"
run_stdin "$WORK/tet.off.gz" fconv --info
expect_json '.gzip' 'true'
expect_json '.vertices' '4'

case_ "a CSV table survives TSV and back"
printf 'x,y\n1,2.5\n-3,1e-300\n' >"$WORK/t.csv"
"$FEST_BIN/fconv" --to tsv <"$WORK/t.csv" | "$FEST_BIN/fconv" --to csv >"$WORK/t2.csv"
run fcompare "$WORK/t.csv" "$WORK/t2.csv"
expect_status 0

case_ "empty input"
run_stdin /dev/null fconv --to off
expect_clean_failure 3 fconv
expect_stderr_has "empty input"

case_ "unrecognised input"
printf 'hello, world\x01' >"$WORK/junk"
run fconv "$WORK/junk" --to off
expect_clean_failure 3 fconv

case_ "truncated mesh leaves no output file"
head -c 40 "$WORK/tet.ply" >"$WORK/cut.ply"
run fconv "$WORK/cut.ply" -o "$WORK/cut.off"
expect_clean_failure 3 fconv
check "no partial output" test ! -e "$WORK/cut.off"

case_ "a mesh cannot become an image"
run fconv "$WORK/tet.off" --to png
expect_clean_failure 2 fconv
expect_stderr_has "cannot convert a mesh"

case_ "unknown output format"
run fconv "$WORK/tet.off" --to docx
expect_clean_failure 2 fconv

case_ "unknown output extension"
run fconv "$WORK/tet.off" -o "$WORK/x.docx"
expect_clean_failure 2 fconv
check "nothing written" test ! -e "$WORK/x.docx"

case_ "unwritable output"
run fconv "$WORK/tet.off" -o "$WORK/no/such/dir/x.ply"
expect_clean_failure 4 fconv

case_ "bad --type value"
printf 'NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 1 1\nencoding: ascii\n\n1 2\n' >"$WORK/v.nrrd"
run fconv "$WORK/v.nrrd" --to mha --type complex
expect_clean_failure 2 fconv

# Clipping: -5 and 300 lie outside uint8's 0..255 (the other two do not), so exactly two
# values are clipped; nothing is clipped as int16.
case_ "--type uint8 warns with the count of clipped values"
printf 'NRRD0004\ntype: short\ndimension: 3\nsizes: 4 1 1\nencoding: ascii\n\n-5 0 100 300\n' >"$WORK/s.nrrd"
run fconv "$WORK/s.nrrd" --to nrrd --type uint8 --ascii
expect_status 0
expect_stderr_has "^fconv: warning: 2 of 4 values clipped to the uint8 range 0\.\.255"
check "clipped values are the bounds" sh -c "'$FEST_BIN/fconv' '$WORK/s.nrrd' --to nii --type uint8 2>/dev/null | '$FEST_BIN/fconv' --info | jq -e '.min == 0 and .max == 255'"
run fconv "$WORK/s.nrrd" --to nrrd --type int16
expect_status 0
check "no warning when nothing is clipped" test ! -s "$err"

# --rescale: v' = 0 + (v - (-5)) * 255 / (300 - (-5)), rounded: -5 -> 0, 0 -> 4.18 -> 4,
# 100 -> 87.79 -> 88, 300 -> 255 (the formula of fconv(1)).
case_ "--rescale maps the input range onto uint8"
"$FEST_BIN/fconv" "$WORK/s.nrrd" --to nrrd --type uint8 --rescale 2>"$err" | tail -c 4 | od -An -tu1 | tr -s ' ' >"$out"
check "values 0 4 88 255" test "$(cat "$out")" = " 0 4 88 255"
check "no clipping warning" test ! -s "$err"
run fconv "$WORK/s.nrrd" --to nrrd --rescale
expect_clean_failure 2 fconv
expect_stderr_has "--rescale"
run fconv "$WORK/s.nrrd" --to nrrd --rescale --type float32
expect_clean_failure 2 fconv

case_ "--frame on a mesh is a usage error"
run fconv "$WORK/tet.off" --frame 0 --to ply
expect_clean_failure 2 fconv

case_ "JPEG output: a flat colour comes back within rounding, --quality checked"
# A flat 16x16 block is pure DC in every 8x8 DCT block: at quality 95 (DC step 2 for
# luma, 3 for chroma) it returns within a few levels of (200, 100, 50).
{ printf 'P6\n16 16\n255\n'; for _ in $(seq 256); do printf '\310\144\062'; done; } >"$WORK/flat.ppm"
run fconv "$WORK/flat.ppm" -o "$WORK/flat.jpg"
expect_status 0
run fconv "$WORK/flat.jpg" --to ppm
expect_status 0
check "every pixel within 3 of (200,100,50)" test "$(tail -c 768 "$out" | od -An -v -tu1 | tr -s ' ' '\n' | grep -v '^$' |
  awk 'BEGIN{bad=0} {want=(NR%3==1)?200:(NR%3==2)?100:50; d=$1-want; if (d<-3||d>3) bad++} END{print bad}')" = 0
run fconv "$WORK/flat.ppm" --to jpg --quality 0
expect_clean_failure 2 fconv
run fconv "$WORK/flat.ppm" --to jpg --quality 101
expect_clean_failure 2 fconv

case_ "truncated PNG, JPEG and TIFF: one line, exit 3, no output file"
run fconv "$WORK/flat.ppm" -o "$WORK/flat.png"
run fconv "$WORK/flat.ppm" -o "$WORK/flat.tiff"
for f in png jpg tiff; do
  head -c $(( $(wc -c <"$WORK/flat.$f") - 12 )) "$WORK/flat.$f" >"$WORK/cut.$f"
  run fconv "$WORK/cut.$f" -o "$WORK/cut_out.pam"
  expect_clean_failure 3 fconv
  check "no output for cut.$f" test ! -e "$WORK/cut_out.pam"
done

finish
