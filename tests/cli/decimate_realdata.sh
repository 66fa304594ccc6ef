#!/usr/bin/env bash
# decimate on the CGAL man.off body (Debian libcgal-demo): a closed 2-manifold stays a
# closed 2-manifold of the same genus at 10 % of its faces, and fcompare's Hausdorff
# distance stays below 1 % of the bounding-box diagonal.
. "$(dirname "$0")/lib.sh"
man=$(need_testdata meshes/man.off) || exit 77

case_ "man.off to 10 %: topology kept (fcompare), error small"
run decimate "$man" --ratio 0.1 -o "$WORK/man10.off" --report "$WORK/r.json"
expect_status 0
run fcompare "$man" "$WORK/man10.off" --ignore-counts --tol 1e9 --report "$WORK/fc.json"
expect_status 0
diag=$(awk 'NR == 2 { n = $1; next } NF == 0 { next } NR > 2 && n-- > 0 { for (i = 1; i <= 3; i++) { if (!(i in lo) || $i < lo[i]) lo[i] = $i; if (!(i in hi) || $i > hi[i]) hi[i] = $i } }
            END { print sqrt((hi[1]-lo[1])^2 + (hi[2]-lo[2])^2 + (hi[3]-lo[3])^2) }' "$man")
check "hausdorff < 1 % of the diagonal" awk -v h="$(jq .hausdorff "$WORK/r.json")" -v d="$diag" 'BEGIN { exit !(h < 0.01 * d) }'
check "faces at the target" test "$(jq .faces "$WORK/r.json")" -le "$(jq .target_faces "$WORK/r.json")"

finish
