#!/usr/bin/env bash
# ebcode / ebdecode on small hand-made meshes: golden CLERS strings (docs/ebcode.md §1),
# exact round trips of closed, open, several-component and non-manifold input (faces
# compared as position triples, orientation kept), the container's bad-input cases,
# and the model subcommand's numbers (seed Tables 5.1/5.2, Theorem 5.7.1).
. "$(dirname "$0")/lib.sh"

# faces FILE.off: one line per face, its vertex positions rotated to start at the
# smallest, sorted -- the face set up to vertex numbering, with orientation.
faces() {
  awk 'NR == 1 { next }
       NR == 2 { nv = $1; nf = $2; next }
       nv > 0 { p[n++] = $1 " " $2 " " $3; nv--; next }
       $1 == 3 { a = p[$2]; b = p[$3]; c = p[$4]
                 if (b < a && b < c) { t = a; a = b; b = c; c = t } else if (c < a && c < b) { t = c; c = b; b = a; a = t }
                 print a " | " b " | " c }' "$1" | sort
}
vertex_count() { awk 'NR == 2 { print $1; exit }' "$1"; }

off() {  # off NAME NV "x y z ..." "a b c ..." -- writes $WORK/NAME.off
  local name="$1" nv="$2" verts="$3" tris="$4"
  {
    echo OFF
    echo "$nv $(echo "$tris" | wc -w | awk '{print $1 / 3}') 0"
    echo "$verts" | xargs -n 3
    echo "$tris" | xargs -n 3 | sed 's/^/3 /'
  } >"$WORK/$name.off"
}

off tet 4 "0 0 0 1 0 0 0 1 0 0 0 1" "0 1 2 0 3 1 0 2 3 1 3 2"

case_ "golden string of the corner tetrahedron (0, e1, e2, e3)"
run ebcode --symbols "$WORK/tet.off"
expect_status 0
check "CRE" test "$(cat "$out")" = "CRE"

case_ "golden strings of CGAL's octahedron, icosahedron and cube"
if [ -f "$FEST_TESTDATA/meshes/octahedron.off" ]; then
  for pair in octahedron:CCRCRRE icosahedron:CCCRCCRCRCRCRRCRRRE cube:CCCCRRCRRLE; do
    run ebcode --symbols "$FEST_TESTDATA/meshes/${pair%%:*}.off"
    check "${pair%%:*} gives ${pair##*:}" test "$(cat "$out")" = "${pair##*:}"
  done
fi

# Non-manifold and open cases (docs/ebcode.md §5), integer coordinates (exact in float32).
V7="0 0 0 1 0 0 0 1 0 0 0 1 -1 0 0 0 -1 0 0 0 -1"
off bowtie 7 "$V7" "0 1 2 0 3 1 0 2 3 1 3 2 0 4 5 0 6 4 0 5 6 4 6 5"
off fin 5 "0 0 0 1 0 0 0 1 0 0 -1 0 0 0 1" "0 1 2 1 0 3 0 1 4"
off flipped 4 "0 0 0 1 0 0 0 1 0 0 0 1" "0 1 2 0 3 1 0 2 3 1 2 3"
off duplicated 4 "0 0 0 1 0 0 0 1 0 0 0 1" "0 1 2 0 3 1 0 2 3 1 3 2 0 1 2"
off moebius 10 "0 0 0 0 0 1 1 0 0 1 0 1 2 0 0 2 0 1 3 0 0 3 0 1 4 0 0 4 0 1" \
  "0 1 3 0 3 2 2 3 5 2 5 4 4 5 7 4 7 6 6 7 9 6 9 8 8 9 0 8 0 1"
off two_parts 8 "0 0 0 1 0 0 0 1 0 0 0 1 5 5 5 6 5 5 5 6 5 9 9 9" "0 1 2 0 3 1 0 2 3 1 3 2 4 5 6"

for name in tet bowtie fin flipped duplicated moebius two_parts; do
  for conn in auto static adaptive raw; do
    case_ "$name round trip, --conn $conn, lossless"
    run ebcode --qp 0 --conn "$conn" "$WORK/$name.off" -o "$WORK/$name.ebm"
    if [ "$name" != tet ] && [ "$conn" = static ] && [ "$rc" -eq 3 ]; then
      # The chapter's coder is proved for genus 0 only; where a cut mesh breaks its
      # exclusions it refuses cleanly (auto then uses the adaptive coder).
      expect_stderr_has "static model cannot code"
      continue
    fi
    expect_status 0
    run ebdecode --to off "$WORK/$name.ebm"
    expect_status 0
    check "same vertex count" test "$(vertex_count "$out")" = "$(vertex_count "$WORK/$name.off")"
    faces "$WORK/$name.off" >"$WORK/want"
    faces "$out" >"$WORK/got"
    check "same faces, same orientation" diff "$WORK/want" "$WORK/got"
  done
done

case_ "--no-stitch keeps the bow-tie's copy of its shared vertex"
"$FEST_BIN/ebcode" --qp 0 --report "$WORK/bowtie.json" "$WORK/bowtie.off" -o "$WORK/bowtie.ebm"
run ebdecode --no-stitch --to off "$WORK/bowtie.ebm"
expect_status 0
check "one stitch pair reported" test "$(jq .stitch "$WORK/bowtie.json")" = 1
check "8 vertices instead of 7" test "$(vertex_count "$out")" = 8

case_ "report counts of the two-part mesh"
"$FEST_BIN/ebcode" --report "$WORK/r.json" "$WORK/two_parts.off" -o "$WORK/r.ebm"
check "2 components" test "$(jq .components "$WORK/r.json")" = 2
check "1 hole" test "$(jq .holes "$WORK/r.json")" = 1
check "1 isolated vertex" test "$(jq .isolated "$WORK/r.json")" = 1
run ebdecode --info "$WORK/r.ebm"
expect_json '.vertices' '8'
expect_json '.faces' '5'

case_ "vertex colours and normals travel with their vertices"
cat >"$WORK/colored.ply" <<'PLY'
ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
property float nx
property float ny
property float nz
property uchar red
property uchar green
property uchar blue
element face 4
property list uchar int vertex_indices
end_header
0 0 0 0 0 -1 10 20 30
1 0 0 1 0 0 40 50 60
0 1 0 0 1 0 70 80 90
0 0 1 0 0 1 100 110 120
3 0 2 1
3 0 1 3
3 0 3 2
3 1 2 3
PLY
run ebcode --qp 0 "$WORK/colored.ply" -o "$WORK/colored.ebm"
expect_status 0
run ebdecode --info "$WORK/colored.ebm"
expect_json '.attributes' '["normal","color"]'
run ebdecode --to plya "$WORK/colored.ebm"
expect_status 0
# Each vertex keeps its colour exactly and its normal within half a step (2/1023/2 at 10
# bits: 1 stays 1, 0 becomes 0.000977).
check "vertex (1,0,0) keeps colour 40 50 60 and normal (1,0,0)" grep -Eqx "1 0 0 1 0\.000977[0-9]* 0\.000977[0-9]* 40 50 60" "$out"
check "vertex (0,0,1) keeps colour 100 110 120 and normal (0,0,1)" grep -Eqx "0 0 1 0\.000977[0-9]* 0\.000977[0-9]* 1 100 110 120" "$out"

case_ "pipes: standard input to standard output"
"$FEST_BIN/ebcode" <"$WORK/tet.off" | "$FEST_BIN/ebdecode" --to off >"$WORK/pipe.off"
check "4 vertices" test "$(vertex_count "$WORK/pipe.off")" = 4

case_ "deterministic output"
"$FEST_BIN/ebcode" "$WORK/moebius.off" -o "$WORK/m1.ebm"
"$FEST_BIN/ebcode" "$WORK/moebius.off" -o "$WORK/m2.ebm"
check "byte-identical" cmp "$WORK/m1.ebm" "$WORK/m2.ebm"

case_ "ebcode model reproduces the chapter's tables"
run ebcode model --model m26
expect_status 0
check "26 states, 3.526762 bpv" grep -q "^# model m26: 26 states .* 3.526762 bpv" "$out"
run ebcode model --model m68 --to json
expect_json '.states' '68'
check "3.52540" test "$(jq '.bpv * 100000 | round' "$out")" = 352540
run ebcode model --model m236 --to json
expect_json '.states' '236'
check "below 3.525" test "$(jq '.bpv < 3.525' "$out")" = true
run ebcode model --lmax 9 --to json
expect_json '.states' '26'
run ebcode model --to inc
check "the committed tables are what the tool generates" diff "$out" "$(dirname "$0")/../../lib/edgebreaker/ebm_models.inc"

# --- container versions (ebm(5)): 2.0 written, 1.0 still read and writable ------------
case_ "a committed 1.0 stream and its 2.0 twin decode to the same mesh"
for name in eight_genus2 mushroom_hole bowtie_stitch tetrahedron_attributes; do
  "$FEST_BIN/ebdecode" --to plya "$FEST_FIXTURES/ebm/$name.ebm" -o "$WORK/$name.v1.ply"
  "$FEST_BIN/ebdecode" --to plya "$FEST_FIXTURES/ebm/${name}_v2.ebm" -o "$WORK/$name.v2.ply"
  check "$name: identical PLY" cmp "$WORK/$name.v1.ply" "$WORK/$name.v2.ply"
done
run ebdecode --info "$FEST_FIXTURES/ebm/eight_genus2_v2.ebm"
expect_json '.version' '"2.0"'
expect_json '.vertices' '315'
expect_json '.faces' '634'
expect_json '.events' '4'

case_ "--ebm-version 1 writes the old container, byte for byte the committed stream"
"$FEST_BIN/ebdecode" --to plya "$FEST_FIXTURES/ebm/eight_genus2.ebm" -o "$WORK/e.ply"
box=$("$FEST_BIN/ebdecode" --info "$FEST_FIXTURES/ebm/eight_genus2.ebm" | jq -r '.box | map(tostring) | join(",")')
run ebcode --ebm-version 1 --qp 6 --box "$box" "$WORK/e.ply" -o "$WORK/e1.ebm"
expect_status 0
check "same bytes as tests/data/ebm/eight_genus2.ebm" cmp "$WORK/e1.ebm" "$FEST_FIXTURES/ebm/eight_genus2.ebm"
run ebcode --ebm-version 3 "$WORK/tet.off"
expect_clean_failure 2 ebcode

case_ "GEOM version 3 (.ebm 2.1) decodes to the same mesh as GEOM version 2 (.ebm 2.0)"
"$FEST_BIN/ebdecode" --to plya "$FEST_FIXTURES/ebm/mushroom_hole_v2.ebm" -o "$WORK/mh.ply"
for gv in 2 3; do
  run ebcode --geom-version $gv --qp 11 "$WORK/mh.ply" -o "$WORK/mh$gv.ebm"
  expect_status 0
  "$FEST_BIN/ebdecode" --to plya "$WORK/mh$gv.ebm" -o "$WORK/mh$gv.ply"
done
check "identical PLY" cmp "$WORK/mh2.ply" "$WORK/mh3.ply"
run ebcode --geom-version 3 --qp 11 --report "$WORK/mh3.json" "$WORK/mh.ply" -o "$WORK/mh3b.ebm"
check "report names GEOM version 3" test "$(jq .geom_version "$WORK/mh3.json")" = 3
run ebdecode --info "$WORK/mh3.ebm"
expect_json '.version' '"2.1"'
run ebdecode --info "$WORK/mh2.ebm"
expect_json '.version' '"2.0"'
run ebcode --geom-version 3 --qp 0 "$WORK/tet.off"
expect_clean_failure 2 ebcode

# Golden: the SHA-256 of the PLY that ebdecode wrote for these 2.0 streams before GEOM
# version 3 existed (main at df93ec1); the 2.0 decoder must not change.
case_ "committed 2.0 streams decode to the same PLY as before 2.1"
for pair in eight_genus2_v2:8b78edb57fef64ffedc36f5620138bf0a5f5ae9e178fc1ef12dcd1cf14b9a914 mushroom_hole_v2:c06e49b53b88513bf5e415fa392bed81d443e1207634555de87d2afe06f573e4 eight_multi_v2:8b78edb57fef64ffedc36f5620138bf0a5f5ae9e178fc1ef12dcd1cf14b9a914; do
  "$FEST_BIN/ebdecode" --to plya "$FEST_FIXTURES/ebm/${pair%%:*}.ebm" -o "$WORK/old.ply"
  check "${pair%%:*}" test "$(sha256sum <"$WORK/old.ply" | cut -c1-64)" = "${pair##*:}"
done

# --- bad input ------------------------------------------------------------------------
"$FEST_BIN/ebcode" "$WORK/moebius.off" -o "$WORK/good.ebm"
size=$(wc -c <"$WORK/good.ebm")

case_ "truncated .ebm at every 97th byte"
for ((n = 0; n < size; n += 97)); do
  head -c "$n" "$WORK/good.ebm" >"$WORK/cut.ebm"
  run ebdecode "$WORK/cut.ebm"
  expect_clean_failure 3 ebdecode
done

case_ "one flipped payload bit"
cp "$WORK/good.ebm" "$WORK/flip.ebm"
printf '\x55' | dd of="$WORK/flip.ebm" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
run ebdecode "$WORK/flip.ebm"
expect_clean_failure 3 ebdecode
expect_stderr_has "CRC mismatch"

case_ "major version 3"
cp "$WORK/good.ebm" "$WORK/v3.ebm"
printf '\x03' | dd of="$WORK/v3.ebm" bs=1 seek=8 conv=notrunc 2>/dev/null
run ebdecode "$WORK/v3.ebm"
expect_clean_failure 3 ebdecode
expect_stderr_has "major version 3"

case_ "binary garbage to ebdecode"
head -c 300 /dev/urandom | tr '\211' 'x' >"$WORK/garbage"
run ebdecode "$WORK/garbage"
expect_clean_failure 3 ebdecode

case_ "empty standard input"
run_stdin /dev/null ebcode
expect_clean_failure 3 ebcode
run_stdin /dev/null ebdecode
expect_clean_failure 3 ebdecode

case_ "face index out of range"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >"$WORK/bad_index.off"
run ebcode "$WORK/bad_index.off"
expect_clean_failure 3 ebcode

case_ "NaN vertex coordinate"
printf 'OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$WORK/nan.off"
run ebcode "$WORK/nan.off"
expect_clean_failure 3 ebcode
expect_stderr_has "not finite"

case_ "OFF with wrong counts"
printf 'OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' >"$WORK/bad_counts.off"
run ebcode "$WORK/bad_counts.off"
expect_clean_failure 3 ebcode

case_ "binary garbage to ebcode"
run ebcode "$WORK/garbage"
expect_clean_failure 3 ebcode

case_ "--strict rejects a boundary"
run ebcode --strict "$WORK/fin.off"
expect_clean_failure 3 ebcode

case_ "usage errors"
run ebcode --qp 40 "$WORK/tet.off"
expect_clean_failure 2 ebcode
run ebcode --model m7 "$WORK/tet.off"
expect_clean_failure 2 ebcode
run ebcode --conn fast "$WORK/tet.off"
expect_clean_failure 2 ebcode

case_ "unwritable output"
run ebcode "$WORK/tet.off" -o /nonexistent/x.ebm
expect_clean_failure 4 ebcode

finish
