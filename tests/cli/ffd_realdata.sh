#!/usr/bin/env bash
# ffd on the CGAL man.off body (Debian libcgal-demo): an affine lattice (2x2x2 points
# A P0 + b around the body) maps every vertex to A X + b (computed here with awk, compared
# by fcompare), and a zero 4x4x6 lattice leaves the file bit-identical.
. "$(dirname "$0")/lib.sh"
man=$(need_testdata meshes/man.off) || exit 77

case_ "zero lattice: identity on 17,495 vertices"
run ffd init "$man" --dims 4,4,6 -o "$WORK/lat.json"
expect_status 0
run ffd apply --lattice "$WORK/lat.json" "$man" -o "$WORK/man_id.off"
expect_status 0
run fcompare "$WORK/man_id.off" "$man" --tol 0
expect_status 0

case_ "affine lattice on the real body: X -> A X + b within 1e-9 of the size"
jq -c '{origin, axes, dims:[2,2,2]}' "$WORK/lat.json" >"$WORK/box.json"
read -r ox oy oz <<<"$(jq -r '.origin | map(tostring) | join(" ")' "$WORK/box.json")"
read -r sx sy sz <<<"$(jq -r '[.axes[0][0], .axes[1][1], .axes[2][2]] | map(tostring) | join(" ")' "$WORK/box.json")"
awk -v ox="$ox" -v oy="$oy" -v oz="$oz" -v sx="$sx" -v sy="$sy" -v sz="$sz" 'BEGIN {
  printf "{\"origin\":[%.17g,%.17g,%.17g],\"axes\":[[%.17g,0,0],[0,%.17g,0],[0,0,%.17g]],\"dims\":[2,2,2],\"points\":[", ox, oy, oz, sx, sy, sz
  n = 0
  for (k = 0; k < 2; k++) for (j = 0; j < 2; j++) for (i = 0; i < 2; i++) {
    x = ox + i * sx; y = oy + j * sy; z = oz + k * sz
    printf "%s[%.17g,%.17g,%.17g]", (n++ ? "," : ""), x + 0.3*y, 0.9*y - 0.2*z + 0.1, 0.1*x + 1.1*z }
  print "]}" }' >"$WORK/affine.json"
run ffd apply --lattice "$WORK/affine.json" "$man" -o "$WORK/man_affine.off"
expect_status 0
awk 'NR == 2 { nv = $1; print; next } NR <= 2 || NF == 0 { print; next } nv-- > 0 { printf "%.17g %.17g %.17g\n", $1 + 0.3*$2, 0.9*$2 - 0.2*$3 + 0.1, 0.1*$1 + 1.1*$3; next } { print }' \
  "$man" >"$WORK/expected.off"
run fcompare "$WORK/man_affine.off" "$WORK/expected.off" --tol 1e-9
expect_status 0

finish
