#!/usr/bin/env bash
# Messages about bad input (issue 31): one line, exit 3, the input quoted as a few
# escaped bytes (\xNN for control and non-UTF-8 bytes), never a library's own words.
# Every input is made here, byte by byte, with printf or python3.
. "$(dirname "$0")/lib.sh"

# Standard error holds only printable ASCII and no line over 300 bytes.
expect_readable_stderr() {
  if LC_ALL=C grep -q '[^ -~]' "$err"; then fail "raw bytes on standard error: $(od -c "$err" | head -3)"; else pass; fi
  if awk 'length($0) > 300 { bad = 1 } END { exit !bad }' "$err"; then fail "a stderr line over 300 bytes"; else pass; fi
}
expect_no_library_text() {
  if grep -q 'json.exception\|last read\|what()' "$err"; then fail "library text: $(cat "$err")"; else pass; fi
}

case_ "OBJ: a control byte where a number belongs is quoted as \\x10 with the line"
printf 'v 0 0 0\nv 1 0 \x10\n' >"$WORK/ctl.obj"
run fconv --info "$WORK/ctl.obj"
expect_clean_failure 3 fconv
expect_stderr_has 'OBJ line 2: "\\x10" is not a number'
expect_readable_stderr

case_ "OFF: a non-UTF-8 byte in a coordinate"
printf 'OFF\n1 0 0\n0 0 \xe10\n' >"$WORK/bad.off"
run fconv --info "$WORK/bad.off"
expect_clean_failure 3 fconv
expect_stderr_has 'OFF line 3: "\\xe10" is not a number'
expect_readable_stderr

case_ "ascii STL: a mutated keyword"
printf 'solid t\nfacet norm\xe1l 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n' >"$WORK/bad.stl"
run fconv --info "$WORK/bad.stl"
expect_clean_failure 3 fconv
expect_stderr_has 'norm\\xe1l'
expect_readable_stderr

case_ "PFM: a scale with a control byte"
{ printf 'Pf\n1 1\n-\x11\n'; printf '\0\0\0\0'; } >"$WORK/bad.pfm"
run fconv --info "$WORK/bad.pfm"
expect_clean_failure 3 fconv
expect_stderr_has "scale '-\\\\x11'"
expect_readable_stderr

case_ "PGM: a maxval run into 1,234 bytes of pixel data is quoted short"
{ printf 'P5\n2 2\n'; python3 -c 'import sys; sys.stdout.buffer.write(bytes([7]*1234))'; } >"$WORK/long.pgm"
run fconv --info "$WORK/long.pgm"
expect_clean_failure 3 fconv
expect_stderr_has 'maxval .\\x07\\x07.*\.\.\.'
expect_readable_stderr

case_ "MetaImage: a header line of binary bytes"
printf 'ObjectType = Image\nx\x9c\x01\x02\nNDims = 3\n' >"$WORK/bad.mha"
run fconv --info "$WORK/bad.mha"
expect_clean_failure 3 fconv
expect_stderr_has "MetaImage header line 2: 'x\\\\x9c\\\\x01\\\\x02'"
expect_readable_stderr

case_ "EXR: an attribute name with a control byte, truncated after it"
printf 'v/1\x01\x02\x00\x00\x00ab\x18\x00int\x00' >"$WORK/bad.exr"
run fconv --info "$WORK/bad.exr"
expect_clean_failure 3 fconv
expect_stderr_has "attribute 'ab\\\\x18'"
expect_readable_stderr

case_ "PLY: a property name that is not UTF-8 is escaped in --info's JSON"
printf 'ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nproperty uchar \xf2ed\nend_header\n0 0 0 1\n' >"$WORK/name.ply"
run fconv --info "$WORK/name.ply"
expect_status 0
expect_json '.not_kept[0] | contains("\\xf2ed")' 'true'

case_ "fconv: text that reads only as a table, asked to become a mesh, is bad input (3)"
printf 'w 1,2,3\nv 0 0 0\n' >"$WORK/mutated.obj"
run fconv "$WORK/mutated.obj" --to ply -o "$WORK/out.ply"
expect_clean_failure 3 fconv
expect_stderr_has 'not a mesh file fest reads'
check "no output" test ! -e "$WORK/out.ply"

case_ "NIfTI: a NaN voxel size is refused naming pixdim[2]"
python3 - "$WORK/nan.nii" <<'PY'
import struct, sys
h = bytearray(352)
struct.pack_into('<i', h, 0, 348)
struct.pack_into('<8h', h, 40, 3, 2, 2, 2, 1, 1, 1, 1)     # dim
struct.pack_into('<hh', h, 70, 2, 8)                        # datatype uint8, bitpix
struct.pack_into('<8f', h, 76, 1, 1, float('nan'), 1, 1, 0, 0, 0)  # pixdim
struct.pack_into('<f', h, 108, 352.0)                       # vox_offset
h[344:348] = b'n+1\0'
open(sys.argv[1], 'wb').write(bytes(h) + bytes(8))
PY
run fconv "$WORK/nan.nii" --to nrrd -o "$WORK/nan.nrrd"
expect_clean_failure 3 fconv
expect_stderr_has 'pixdim\[2\].*nan'
check "no output" test ! -e "$WORK/nan.nrrd"

case_ "radiosity scene: broken JSON is named by line, column and byte, not by the library"
printf '{\n  "objects": [\n    tru\xf4\n  ]\n}\n' >"$WORK/scene.json"
run radiosity solve "$WORK/scene.json" --no-mesh -o "$WORK/s.ply"
expect_clean_failure 3 radiosity
expect_stderr_has 'not JSON: .* at line 3, column [0-9]* .byte [0-9]*.'
expect_no_library_text
expect_readable_stderr

case_ ".ltx: a header that is not JSON"
python3 - "$WORK/bad.ltx" <<'PY'
import struct, sys
hdr = b'{"format": "ltx", "version": 1,\n "x": nul\x01}'
open(sys.argv[1], 'wb').write(b'LUMITEX1' + struct.pack('<I', len(hdr)) + hdr)
PY
run brdffit info "$WORK/bad.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has 'not JSON: .* at line 2, column'
expect_no_library_text
expect_readable_stderr

case_ ".ltx: a header field of the wrong type"
python3 - "$WORK/type.ltx" <<'PY'
import struct, sys
hdr = b'{"format": "ltx", "version": 1, "mesh_sha256": "", "images": [], "lumitexels": "many", "samples": 0}'
open(sys.argv[1], 'wb').write(b'LUMITEX1' + struct.pack('<I', len(hdr)) + hdr)
PY
run brdffit info "$WORK/type.ltx"
expect_clean_failure 3 brdffit
expect_stderr_has 'field "lumitexels": expected a number, got a string'
expect_no_library_text

case_ "lights: a station file that is not JSON"
printf '{"lights": [tru\x01' >"$WORK/station.json"
run lights --station "$WORK/station.json" list
expect_clean_failure 3 lights
expect_stderr_has 'station: not JSON: .* at line 1, column 16 .byte 16.'
expect_no_library_text
expect_readable_stderr


case_ "quatpath keys and patnet events: JSON failures in fest's words, with file:line"
printf '{"t": 0, "pos": [0,0,0], "quat": [1,0,0,0]}\n{"t": 1, "pos": [1,0, "quat": [1,0,0,0]}\n' > "$WORK/keys.jsonl"
run quatpath "$WORK/keys.jsonl" -o "$WORK/path.csv"
expect_clean_failure 3 quatpath
expect_stderr_has 'malformed key: not JSON: .* at line 1, column 29 .byte 29. .*keys.jsonl:2'
expect_no_library_text
printf '{"t": "x", "pos": [0,0,0], "quat": [1,0,0,0]}\n' > "$WORK/keys2.jsonl"
run quatpath "$WORK/keys2.jsonl" -o "$WORK/path.csv"
expect_clean_failure 3 quatpath
expect_stderr_has 'malformed key: expected a number, got a string .*keys2.jsonl:1'
expect_no_library_text

case_ "lmfsim trajectories: a frame number beyond long's range and a binary header are refused in plain words"
printf '{"bodies": [{"name": "p", "type": "particle", "mass": 1}], "sim": {"t_end": 0.002, "dt": 0.001}}\n' > "$WORK/p.json"
"$FEST_BIN/lmfsim" run < "$WORK/p.json" > "$WORK/p.csv"
{ head -1 "$WORK/p.csv"; echo "1e300,0,p,0,0,0,1,0,0,0,0,0,0,0,0,0"; } > "$WORK/p_bad.csv"
run lmfsim diff "$WORK/p.csv" "$WORK/p_bad.csv"
expect_clean_failure 3 lmfsim
expect_stderr_has 'frame 1e300 is not a whole number in \[0, 1e15\] .*p_bad.csv:2'
printf 'fr\001ame\n' > "$WORK/p_bin.csv"
run lmfsim diff "$WORK/p.csv" "$WORK/p_bin.csv"
expect_clean_failure 3 lmfsim
expect_readable_stderr

case_ "hdrmerge session: manifest fields of another type, an angle index beyond int and a light naming a path"
echo '{"version": 1, "status": 5}' > "$WORK/m_status.json"
run hdrmerge --manifest "$WORK/m_status.json"
expect_clean_failure 3 hdrmerge
expect_stderr_has 'the session is not complete'
expect_no_library_text
echo '{"version": 1, "status": "complete", "shots": [{"file": "a.png", "sha256": "x", "exposure_s": 0.1, "angle_index": 1e300, "angle_deg": 0}], "sets": [{"light": "L0", "shots": [0]}]}' > "$WORK/m_angle.json"
run hdrmerge --manifest "$WORK/m_angle.json"
expect_clean_failure 3 hdrmerge
expect_stderr_has 'shots\[0\].angle_index must be an integer in \[0, 1000000\]'
echo '{"version": 1, "status": "complete", "shots": [], "sets": [{"light": "../x", "shots": []}]}' > "$WORK/m_light.json"
run hdrmerge --manifest "$WORK/m_light.json"
expect_clean_failure 3 hdrmerge
expect_stderr_has 'sets\[0\].light "../x" is not a light id'

finish
