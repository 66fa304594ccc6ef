#!/usr/bin/env bash
# Scene formats read through the assimp plugin (libfest_assimp_plugin.so, opened only
# when such a file arrives): glTF/GLB, COLLADA, FBX, 3DS, DirectX .x. Counts come from
# mathematics (a hand-made glTF) or from assimp's own `assimp info` (assimp-utils), an
# independent program; the models are Debian's assimp-testmodels (fetched).
. "$(dirname "$0")/lib.sh"
if [ ! -e "$FEST_BIN/libfest_assimp_plugin.so" ]; then
  echo "skipped: libfest_assimp_plugin.so was not built (libassimp-dev missing at configure time)" >&2
  exit 77
fi

case_ "hand-made glTF: one unit square instanced by two nodes, flattened with the node transforms"
# Node 'plain' holds the square as is; node 'doubled' (scale 2) is the child of 'lifted'
# (translation z = 5), so glTF's parent * child gives (2x, 2y, 5): 2 x 4 vertices,
# 2 x 2 triangles, bounding box (0,0,0)-(2,2,5).
sq="$FEST_FIXTURES/mesh/square_two_instances.gltf"
run fconv --info "$sq"
expect_status 0
expect_json '.format' '"gltf"'
expect_json '.vertices' '8'
expect_json '.faces' '4'
expect_json '.bbox.min' '[0,0,0]'
expect_json '.bbox.max' '[2,2,5]'
run fconv "$sq" -o "$WORK/sq.off"
expect_status 0
check "OFF has 8 vertices and 4 faces" test "$(sed -n 2p "$WORK/sq.off")" = "8 4 0"
# Its area, 1 + 4 = 5, is the two squares' (fcompare against an OFF written by hand).
printf 'OFF\n8 4 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 5\n2 0 5\n2 2 5\n0 2 5\n3 0 1 2\n3 0 2 3\n3 4 5 6\n3 4 6 7\n' \
  >"$WORK/sq_expected.off"
run fcompare --samples 2000 "$sq" "$WORK/sq_expected.off"
expect_status 0
check "hausdorff 0" grep -qx "hausdorff 0" "$out"

# A glTF whose geometry is in a separate quad.bin (and whose texture is a separate
# quad_texture.png, not shipped: images are material data, never opened). The buffer
# holds the quad (0,0,0) (3,0,0) (3,2,0) (0,2,0) as triangles 0 1 2, 0 2 3; its node moves
# it by (10, 20, 30): 4 vertices, 2 triangles, bbox (10,20,30)-(13,22,30).
ext="$FEST_FIXTURES/mesh/external_buffer"
case_ "glTF with an external .bin, given by path from another folder: read beside the .gltf"
mkdir -p "$WORK/elsewhere" "$WORK/copy of scene"
(cd "$WORK/elsewhere" && "$FEST_BIN/fconv" --info "$ext/quad.gltf") >"$out" 2>"$err"
rc=$?
expect_status 0
expect_json '.vertices' '4'
expect_json '.faces' '2'
expect_json '.bbox.min' '[10,20,30]'
expect_json '.bbox.max' '[13,22,30]'
expect_stderr_has "not read: 1 materials"
cp "$ext/quad.gltf" "$ext/quad.bin" "$WORK/copy of scene/"
(cd "$WORK" && "$FEST_BIN/fconv" "copy of scene/quad.gltf" -o quad.ply) >"$out" 2>"$err"
rc=$?
expect_status 0
check "a relative path in a folder with a space: PLY of 4 vertices" \
  grep -q "^element vertex 4" "$WORK/quad.ply"
# glTF URIs are percent-encoded: "quad%20buffer.bin" names the file "quad buffer.bin".
cp "$ext/quad.bin" "$WORK/copy of scene/quad buffer.bin"
sed 's/"quad.bin"/"quad%20buffer.bin"/' "$ext/quad.gltf" >"$WORK/copy of scene/encoded.gltf"
run fconv --info "$WORK/copy of scene/encoded.gltf"
expect_status 0
expect_json '.vertices' '4'

case_ "glTF with an external .bin on standard input: exit 3 naming the buffer, nothing written"
# Run where quad.bin lies: the working directory must not stand in for the scene's folder.
(cd "$ext" && "$FEST_BIN/fconv" - -o "$WORK/stdin_quad.ply" <quad.gltf) >"$out" 2>"$err"
rc=$?
expect_clean_failure 3 fconv
expect_stderr_has '"quad.bin"'
expect_stderr_has "standard input"
check "nothing written" test ! -e "$WORK/stdin_quad.ply"

case_ "glTF whose external .bin is missing beside it: exit 4 naming the file"
mkdir -p "$WORK/lonely"
cp "$ext/quad.gltf" "$WORK/lonely/"
run fconv "$WORK/lonely/quad.gltf" -o "$WORK/lonely.ply"
expect_clean_failure 4 fconv
expect_stderr_has "lonely/quad.bin"
check "nothing written" test ! -e "$WORK/lonely.ply"

case_ "--version and a PLY conversion do not load libassimp; a glTF does"
LD_DEBUG=files "$FEST_BIN/fconv" --version >/dev/null 2>"$WORK/ld1"
check "no libassimp for --version" bash -c "! grep -q 'libassimp' '$WORK/ld1'"
"$FEST_BIN/fconv" "$WORK/sq.off" -o "$WORK/sq.ply"
LD_DEBUG=files "$FEST_BIN/fconv" "$WORK/sq.ply" -o "$WORK/sq2.off" 2>"$WORK/ld2"
check "no libassimp for PLY -> OFF" bash -c "! grep -q 'libassimp' '$WORK/ld2'"
LD_DEBUG=files "$FEST_BIN/fconv" "$sq" -o "$WORK/sq3.off" 2>"$WORK/ld3"
check "libassimp for a glTF" grep -q 'libassimp' "$WORK/ld3"

case_ "no plugin in FEST_PLUGIN_DIR: exit 4, one line naming libassimp5, nothing written"
mkdir -p "$WORK/empty"
FEST_PLUGIN_DIR="$WORK/empty" "$FEST_BIN/fconv" "$sq" -o "$WORK/never.ply" >"$out" 2>"$err"
rc=$?
expect_clean_failure 4 fconv
expect_stderr_has "install the Debian package libassimp5"
check "one line" test "$(wc -l <"$err")" = 1
check "nothing written" test ! -e "$WORK/never.ply"

case_ "scene formats are read, not written: a usage error"
run fconv "$WORK/sq.off" -o "$WORK/sq.gltf"
expect_status 2
expect_stderr_has "reads gltf .* but does not write it"
run fconv "$WORK/sq.off" --to fbx
expect_status 2

case_ "a broken glTF: exit 3 with assimp's reason, nothing written"
printf '{"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":7}}]}]}' >"$WORK/bad.gltf"
run fconv "$WORK/bad.gltf" -o "$WORK/bad.ply"
expect_clean_failure 3 fconv
expect_stderr_has "gltf \\(through assimp\\)"
check "nothing written" test ! -e "$WORK/bad.ply"

# Debian's assimp test models, counted by assimp itself (default post-processing, which
# triangulates): fest's triangles must be assimp's faces. Each mesh of these models is
# used by one node, so flattening does not multiply them.
dir=$(dirname "$(need_testdata meshes/assimp/test1.3ds 2>/dev/null)" 2>/dev/null)
if [ -n "$dir" ] && [ -e "$dir/test1.3ds" ] && command -v assimp >/dev/null; then
  # (test1.3ds is counted below: its meshes are instanced by several nodes.)
  for name in duck.dae box.fbx test.x BoxTextured.glb BoxTextured.gltf; do
    f="$dir/$name"
    [ -e "$f" ] || continue
    expected=$(assimp info "$f" 2>/dev/null | awk '/^Faces:/{print $2}')
    case_ "$name: the $expected triangles assimp reads"
    run fconv --info "$f"
    expect_status 0
    check "fest $(jq .faces "$out") = assimp $expected" test "$(jq .faces "$out")" = "$expected"
    run fconv --drop-unrepresentable "$f" -o "$WORK/$name.ply"
    expect_status 0
    run fcompare --samples 2000 "$f" "$WORK/$name.ply" --tol 1e-6
    expect_status 0
  done

  # test1.3ds: 5 meshes used by 9 nodes (mesh 2 three times, meshes 0 and 1 twice). A
  # mesh converter writes what the scene shows, every instance as geometry of its own
  # (docs/fconv.md), so fest's triangles are sum over nodes of the faces of the node's
  # mesh -- computed here from `assimp info`'s own mesh table and node hierarchy -- and
  # not the 60 faces assimp info sums over meshes. The placement is checked against
  # assimp's OBJ exporter, which flattens instances with its own code.
  f="$dir/test1.3ds"
  if [ -e "$f" ]; then
    assimp info "$f" -v >"$WORK/t3ds.info" 2>/dev/null
    expected=$(awk '
      /^Meshes:  \(name\)/ { table = 1; next }
      table && /^    [0-9]+ \(/ { split($0, a, /\[|\//); faces[$1] = a[4] + 0; next }
      table && /^$/ { table = 0 }
      /\(meshes / { bad = 1 }
      /\(mesh [0-9]+\)/ { match($0, /\(mesh [0-9]+\)/); m = substr($0, RSTART + 6, RLENGTH - 7); used[m]++ }
      END { if (bad) { print "multi"; exit } for (m in used) { sum += used[m] * faces[m]; n += used[m] } print sum, n }' \
      "$WORK/t3ds.info")
    case_ "test1.3ds: every node instance is geometry (${expected% *} triangles in ${expected#* } instances, from assimp info)"
    check "assimp info's node graph parsed (9 instances)" test "${expected#* }" = 9
    run fconv --info "$f"
    expect_status 0
    check "fest $(jq .faces "$out") triangles = ${expected% *}" test "$(jq .faces "$out")" = "${expected% *}"
    (cd "$WORK" && assimp export "$f" t3ds.obj >/dev/null 2>&1)
    check "assimp's OBJ export has ${expected% *} faces" test "$(grep -c '^f ' "$WORK/t3ds.obj")" = "${expected% *}"
    obj_box=$(awk '/^v /{ for (i = 2; i <= 4; i++) { if (!(i in lo) || $i < lo[i]) lo[i] = $i; if (!(i in hi) || $i > hi[i]) hi[i] = $i } }
      END { printf "%s %s %s %s %s %s", lo[2], lo[3], lo[4], hi[2], hi[3], hi[4] }' "$WORK/t3ds.obj")
    fest_box=$(jq -r '[.bbox.min[], .bbox.max[]] | map(tostring) | join(" ")' "$out")
    check "bbox ($fest_box) = assimp's OBJ export's ($obj_box) to 1e-6" \
      awk -v a="$fest_box" -v b="$obj_box" 'BEGIN { split(a, x, " "); split(b, y, " ");
        for (i = 1; i <= 6; i++) { d = x[i] - y[i]; if (d < -1e-6 || d > 1e-6) exit 1 } }'
    run fcompare --samples 4000 "$f" "$WORK/t3ds.obj"
    check "hausdorff to assimp's OBJ export below 1e-6" \
      awk '$1 == "hausdorff" { found = 1; if ($2 > 1e-6) exit 1 } END { exit !found }' "$out"
  fi

  case_ "duck.dae: its material is named in a warning, not silently dropped"
  run fconv "$dir/duck.dae" -o "$WORK/duck.ply"
  expect_status 0
  expect_stderr_has "not read: 1 materials"
fi

finish
