#include "terrainlod/mesh_add_face.hpp"

#include <array>
#include <utility>

namespace fest::terrainlod {
namespace {

using HalfedgeHandle = TriMesh::HalfedgeHandle;
using VertexHandle = TriMesh::VertexHandle;

HalfedgeHandle halfedge_between(const TriMesh& m, VertexHandle from, VertexHandle to) {
  for (auto h : m.voh_range(from))
    if (m.to_vertex_handle(h) == to) return h;
  return HalfedgeHandle();
}

// See halfedge_collapse.cpp: a boundary vertex keeps a boundary half-edge as its outgoing one.
void keep_boundary_outgoing(TriMesh& m, VertexHandle v) {
  for (auto h : m.voh_range(v))
    if (m.is_boundary(h)) {
      m.set_halfedge_handle(v, h);
      return;
    }
}

}  // namespace

TriMesh::FaceHandle add_triangle(TriMesh& m, VertexHandle a, VertexHandle b, VertexHandle c) {
  constexpr int n = 3;
  const std::array<VertexHandle, n> v{a, b, c};
  struct Side {
    HalfedgeHandle h;  // v[i] -> v[i + 1]
    bool is_new = false;
    bool needs_adjust = false;
  };
  std::array<Side, n> side;
  // Every corner must be on the boundary and every existing side free on this side.
  for (int i = 0; i < n; ++i) {
    if (!m.is_boundary(v[i])) return TriMesh::FaceHandle();
    side[i].h = halfedge_between(m, v[i], v[(i + 1) % n]);
    side[i].is_new = !side[i].h.is_valid();
    if (!side[i].is_new && !m.is_boundary(side[i].h)) return TriMesh::FaceHandle();
  }
  // next-links to set, all at the end and in this order (later ones win).
  std::array<std::pair<HalfedgeHandle, HalfedgeHandle>, 6 * n> links;
  int n_links = 0;
  // Two existing sides that do not follow each other on the boundary: the boundary patch
  // between them moves to a free gap around their shared vertex.
  for (int i = 0; i < n; ++i) {
    const int ii = (i + 1) % n;
    if (side[i].is_new || side[ii].is_new) continue;
    const HalfedgeHandle inner_prev = side[i].h, inner_next = side[ii].h;
    if (m.next_halfedge_handle(inner_prev) == inner_next) continue;
    HalfedgeHandle boundary_prev = m.opposite_halfedge_handle(inner_next);
    do boundary_prev = m.opposite_halfedge_handle(m.next_halfedge_handle(boundary_prev));
    while (!m.is_boundary(boundary_prev));
    const HalfedgeHandle boundary_next = m.next_halfedge_handle(boundary_prev);
    if (boundary_prev == inner_prev) return TriMesh::FaceHandle();  // no free gap
    const HalfedgeHandle patch_start = m.next_halfedge_handle(inner_prev);
    const HalfedgeHandle patch_end = m.prev_halfedge_handle(inner_next);
    links[n_links++] = {boundary_prev, patch_start};
    links[n_links++] = {patch_end, boundary_next};
    links[n_links++] = {inner_prev, inner_next};
  }
  for (int i = 0; i < n; ++i)
    if (side[i].is_new) side[i].h = m.new_edge(v[i], v[(i + 1) % n]);
  const TriMesh::FaceHandle f = m.new_face();
  m.set_halfedge_handle(f, side[n - 1].h);
  for (int i = 0; i < n; ++i) {
    const int ii = (i + 1) % n;
    const VertexHandle corner = v[ii];
    const HalfedgeHandle inner_prev = side[i].h, inner_next = side[ii].h;
    const int fresh = (side[i].is_new ? 1 : 0) | (side[ii].is_new ? 2 : 0);
    if (fresh) {
      const HalfedgeHandle outer_prev = m.opposite_halfedge_handle(inner_next);
      const HalfedgeHandle outer_next = m.opposite_halfedge_handle(inner_prev);
      if (fresh == 1) {  // the side into the corner is new, the one out of it existed
        links[n_links++] = {m.prev_halfedge_handle(inner_next), outer_next};
        m.set_halfedge_handle(corner, outer_next);
      } else if (fresh == 2) {  // the side out of the corner is new
        const HalfedgeHandle boundary_next = m.next_halfedge_handle(inner_prev);
        links[n_links++] = {outer_prev, boundary_next};
        m.set_halfedge_handle(corner, boundary_next);
      } else if (!m.halfedge_handle(corner).is_valid()) {  // both new, an isolated corner
        m.set_halfedge_handle(corner, outer_next);
        links[n_links++] = {outer_prev, outer_next};
      } else {  // both new at a boundary corner: the face goes into the gap at its outgoing half-edge
        const HalfedgeHandle boundary_next = m.halfedge_handle(corner);
        const HalfedgeHandle boundary_prev = m.prev_halfedge_handle(boundary_next);
        links[n_links++] = {boundary_prev, outer_next};
        links[n_links++] = {outer_prev, boundary_next};
      }
      links[n_links++] = {inner_prev, inner_next};
    } else {
      side[ii].needs_adjust = m.halfedge_handle(corner) == inner_next;
    }
    m.set_face_handle(side[i].h, f);
  }
  for (int k = 0; k < n_links; ++k) m.set_next_halfedge_handle(links[k].first, links[k].second);
  for (int i = 0; i < n; ++i)
    if (side[i].needs_adjust) keep_boundary_outgoing(m, v[i]);
  return f;
}

}  // namespace fest::terrainlod
