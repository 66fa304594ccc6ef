#!/usr/bin/env bash
# Meshes fest writes (PLY binary and ASCII, OBJ, OFF, STL, Draco), read by assimp, Draco's
# own tools and VTK. The expected counts and boxes come from the source files themselves
# (their headers and coordinates, read with awk), not from fest.
. "$(dirname "$0")/../cli/lib.sh"
. "$(dirname "$0")/interop_lib.sh"
here=$(cd "$(dirname "$0")" && pwd)

# off_facts FILE: "TRIANGLES XMIN YMIN ZMIN XMAX YMAX ZMAX" of an OFF file (polygons
# counted as n-2 triangles, the fan every reader makes of them).
off_facts() {
  awk '/^#/ || NF == 0 { next }
       !h { if ($1 == "OFF") { if (NF >= 4) { nv = $2; nf = $3; h = 2 } else h = 1; next }
            if (h == 0) next }
       h == 1 { nv = $1; nf = $2; h = 2; next }
       h == 2 && v < nv { for (i = 1; i <= 3; i++) { x = $i + 0
                            if (v == 0 || x < lo[i]) lo[i] = x; if (v == 0 || x > hi[i]) hi[i] = x }
                          v++; next }
       h == 2 && f < nf { t += $1 - 2; f++ }
       END { printf "%d %.6f %.6f %.6f %.6f %.6f %.6f\n", t, lo[1], lo[2], lo[3], hi[1], hi[2], hi[3] }' "$1"
}

sources=("$FEST_FIXTURES/mesh/cube_quads.off")
bunny="$FEST_TESTDATA/meshes/bunny00.off"
[ -f "$bunny" ] && sources+=("$bunny") || echo "interop: bunny00.off not fetched: the real-mesh case is skipped"

have_assimp=0; reader assimp assimp-utils && have_assimp=1
have_draco=0; reader draco_encoder draco && have_draco=1
have_vtk=0; py_has vtk python3-vtk9 && have_vtk=1

for src in "${sources[@]}"; do
  name=$(basename "$src" .off)
  read -r tris x0 y0 z0 x1 y1 z1 <<<"$(off_facts "$src")"
  for fmt in ply ascii.ply obj off stl; do
    f="$WORK/$name.$fmt"
    case $fmt in ascii.ply) "$FEST_BIN/fconv" --ascii "$src" -o "$f" ;; *) "$FEST_BIN/fconv" "$src" -o "$f" ;; esac
    case_ "$name.$fmt written by fconv"
    check "fconv wrote it" test -s "$f"
    if [ $have_assimp = 1 ]; then
      case_ "assimp reads $name.$fmt"
      assimp info "$f" >"$out" 2>"$err"; rc=$?
      expect_status 0
      check "$tris triangles" grep -Eq "^Faces: +$tris\$" "$out"
      check "bounding box" awk -v a="$x0 $y0 $z0" -v b="$x1 $y1 $z1" '
        function near(s, t,   p, q, i, n) { n = split(s, p, " "); split(t, q, " ")
          for (i = 1; i <= n; i++) if ((p[i] - q[i]) > 1e-5 || (q[i] - p[i]) > 1e-5) return 0; return 1 }
        /^Minimum point/ { gsub(/[()]/, ""); lo = $3 " " $4 " " $5 }
        /^Maximum point/ { gsub(/[()]/, ""); hi = $3 " " $4 " " $5 }
        END { exit !(near(lo, a) && near(hi, b)) }' "$out"
    fi
    if [ $have_vtk = 1 ] && [ $fmt != off ]; then
      case_ "VTK reads $name.$fmt"
      "$PY" "$here/vtk_read.py" "$f" >"$out" 2>"$err"; rc=$?
      expect_status 0
      check "bounds" "$PY" -c "import json,sys; b=json.load(open('$out'))['bounds']; e=[$x0,$x1,$y0,$y1,$z0,$z1]; sys.exit(max(abs(p-q) for p,q in zip(b,e)) > 1e-5)"
    fi
  done
  if [ $have_draco = 1 ]; then
    for fmt in ply ascii.ply obj; do
      case_ "draco_encoder reads fconv's $name.$fmt"
      draco_encoder -i "$WORK/$name.$fmt" -o "$WORK/$name.$fmt.drc" >"$out" 2>"$err"; rc=$?
      expect_status 0
      check "encoded" test -s "$WORK/$name.$fmt.drc"
    done
    case_ "draco_decoder reads fconv's $name.drc"
    "$FEST_BIN/fconv" "$src" -o "$WORK/$name.drc"
    draco_decoder -i "$WORK/$name.drc" -o "$WORK/$name.drc.ply" >"$out" 2>"$err"; rc=$?
    expect_status 0
    check "$tris triangles" grep -qx "element face $tris" "$WORK/$name.drc.ply"
  fi
done

finish_interop
