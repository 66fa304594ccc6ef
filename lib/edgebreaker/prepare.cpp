// General meshes (docs/ebcode.md §5). Orientation is never changed: an edge is paired only between a
// face using it u->v and one using it v->u, in input face order, so edges with three or
// more faces and flipped faces become boundary instead of being "repaired".
#include "edgebreaker/prepare.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "core/error.hpp"

namespace fest::edgebreaker {
namespace {

constexpr std::size_t max_faces = static_cast<std::size_t>(std::numeric_limits<int>::max() / 16);

// Pairs u->v with v->u per undirected edge, first with first, in face order (step 3).
// Half-edges are bucketed by their first vertex (a counting sort, so corners stay in face
// order within a bucket), with each entry's end vertex stored beside it so that the scans
// below read one contiguous array instead of chasing V through next/prev. Each undirected
// edge is handled once, from its smaller vertex, by walking its u->v entries in bucket u
// and its v->u entries in bucket v side by side: O(sum of valence^2), linear on real meshes.
void pair_edges(CornerTable& table) {
  const int n = table.corners();
  const int* V = table.V.data();
  std::vector<int> start(static_cast<std::size_t>(table.vertex_count) + 1, 0);
  // Half-edges leaving each vertex: one per corner next(c); next permutes each triangle's
  // corners, so counting V[c] over all corners gives the same counts without it.
  for (int c = 0; c < n; ++c) ++start[static_cast<std::size_t>(V[c]) + 1];
  for (std::size_t v = 0; v + 1 < start.size(); ++v) start[v + 1] += start[v];
  std::vector<int> bucket(static_cast<std::size_t>(n)), bucket_to(static_cast<std::size_t>(n));
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int f = 0; f < n; f += 3)
      for (int j = 0; j < 3; ++j) {
        // corner f+j is opposite the half-edge V[next] -> V[prev]
        const int from = V[f + (j + 1) % 3], to = V[f + (j + 2) % 3];
        const int slot = fill[static_cast<std::size_t>(from)]++;
        bucket[static_cast<std::size_t>(slot)] = f + j;
        bucket_to[static_cast<std::size_t>(slot)] = to;
      }
  }
  int* O = table.O.data();
  for (int u = 0; u < table.vertex_count; ++u) {
    const int ub = start[static_cast<std::size_t>(u)], ue = start[static_cast<std::size_t>(u) + 1];
    for (int i = ub; i < ue; ++i) {
      const int v = bucket_to[static_cast<std::size_t>(i)];
      if (v < u) continue;  // from the smaller vertex only
      bool first = true;    // handle each (u, v) at its first u->v half-edge
      for (int k = ub; k < i && first; ++k) first = bucket_to[static_cast<std::size_t>(k)] != v;
      if (!first) continue;
      const int vb = start[static_cast<std::size_t>(v)], ve = start[static_cast<std::size_t>(v) + 1];
      int f = i, b = vb;
      for (;;) {  // the k-th u->v with the k-th v->u
        while (b < ve && bucket_to[static_cast<std::size_t>(b)] != u) ++b;
        if (b == ve) break;
        const int cf = bucket[static_cast<std::size_t>(f)], cb = bucket[static_cast<std::size_t>(b)];
        O[cf] = cb;
        O[cb] = cf;
        ++b;
        for (++f; f < ue && bucket_to[static_cast<std::size_t>(f)] != v;) ++f;
        if (f == ue) break;
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
  table.V.reserve(3 * faces.size());
  out.face_of.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const Triangle& t = faces[f];
    for (int v : t)
      if (v < 0 || v >= vertex_count)
        throw bad_input("face {} refers to vertex {}, outside 0..{}", f, v, vertex_count - 1);
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      if (strict) throw bad_input("face {} ({} {} {}) repeats a vertex (strict coding)", f, t[0], t[1], t[2]);
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
  // The corners of one fan form a path or a cycle under c -> next(O[next(c)]), whose
  // inverse is c -> prev(O[prev(c)]); walking it from the fan's lowest corner labels the
  // whole fan at once (a union-find over all corners cost a tenth of the encoder).
  // The fan met first (lowest face) keeps the vertex; later fans get copies in order.
  std::vector<char> owned(static_cast<std::size_t>(vertex_count), 0);  // some fan keeps the id
  std::vector<char> labelled(static_cast<std::size_t>(kept_corners), 0);
  std::vector<int> fan;
  int next_vertex = vertex_count;
  int* V = table.V.data();
  const int* O = table.O.data();
  for (int c = 0; c < kept_corners; ++c) {
    if (labelled[static_cast<std::size_t>(c)]) continue;
    const int v = V[c];
    int id = v;
    if (!owned[static_cast<std::size_t>(v)]) {
      owned[static_cast<std::size_t>(v)] = 1;
    } else {
      if (strict) throw bad_input("vertex {} is non-manifold (strict coding)", v);
      out.copy_of.push_back(v);
      id = next_vertex++;
    }
    fan.clear();
    fan.push_back(c);
    bool cycle = false;
    for (int k = c;;) {  // forwards
      const int o = O[next(k)];
      if (o < 0) break;
      k = next(o);
      if (k == c) {
        cycle = true;
        break;
      }
      fan.push_back(k);
    }
    if (!cycle)
      for (int k = c;;) {  // backwards
        const int o = O[prev(k)];
        if (o < 0) break;
        k = prev(o);
        fan.push_back(k);
      }
    for (int k : fan) {
      labelled[static_cast<std::size_t>(k)] = 1;
      V[k] = id;
    }
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
    if (strict) throw bad_input("the mesh has a boundary (strict coding)");
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
