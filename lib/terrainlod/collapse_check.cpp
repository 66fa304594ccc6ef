#include "terrainlod/collapse_check.hpp"

#include <algorithm>

namespace fest::terrainlod {
namespace {

// The far corner of the triangle left of h, and whether that triangle's other two edges
// both lie on the boundary (collapsing h would leave a dangling edge).
bool both_other_edges_on_boundary(const TriMesh& m, TriMesh::HalfedgeHandle h, TriMesh::VertexHandle& corner) {
  const auto h1 = m.next_halfedge_handle(h), h2 = m.next_halfedge_handle(h1);
  corner = m.to_vertex_handle(h1);
  return m.is_boundary(m.opposite_halfedge_handle(h1)) && m.is_boundary(m.opposite_halfedge_handle(h2));
}

}  // namespace

bool CollapseCheck::collapse_ok(const TriMesh& m, TriMesh::HalfedgeHandle v0v1) {
  const auto v1v0 = m.opposite_halfedge_handle(v0v1);
  const auto v0 = m.to_vertex_handle(v1v0), v1 = m.to_vertex_handle(v0v1);
  TriMesh::VertexHandle vl, vr;  // invalid on a boundary side
  if (!m.is_boundary(v0v1) && both_other_edges_on_boundary(m, v0v1, vl)) return false;
  if (!m.is_boundary(v1v0) && both_other_edges_on_boundary(m, v1v0, vr)) return false;
  if (vl == vr) return false;
  if (++epoch_ == 0) {  // wrapped after 2^32 checks: clear the marks once
    std::fill(mark_.begin(), mark_.end(), 0u);
    epoch_ = 1;
  }
  // Outgoing half-edges around a vertex: next(opposite(h)) is the next one (for boundary
  // vertices too, across the boundary loop).
  const auto first1 = m.halfedge_handle(v1);
  auto h = first1;
  do {
    mark_[static_cast<std::size_t>(m.to_vertex_handle(h).idx())] = epoch_;
    h = m.next_halfedge_handle(m.opposite_halfedge_handle(h));
  } while (h != first1);
  const auto first0 = m.halfedge_handle(v0);
  h = first0;
  do {
    const auto u = m.to_vertex_handle(h);
    if (mark_[static_cast<std::size_t>(u.idx())] == epoch_ && u != vl && u != vr) return false;
    h = m.next_halfedge_handle(m.opposite_halfedge_handle(h));
  } while (h != first0);
  return !(m.is_boundary(v0) && m.is_boundary(v1) && !m.is_boundary(v0v1) && !m.is_boundary(v1v0));
}

}  // namespace fest::terrainlod
