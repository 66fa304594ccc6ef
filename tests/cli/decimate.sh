#!/usr/bin/env bash
# decimate: answers from geometry, not from decimate's output. A cube whose faces are
# split into n x n squares is still the cube, so simplifying it to 12 faces must leave a
# surface at Hausdorff distance 0 (fcompare); a flat square with its boundary locked
# keeps exactly its 4n boundary vertices and needs 4n - 2 triangles (Euler); a golden
# file guards the output; bad input fails cleanly.
. "$(dirname "$0")/lib.sh"

# cube N FILE: the unit cube, each face n x n squares (two triangles each), as OFF.
cube() {
  awk -v n="$1" 'BEGIN {
    nv = 0; nf = 0
    for (ax = 0; ax < 3; ax++) for (s = 0; s <= 1; s++) for (i = 0; i < n; i++) for (j = 0; j < n; j++) {
      for (k = 0; k < 4; k++) {
        a = i + (k == 1 || k == 2); b = j + (k >= 2)
        c[ax] = s * n; c[(ax + 1) % 3] = a; c[(ax + 2) % 3] = b
        key = c[0] " " c[1] " " c[2]
        if (!(key in id)) { id[key] = nv; vx[nv++] = key }
        q[k] = id[key]
      }
      if (s == 1) { f[nf++] = q[0] " " q[1] " " q[2]; f[nf++] = q[0] " " q[2] " " q[3] }
      else        { f[nf++] = q[0] " " q[2] " " q[1]; f[nf++] = q[0] " " q[3] " " q[2] }
    }
    print "OFF"; print nv, nf, 0
    for (v = 0; v < nv; v++) { split(vx[v], p, " "); print p[1] / n, p[2] / n, p[3] / n }
    for (g = 0; g < nf; g++) print 3, f[g]
  }' >"$2"
}

# square N FILE: the unit square in z = 0 as an n x n grid of triangle pairs.
square() {
  awk -v n="$1" 'BEGIN {
    print "OFF"; print (n + 1) * (n + 1), 2 * n * n, 0
    for (j = 0; j <= n; j++) for (i = 0; i <= n; i++) print i / n, j / n, 0
    for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
      a = j * (n + 1) + i; b = a + 1; c = b + n + 1; d = a + n + 1
      print 3, a, b, c; print 3, a, c, d
    }
  }' >"$2"
}

cube 6 "$WORK/cube.off"
square 8 "$WORK/square.off"

case_ "a subdivided cube simplifies to the cube itself (Hausdorff 0 by fcompare)"
run decimate "$WORK/cube.off" --faces 12 -o "$WORK/cube12.off" --report "$WORK/r.json"
expect_status 0
check "at most 24 faces left" test "$(jq .faces "$WORK/r.json")" -le 24
run fcompare "$WORK/cube.off" "$WORK/cube12.off" --ignore-counts --tol 1e-9
expect_status 0

case_ "a locked boundary keeps its 32 vertices; 4n - 2 = 30 triangles remain"
run decimate "$WORK/square.off" --faces 2 --lock boundary --to off
expect_status 0
check "32 vertices, 30 faces" test "$(sed -n 2p "$out" | awk '{print $1, $2}')" = "32 30"
check "all vertices on the square's boundary" awk 'NR > 2 && NR <= 34 && !($1 == 0 || $1 == 1 || $2 == 0 || $2 == 1) { exit 1 }' "$out"

case_ "the error bound 0 keeps a surface that has no flat part"
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' >"$WORK/octa.off"
run decimate "$WORK/octa.off" --error 0 --to off
expect_status 0
check "8 faces kept" test "$(sed -n 2p "$out" | awk '{print $2}')" = "8"

case_ "golden: the 6 x 6 cube at 100 faces, unchanged within 1e-9 (fcompare)"
run decimate "$WORK/cube.off" --faces 100 -o "$WORK/cube100.off"
expect_status 0
run fcompare "$WORK/cube100.off" "$FEST_FIXTURES/decimate/cube6_100.off" --tol 1e-9
expect_status 0

case_ "polygons are split into triangles (6 quads -> 12 triangles), with a warning"
run decimate "$FEST_FIXTURES/mesh/cube_quads.off" --faces 12 --to off
expect_status 0
expect_stderr_has "6 polygons were split"
check "12 triangles" test "$(sed -n 2p "$out" | awk '{print $2}')" = 12

case_ "bad input: empty file"
: >"$WORK/empty.off"
run decimate "$WORK/empty.off" --faces 10
expect_clean_failure 3 decimate

case_ "bad input: truncated OFF"
head -c 60 "$WORK/cube.off" >"$WORK/trunc.off"
run decimate "$WORK/trunc.off" --faces 10
expect_clean_failure 3 decimate

case_ "bad input: non-finite coordinate"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n' >"$WORK/nan.off"
run decimate "$WORK/nan.off" --faces 1
expect_clean_failure 3 decimate

case_ "bad input: no faces"
printf 'OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n' >"$WORK/nofaces.off"
run decimate "$WORK/nofaces.off" --faces 1
expect_clean_failure 3 decimate

case_ "usage: no stopping rule, ratio out of range, unknown lock"
run decimate "$WORK/cube.off"
expect_clean_failure 2 decimate
run decimate "$WORK/cube.off" --ratio 2
expect_clean_failure 2 decimate
run decimate "$WORK/cube.off" --faces 10 --lock everything
expect_clean_failure 2 decimate

case_ "no output file is left behind on bad input"
run decimate "$WORK/trunc.off" --faces 10 -o "$WORK/never.off"
check "nothing written" test ! -e "$WORK/never.off"

case_ "decimate --help, --version, unknown flag"
run decimate --help
expect_status 0
check "usage printed" grep -q "Usage" "$out"
run decimate --version
expect_status 0
check "version names fest" grep -q "(fest)" "$out"
run decimate --no-such-flag
expect_clean_failure 2 decimate

finish
