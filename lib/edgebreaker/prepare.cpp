// spec 2.8 steps 2-5 and 8. Orientation is never changed: an edge is paired only between a
// face using it u->v and one using it v->u, in input face order, so edges with three or
// more faces and flipped faces become boundary instead of being "repaired".
#include "edgebreaker/prepare.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <utility>

#include "core/error.hpp"

namespace fest::edgebreaker {
namespace {

constexpr std::size_t max_faces = static_cast<std::size_t>(std::numeric_limits<int>::max() / 16);

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<std::size_t>(n)) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int v) {
    while (parent[static_cast<std::size_t>(v)] != v) {
      const int up = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(v)])];
      parent[static_cast<std::size_t>(v)] = up;
      v = up;
    }
    return v;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// Pairs u->v with v->u per undirected edge, first with first, in face order (step 3).
// Half-edges are bucketed by their first vertex (a counting sort, so corners stay in face
// order within a bucket); each undirected edge is handled once, from its smaller vertex,
// by scanning the two buckets: O(sum of valence^2), linear on real meshes.
void pair_edges(CornerTable& table) {
  const int n = table.corners();
  const auto from = [&](int c) { return table.V[static_cast<std::size_t>(next(c))]; };
  const auto to = [&](int c) { return table.V[static_cast<std::size_t>(prev(c))]; };
  std::vector<int> start(static_cast<std::size_t>(table.vertex_count) + 1, 0);
  for (int c = 0; c < n; ++c) ++start[static_cast<std::size_t>(from(c)) + 1];
  for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
  std::vector<int> bucket(static_cast<std::size_t>(n));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int c = 0; c < n; ++c) bucket[static_cast<std::size_t>(fill[static_cast<std::size_t>(from(c))]++)] = c;
  }
  std::vector<int> forward, backward;
  for (int u = 0; u < table.vertex_count; ++u) {
    const int* ub = bucket.data() + start[static_cast<std::size_t>(u)];
    const int un = start[static_cast<std::size_t>(u) + 1] - start[static_cast<std::size_t>(u)];
    for (int i = 0; i < un; ++i) {
      const int v = to(ub[i]);
      if (v < u) continue;  // from the smaller vertex only
      bool first = true;    // handle each (u, v) at its first u->v half-edge
      for (int k = 0; k < i && first; ++k) first = to(ub[k]) != v;
      if (!first) continue;
      forward.clear();
      backward.clear();
      for (int k = i; k < un; ++k)
        if (to(ub[k]) == v) forward.push_back(ub[k]);
      const int* vb = bucket.data() + start[static_cast<std::size_t>(v)];
      const int vn = start[static_cast<std::size_t>(v) + 1] - start[static_cast<std::size_t>(v)];
      for (int k = 0; k < vn; ++k)
        if (to(vb[k]) == u) backward.push_back(vb[k]);
      for (std::size_t k = 0; k < std::min(forward.size(), backward.size()); ++k) {
        table.O[static_cast<std::size_t>(forward[k])] = backward[k];
        table.O[static_cast<std::size_t>(backward[k])] = forward[k];
      }
    }
  }
}

}  // namespace

PreparedMesh prepare_mesh(const std::vector<Triangle>& faces, int vertex_count, bool strict) {
  if (vertex_count < 0) throw bad_input("vertex count {} is negative", vertex_count);
  if (faces.size() > max_faces) throw bad_input("{} faces, more than the {} supported", faces.size(), max_faces);
  PreparedMesh out;
  out.input_vertices = vertex_count;
  CornerTable& table = out.table;

  // Step 2: indices checked, degenerate faces dropped.
  std::vector<char> used(static_cast<std::size_t>(vertex_count), 0);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    for (int v : t)
      if (v < 0 || v >= vertex_count)
        throw bad_input("face {} refers to vertex {}, outside 0..{}", f, v, vertex_count - 1);
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      if (strict) throw bad_input("face {} ({} {} {}) repeats a vertex (--strict)", f, t[0], t[1], t[2]);
      ++out.dropped_degenerate;
      continue;
    }
    table.V.insert(table.V.end(), t.begin(), t.end());
    out.face_of.push_back(static_cast<int>(f));
    for (int v : t) used[static_cast<std::size_t>(v)] = 1;
  }
  for (int v = 0; v < vertex_count; ++v)
    if (!used[static_cast<std::size_t>(v)]) out.isolated.push_back(v);
  table.O.assign(table.V.size(), -1);
  table.vertex_count = vertex_count;  // input ids for now; copies and dummies follow
  pair_edges(table);
  const int kept_corners = table.corners();

  // Step 4: corners around a vertex joined through paired edges form fans. The corner
  // next to c across its edge V[c] -> V[prev(c)]... is next(O[next(c)]), at the same vertex.
  UnionFind fans(kept_corners);
  for (int c = 0; c < kept_corners; ++c) {
    const int o = table.O[static_cast<std::size_t>(next(c))];
    if (o >= 0) fans.unite(c, next(o));
  }
  // The fan met first (lowest face) keeps the vertex; later fans get copies in order.
  std::vector<int> owner(static_cast<std::size_t>(vertex_count), -1);  // root keeping the id
  std::vector<int> fan_vertex(static_cast<std::size_t>(kept_corners), -1);  // per root
  int next_vertex = vertex_count;
  for (int c = 0; c < kept_corners; ++c) {
    const int root = fans.find(c);
    int& id = fan_vertex[static_cast<std::size_t>(root)];
    const int v = table.V[static_cast<std::size_t>(c)];
    if (id == -1) {
      if (owner[static_cast<std::size_t>(v)] == -1) {
        owner[static_cast<std::size_t>(v)] = root;
        id = v;
      } else {
        if (strict) throw bad_input("vertex {} is non-manifold (--strict)", v);
        out.copy_of.push_back(v);
        id = next_vertex++;
      }
    }
    table.V[static_cast<std::size_t>(c)] = id;
  }
  out.first_dummy = next_vertex;

  // Step 5: every boundary loop gets a dummy vertex and a fan of triangles (v, u, d), one
  // per boundary half-edge u -> v. After splitting each vertex has at most one outgoing
  // boundary half-edge, so the loops are simple.
  std::vector<int> outgoing(static_cast<std::size_t>(next_vertex), -1);  // boundary corner leaving v
  for (int c = 0; c < kept_corners; ++c)
    if (table.O[static_cast<std::size_t>(c)] == -1) {
      int& slot = outgoing[static_cast<std::size_t>(table.V[static_cast<std::size_t>(next(c))])];
      if (slot != -1) throw runtime_failure("internal: two boundary edges leave one vertex after splitting");
      slot = c;
    }
  for (int c0 = 0; c0 < kept_corners; ++c0) {
    if (table.O[static_cast<std::size_t>(c0)] != -1) continue;
    if (strict) throw bad_input("the mesh has a boundary (--strict)");
    const int d = next_vertex++;
    ++out.holes;
    int c = c0;
    int first_new = -1, last_new = -1;
    do {
      const int u = table.V[static_cast<std::size_t>(next(c))], v = table.V[static_cast<std::size_t>(prev(c))];
      const int t = table.corners();
      table.V.insert(table.V.end(), {v, u, d});
      table.O.insert(table.O.end(), {-1, -1, -1});
      out.face_of.push_back(-1);
      // Corner t+2 (at d) is opposite v -> u: the reverse of the boundary half-edge.
      table.O[static_cast<std::size_t>(t + 2)] = c;
      table.O[static_cast<std::size_t>(c)] = t + 2;
      // Consecutive dummy triangles share the edge (v, d): corner t (at v) of this one is
      // opposite u -> d ... linked when the next triangle, starting at v, is made.
      if (last_new != -1) {
        // previous triangle (v', u', d) with u' ... its edge d -> v' is opposite corner
        // last_new + 1 (at u'); this triangle's edge u -> d is opposite corner t (at v).
        table.O[static_cast<std::size_t>(last_new + 1)] = t;
        table.O[static_cast<std::size_t>(t)] = last_new + 1;
      } else {
        first_new = t;
      }
      last_new = t;
      const int w = outgoing[static_cast<std::size_t>(v)];
      if (w == -1) throw runtime_failure("internal: a boundary loop does not continue");
      c = w;
    } while (c != c0);
    table.O[static_cast<std::size_t>(last_new + 1)] = first_new;
    table.O[static_cast<std::size_t>(first_new)] = last_new + 1;
  }
  table.vertex_count = next_vertex;
  return out;
}

}  // namespace fest::edgebreaker
