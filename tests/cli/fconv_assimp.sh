#!/usr/bin/env bash
# fconv and fcompare on assimp's OBJ/PLY test models (Debian assimp-testmodels, fetched
# by scripts/fetch-test-data.sh): every face, line and point element is carried. The
# expected counts come from assimp itself (`assimp info FILE -r`, no post-processing),
# which counts faces, line segments and points together as primitives.
. "$(dirname "$0")/lib.sh"
dir=$(dirname "$(need_testdata meshes/assimp/WusonOBJ.obj)") || exit 77
if ! command -v assimp >/dev/null; then
  echo "skipped: assimp (package assimp-utils) is not installed; it gives the expected counts" >&2
  exit 77
fi
# assimp's raw primitive count: faces + line segments + points.
assimp_primitives() { assimp info "$1" -r 2>/dev/null | awk '/^Faces:/{print $2}'; }
fest_primitives() { "$FEST_BIN/fconv" --info "$1" | jq '.faces + (.line_segments // 0) + (.points // 0)'; }

for name in WusonOBJ spider box_longline regr_3429812 space_in_material_name concave_polygon testline testpoints \
            testmixed; do
  f="$dir/$name.obj"
  expected=$(assimp_primitives "$f")
  case_ "$name.obj: fest reads the $expected primitives assimp reads, silently"
  run fconv --info "$f"
  expect_status 0
  check "no warning" test ! -s "$err"
  check "fest $(fest_primitives "$f") = assimp $expected" test "$(fest_primitives "$f")" = "$expected"

  case_ "$name.obj -> OBJ -> PLY: every element survives, and fcompare sees the same file"
  # spider.obj has per-corner normals and texture coordinates (fest keeps one per
  # vertex; the case below checks that fconv refuses them): drop those here.
  "$FEST_BIN/fconv" --drop-unrepresentable "$f" -o "$WORK/$name.obj" 2>/dev/null
  check "OBJ round trip keeps $expected primitives" test "$(fest_primitives "$WORK/$name.obj")" = "$expected"
  check "assimp reads fest's OBJ: $expected primitives" test "$(assimp_primitives "$WORK/$name.obj")" = "$expected"
  run fcompare --samples 2000 "$f" "$WORK/$name.obj"
  expect_status 0
  # PLY holds faces and lines (edges), not points.
  points=$("$FEST_BIN/fconv" --info "$f" | jq '.points // 0')
  if [ "$points" -eq 0 ]; then
    run fconv "$WORK/$name.obj" -o "$WORK/$name.ply"
    expect_status 0
    check "PLY keeps $expected primitives" test "$(fest_primitives "$WORK/$name.ply")" = "$expected"
    run fcompare --samples 2000 "$f" "$WORK/$name.ply" --tol 1e-6
    expect_status 0
  else
    run fconv "$WORK/$name.obj" -o "$WORK/$name.ply"
    expect_clean_failure 3 fconv
    expect_stderr_has "ply cannot hold the input's [0-9]+ point elements \\($points points\\)"
    check "nothing written" test ! -e "$WORK/$name.ply"
  fi
done

case_ "WusonOBJ.obj: 3732 triangles (assimp, VTK and ebcode agree), all in fconv's PLY"
run fconv --info "$dir/WusonOBJ.obj"
expect_json '.faces' '3732'
"$FEST_BIN/fconv" --ascii "$dir/WusonOBJ.obj" -o "$WORK/wuson.ply"
check "ascii PLY declares 3732 faces" grep -qx "element face 3732" "$WORK/wuson.ply"
check "assimp reads 3732 faces from fest's PLY" test "$(assimp_primitives "$WORK/wuson.ply")" = 3732

case_ "spider.obj: corners whose normal or texture coordinates differ from their vertex's are named"
# Counted here independently of fest: corners whose vn/vt text differs from the text
# at the first corner of the same vertex.
counts=$(awk '$1=="vt"{t[++nt]=$2" "$3} $1=="vn"{n[++nn]=$2" "$3" "$4}
  $1=="f"{for(i=2;i<=NF;i++){split($i,c,"/"); v=c[1]
    if(c[2]!=""){if(v in ft){if(ft[v]!=t[c[2]])dt++}else ft[v]=t[c[2]]}
    if(c[3]!=""){if(v in fn){if(fn[v]!=n[c[3]])dn++}else fn[v]=n[c[3]]}}}
  END{print dn+0, dt+0}' "$dir/spider.obj")
read -r normals texcoords <<<"$counts"
run fconv "$dir/spider.obj" --to ply
expect_clean_failure 3 fconv
expect_stderr_has "does not keep the input's $normals face corners' normals that differ from their vertex's"
expect_stderr_has "$texcoords face corners' texture coordinates that differ"
run fconv "$dir/spider.obj" --to ply --drop-unrepresentable
expect_status 0
expect_stderr_has "^fconv: warning: dropped $normals face corners' normals"

case_ "concave_polygon.obj: one face of 66 corners (it visits two vertices twice)"
"$FEST_BIN/fconv" --ascii "$dir/concave_polygon.obj" -o "$WORK/concave.ply"
check "one face" grep -qx "element face 1" "$WORK/concave.ply"
check "of 66 corners" test "$(tail -n 1 "$WORK/concave.ply" | cut -d' ' -f1)" = 66

case_ "testline.obj: 6 polylines = 18 segments become 18 PLY edges; OFF refuses them by name"
"$FEST_BIN/fconv" --ascii "$dir/testline.obj" -o "$WORK/lines.ply"
check "element edge 18" grep -qx "element edge 18" "$WORK/lines.ply"
run fconv "$dir/testline.obj" --to off
expect_clean_failure 3 fconv
expect_stderr_has "off cannot hold the input's 6 line elements \\(18 segments\\); --drop-unrepresentable"
run fconv "$dir/testline.obj" --to off --drop-unrepresentable
expect_status 0
expect_stderr_has "^fconv: warning: dropped 6 line elements \\(18 segments\\), which off cannot hold"

case_ "fcompare sees a face a file lost (regr_3429812.obj without its last face)"
head -n -1 "$dir/regr_3429812.obj" >"$WORK/regr_lost.obj"
run fcompare "$dir/regr_3429812.obj" "$WORK/regr_lost.obj"
expect_status 1
check "face_count_diff 1" grep -qx "face_count_diff 1" "$out"

case_ "Wuson.ply: a header line without 'comment' (Blender 2.47) is read, with a warning"
run fconv --info "$dir/Wuson.ply"
expect_status 0
expect_json '.faces' "$(assimp_primitives "$dir/Wuson.ply")"
expect_stderr_has "^fconv: warning: PLY header line 3: \"Created by Blender3D 247"

case_ "PLY properties fest does not keep are refused by name, or dropped with a warning"
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty float confidence\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0 1\n1 0 0 1\n0 1 0 1\n3 0 1 2\n' >"$WORK/scan.ply"
run fconv "$WORK/scan.ply" --to off
expect_clean_failure 3 fconv
expect_stderr_has "does not keep the input's 3 vertices' confidence \\(PLY properties\\)"
run fconv "$WORK/scan.ply" --to off --drop-unrepresentable
expect_status 0
expect_stderr_has "^fconv: warning: dropped 3 vertices' confidence"

finish
