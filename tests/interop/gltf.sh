#!/usr/bin/env bash
# brdffit's glTF 2.0 (.gltf with PNG textures beside it, and .glb) checked by the Khronos
# glTF validator, the format's reference checker (npm gltf-validator, fetched by
# scripts/fetch-test-data.sh into the test data folder).
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"
here=$(cd "$(dirname "$0")" && pwd)

modules="$FEST_TESTDATA/npm/node_modules"
reader node nodejs || finish_interop
if [ ! -f "$modules/gltf-validator/package.json" ]; then
  echo "interop: skip: gltf-validator not fetched (scripts/fetch-test-data.sh installs it from npm)"
  exit 77
fi
validate() { NODE_PATH="$modules" node "$here/gltf_validate.cjs" "$1" >"$out" 2>"$err"; rc=$?; }

"$FEST_BIN/brdffit" synth --sphere 2 --materials 2 --views 4 --width 80 --height 60 --seed 3 -o "$WORK/syn" >/dev/null 2>&1
mkdir -p "$WORK/out"
for f in obj.gltf obj.glb; do
  "$FEST_BIN/brdffit" export --mesh "$WORK/syn/mesh.ply" --materials "$WORK/syn/truth.json" \
    --gltf "$WORK/out/$f" --texture-size 64 >/dev/null 2>"$err"
  case_ "the glTF validator accepts brdffit's $f"
  validate "$WORK/out/$f"
  expect_status 0
  check "no errors" test "$(jq .errors "$out")" = 0
  check "triangles" test "$(jq .triangles "$out")" -gt 0
done

finish_interop
