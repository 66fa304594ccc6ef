#!/usr/bin/env bash
# VTK datasets checked by fest before VTK parses them (issue 31): legal re-encodings of a
# `lemtrace gen` grid (UInt32 block headers, big-endian data, encoded independently by
# vtk_robustness.py) read as the original does; broken copies (attributes changed without
# re-encoding the bytes, a mistyped type, an appended length past the end of the file, a
# negative offset, ...) give one line and exit 3 in fconv --info, fconv --to vtk and
# lemtrace, never a signal and never VTK's text alone.
. "$(dirname "$0")/lib.sh"
HERE="$(dirname "$0")"

run lemtrace gen helix --n 3 --jitter 0.2 --seed 3 -o "$WORK/good.vtu"
python3 "$HERE/vtk_robustness.py" "$WORK/good.vtu" "$WORK/v" || { echo "vtk_robustness.py failed" >&2; exit 1; }
"$FEST_BIN/fconv" "$WORK/good.vtu" -o "$WORK/good_again.vtu"
"$FEST_BIN/fconv" --info "$WORK/good.vtu" | jq -S 'del(.file, .bytes)' >"$WORK/good.json"

for variant in ok_uint32 ok_bigendian ok_uint32_bigendian; do
  case_ "$variant.vtu: legal encoding, read as the original"
  run fconv --info "$WORK/v/$variant.vtu"
  expect_status 0
  check "same description as the original" cmp -s <(jq -S 'del(.file, .bytes)' "$out") "$WORK/good.json"
  run fconv "$WORK/v/$variant.vtu" -o "$WORK/again.vtu"
  expect_status 0
  check "rewritten byte for byte as the original is" cmp -s "$WORK/again.vtu" "$WORK/good_again.vtu"
  run lemtrace "$WORK/v/$variant.vtu" --seed-point 0.4,0,-0.9
  expect_status 0
done

# variant|what the one line must say
while IFS='|' read -r variant message; do
  f="$WORK/v/$variant.vtu"
  case_ "$variant.vtu: fconv --info"
  run fconv --info "$f"
  expect_clean_failure 3 fconv
  expect_stderr_has "$message"
  case_ "$variant.vtu: fconv --to vtk writes nothing"
  run fconv --to vtk "$f" -o "$WORK/out.vtk"
  expect_clean_failure 3 fconv
  check "no output file" test ! -e "$WORK/out.vtk"
  case_ "$variant.vtu: lemtrace"
  run lemtrace "$f" --seed-point 0.4,0,-0.9
  expect_clean_failure 3 lemtrace
  expect_stderr_has "$message"
done <<'CASES'
bad_uint32|DataArray "LemtraceKind" at byte [0-9]+: its 6 bytes hold 4 strings, not 1
bad_no_header_type|DataArray "LemtraceKind" at byte [0-9]+: its 6 bytes hold 4 strings, not 1
bad_bigendian|DataArray "LemtraceKind" at byte [0-9]+: its block header "\\x06\\x00.*declares [0-9]+ bytes, more than
bad_type_typo|DataArray "velocity" at byte [0-9]+: type "Flaot64" is not a VTK type
bad_type_int8|DataArray "velocity" at byte [0-9]+: its block holds 1536 bytes, but the markup asks for 192 values of Int8
bad_long_block|DataArray "velocity" at byte [0-9]+: its block header .* declares 1000000000 bytes
bad_negative_offset|DataArray "velocity" at byte [0-9]+: offset "-[0-9]+" is not a byte offset
bad_truncated|vtu: DataArray ".*" at byte [0-9]+: .*past the end
bad_unreferenced|bytes before its block, from byte [0-9]+, belong to no array
CASES

case_ "markup that is not well-formed XML: where and why in fest's words, not VTK's"
# A bare '&' in an attribute value: fest's scan of the blocks passes, expat refuses it.
sed 's/Name="velocity"/Name="vel\&ocity"/' "$WORK/good.vtu" > "$WORK/not_xml.vtu"
run fconv --info "$WORK/not_xml.vtu"
expect_clean_failure 3 fconv
expect_stderr_has '^fconv: error: vtu: the markup is not well-formed XML at line [0-9]+, column [0-9]+ \(byte [0-9]+\) \(.*not_xml.vtu\)$'
check "no VTK or expat sentence" sh -c "! grep -q 'Error parsing XML\\|not well-formed (' '$err'"
case_ "the same with -v: expat's reason as a second line, the detail"
run fconv -v --info "$WORK/not_xml.vtu"
expect_status 3
expect_stderr_has '^fconv: detail: expat: "not well-formed \(invalid token\)"'

# VTK's own reasons (what fest's pre-check leaves to VTK's readers), said in fest's words:
# the piece and the array, never VTK's sentence; VTK's text only with -v. A small ASCII
# grid of two tetrahedra, edited to break one rule at a time.
cat >"$WORK/tets.vtu" <<'VTU'
<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="2">
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">
          0 0 0 1 0 0 0 1 0 0 0 1 1 1 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">
          0 1 2 3 1 2 3 4
        </DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">
          4 8
        </DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">
          10 10
        </DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
VTU
run fconv --info "$WORK/tets.vtu"
expect_status 0
# variant|sed edit|what the one line must say
while IFS='|' read -r variant edit message; do
  sed "$edit" "$WORK/tets.vtu" >"$WORK/$variant.vtu"
  case_ "$variant.vtu: VTK's reason in fest's words"
  run fconv --info "$WORK/$variant.vtu"
  expect_clean_failure 3 fconv
  expect_stderr_has "^fconv: error: vtu: $message \\(.*$variant.vtu\\)\$"
  check "no VTK sentence" sh -c "! grep -q 'VTK\\|Cannot read\\|because the' '$err'"
  run lemtrace classify "$WORK/$variant.vtu"
  expect_clean_failure 3 lemtrace
  expect_stderr_has "vtu: $message"
  case_ "$variant.vtu with -v: VTK's sentence as the detail"
  run fconv -v --info "$WORK/$variant.vtu"
  expect_status 3
  expect_stderr_has '^fconv: detail: VTK: Cannot read cell'
done <<'CASES'
offsets_not_increasing|s/^          4 8$/          9 8/|the "offsets" of the cells of piece 0 do not start at 0 and increase from cell to cell
no_types_array|s/Name="types"/Name="typez"/|the cells of piece 0 have no "types" array
CASES

case_ "a stray byte between <AppendedData> and its '_': refused, not handed to VTK (was SIGSEGV)"
python3 - "$WORK/good.vtu" "$WORK/stray.vtu" <<'PY2'
import sys
b = open(sys.argv[1], 'rb').read()
tag = b.index(b'<AppendedData')
under = b.index(b'_', b.index(b'>', tag))
open(sys.argv[2], 'wb').write(b[:under - 1] + b'$' + b[under:])
PY2
run fconv --info "$WORK/stray.vtu"
expect_clean_failure 3 fconv
expect_stderr_has "<AppendedData> at byte [0-9]+: \"[$]\" at byte [0-9]+ before the '_' that starts its data"

case_ "legacy .vtk cut short or with a count past its data: one line, exit 3"
run lemtrace gen helix --n 2 --to vtk -o "$WORK/good.vtk"
head -c 3000 "$WORK/good.vtk" >"$WORK/short.vtk"
run fconv --info "$WORK/short.vtk"
expect_clean_failure 3 fconv
sed '0,/^POINTS [0-9]*/s//POINTS 999999999/' "$WORK/good.vtk" >"$WORK/count.vtk"
run lemtrace "$WORK/count.vtk" --seed-point 0.4,0,-0.9
expect_clean_failure 3 lemtrace
finish
