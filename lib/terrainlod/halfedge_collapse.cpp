#include "terrainlod/halfedge_collapse.hpp"

namespace fest::terrainlod {
namespace {

using HalfedgeHandle = TriMesh::HalfedgeHandle;
using VertexHandle = TriMesh::VertexHandle;
using FaceHandle = TriMesh::FaceHandle;

// A vertex on the boundary keeps a boundary half-edge as its outgoing one (the first met
// circulating from its current one), so that boundary tests need look at one half-edge.
void keep_boundary_outgoing(TriMesh& m, VertexHandle v) {
  for (auto h : m.voh_range(v))
    if (m.is_boundary(h)) {
      m.set_halfedge_handle(v, h);
      return;
    }
}

void mark_deleted(TriMesh& m, HalfedgeHandle h0, HalfedgeHandle o0) {
  m.status(m.edge_handle(h0)).set_deleted(true);
  if (m.has_halfedge_status()) {
    m.status(h0).set_deleted(true);
    m.status(o0).set_deleted(true);
  }
}

// Removes edge h = (vo -> vh): every half-edge into vo now ends in vh; the two face loops
// skip h and its opposite; the faces and vh keep valid half-edges; vo is left isolated.
void remove_edge_keep_to_vertex(TriMesh& m, HalfedgeHandle h) {
  const HalfedgeHandle hn = m.next_halfedge_handle(h), hp = m.prev_halfedge_handle(h);
  const HalfedgeHandle o = m.opposite_halfedge_handle(h);
  const HalfedgeHandle on = m.next_halfedge_handle(o), op = m.prev_halfedge_handle(o);
  const FaceHandle fh = m.face_handle(h), fo = m.face_handle(o);
  const VertexHandle vh = m.to_vertex_handle(h), vo = m.to_vertex_handle(o);
  for (auto hin : m.vih_range(vo)) m.set_vertex_handle(hin, vh);
  m.set_next_halfedge_handle(hp, hn);
  m.set_next_halfedge_handle(op, on);
  if (fh.is_valid()) m.set_halfedge_handle(fh, hn);
  if (fo.is_valid()) m.set_halfedge_handle(fo, on);
  if (m.halfedge_handle(vh) == o) m.set_halfedge_handle(vh, hn);
  keep_boundary_outgoing(m, vh);
  m.set_isolated(vo);
  m.status(vo).set_deleted(true);
  mark_deleted(m, h, o);
}

// Removes a face of two half-edges (h0, h1 = next(h0)) left by the edge removal: h0's
// edge goes, h1 takes the place of h0's opposite in the face across.
void remove_two_gon(TriMesh& m, HalfedgeHandle h0) {
  const HalfedgeHandle h1 = m.next_halfedge_handle(h0);
  const HalfedgeHandle o0 = m.opposite_halfedge_handle(h0), o1 = m.opposite_halfedge_handle(h1);
  const VertexHandle v0 = m.to_vertex_handle(h0), v1 = m.to_vertex_handle(h1);
  const FaceHandle fh = m.face_handle(h0), fo = m.face_handle(o0);
  m.set_next_halfedge_handle(h1, m.next_halfedge_handle(o0));
  m.set_next_halfedge_handle(m.prev_halfedge_handle(o0), h1);
  m.set_face_handle(h1, fo);
  m.set_halfedge_handle(v0, h1);
  keep_boundary_outgoing(m, v0);
  m.set_halfedge_handle(v1, o1);
  keep_boundary_outgoing(m, v1);
  if (fo.is_valid() && m.halfedge_handle(fo) == o0) m.set_halfedge_handle(fo, h1);
  if (fh.is_valid()) {
    m.set_halfedge_handle(fh, HalfedgeHandle());  // invalid
    m.status(fh).set_deleted(true);
  }
  mark_deleted(m, h0, o0);
}

}  // namespace

void collapse_halfedge(TriMesh& m, TriMesh::HalfedgeHandle h) {
  const HalfedgeHandle h1 = m.next_halfedge_handle(h);
  const HalfedgeHandle o1 = m.next_halfedge_handle(m.opposite_halfedge_handle(h));
  remove_edge_keep_to_vertex(m, h);
  if (m.next_halfedge_handle(m.next_halfedge_handle(h1)) == h1) remove_two_gon(m, m.next_halfedge_handle(h1));
  if (m.next_halfedge_handle(m.next_halfedge_handle(o1)) == o1) remove_two_gon(m, o1);
}

}  // namespace fest::terrainlod
