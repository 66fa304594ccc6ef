#!/usr/bin/env bash
# Test tooling: turns DOLFIN's Stokes-flow demo data (dolfin-doc, fetched by
# scripts/fetch-test-data.sh into cfd/) into a legacy VTK unstructured grid for lemtrace.
#
#   tests/tools/dolfin_to_vtk.sh MESH.xml.gz VELOCITY.xml.gz [THICKNESS] > grid.vtk
#
# The mesh is 2-D (triangles); the velocity a P2 vector field whose dofs name their cell
# and local index: 12 per cell, component-major, vertex dofs 0-2 (x) and 6-8 (y). The
# vertex values are the P2 field at the vertices (exact there). lemtrace works in 3-D, so
# the triangles are extruded into one layer of wedges of THICKNESS (default 0.05) with
# the same (u, v, 0) at both layers: a path started inside the slab stays in its plane.
set -euo pipefail
mesh=$1 velocity=$2 thickness=${3:-0.05}
{ gzip -dc "$mesh"; echo "@@VELOCITY@@"; gzip -dc "$velocity"; } | awk -v dz="$thickness" '
function attr(name,    m) {
  if (match($0, " " name "=\"[^\"]*\"")) return substr($0, RSTART + length(name) + 3, RLENGTH - length(name) - 4)
  return ""
}
/@@VELOCITY@@/ { in_velocity = 1; next }
!in_velocity && /<vertex / { i = attr("index"); x[i] = attr("x"); y[i] = attr("y"); if (i + 1 > nv) nv = i + 1 }
!in_velocity && /<triangle / { c = attr("index"); a[c] = attr("v0"); b[c] = attr("v1"); d[c] = attr("v2"); if (c + 1 > nc) nc = c + 1 }
in_velocity && /<dof / {
  c = attr("cell_index"); k = attr("cell_dof_index") + 0; v = attr("value")
  if (k <= 2) { vert = (k == 0 ? a[c] : k == 1 ? b[c] : d[c]); u[vert] = v; seen_u[vert] = 1 }
  else if (k >= 6 && k <= 8) { vert = (k == 6 ? a[c] : k == 7 ? b[c] : d[c]); w[vert] = v; seen_w[vert] = 1 }
}
END {
  if (nv == 0 || nc == 0) { print "dolfin_to_vtk: no vertices or cells in the mesh" > "/dev/stderr"; exit 3 }
  for (i = 0; i < nv; i++)
    if (!seen_u[i] || !seen_w[i]) { print "dolfin_to_vtk: vertex " i " has no velocity dof" > "/dev/stderr"; exit 3 }
  print "# vtk DataFile Version 3.0"
  print "DOLFIN Stokes velocity (dolfin-doc advection-diffusion demo), extruded"
  print "ASCII"
  print "DATASET UNSTRUCTURED_GRID"
  print "POINTS " 2 * nv " double"
  for (layer = 0; layer < 2; layer++) for (i = 0; i < nv; i++) print x[i], y[i], layer * dz
  print "CELLS " nc " " 7 * nc
  for (c = 0; c < nc; c++) print 6, a[c], b[c], d[c], a[c] + nv, b[c] + nv, d[c] + nv
  print "CELL_TYPES " nc
  for (c = 0; c < nc; c++) print 13
  print "POINT_DATA " 2 * nv
  print "VECTORS velocity double"
  for (layer = 0; layer < 2; layer++) for (i = 0; i < nv; i++) print u[i], w[i], 0
}'
