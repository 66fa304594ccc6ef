// reencodes_exactly() (the decoder's one-pass self-check) against the reference check it
// replaces on accepted streams: check_closed_manifold(), traverse() and the comparison of
// its results, written out here. On decoded tables both must accept; on random damage
// (vertex ids, opposite pairs, symbols, events, renumbered vertices and faces, rotated
// triangles) the one-pass check may only accept what the reference accepts.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "edgebreaker/corner_table.hpp"
#include "edgebreaker/prepare.hpp"
#include "edgebreaker/reencode_check.hpp"
#include "edgebreaker/reverse_decoder.hpp"
#include "edgebreaker/reverse_decoder_steps.hpp"
#include "edgebreaker/traversal.hpp"
#include "test_edgebreaker_meshes.hpp"

namespace {

using namespace fest::edgebreaker;

struct Case {
  std::vector<int> V, O;
  int vertex_count = 0;
  Clers reversed;  // decode order
  std::vector<HandleEvent> events;
};

bool reference(const Case& k) {
  CornerTable table;
  table.V = k.V;
  table.O = k.O;
  table.vertex_count = k.vertex_count;
  try {
    check_closed_manifold(table);
  } catch (const fest::Error&) {
    return false;
  }
  const Traversal again = traverse(table);
  for (std::size_t g = 0; g < again.vertex_order.size(); ++g)
    if (again.vertex_order[g] != static_cast<int>(g)) return false;
  for (std::size_t i = 0; i < again.triangle_order.size(); ++i)
    if (again.triangle_order[i] != static_cast<int>(i)) return false;
  if (again.code.events != k.events) return false;
  return std::equal(again.code.clers.begin(), again.code.clers.end(), k.reversed.rbegin(), k.reversed.rend());
}

bool one_pass(const Case& k) {
  return reencodes_exactly(k.V.data(), k.O.data(), static_cast<int>(k.V.size() / 3), k.vertex_count, k.reversed.data(),
                           k.reversed.size(), k.events);
}

// What the decoder hands to its check: the decoded faces and opposite corners.
Case decoded(const std::vector<Triangle>& faces, int vertex_count) {
  const PreparedMesh prepared = prepare_mesh(faces, vertex_count);
  const Traversal trav = traverse(prepared.table);
  ReverseDecoder decoder(trav.code.clers.size(), trav.code.events);
  for (std::size_t i = trav.code.clers.size(); i-- > 0;) decoder.step(trav.code.clers[i]);
  const DecodedConnectivity d = decoder.finish(false, true);
  Case k;
  for (const Triangle& t : d.triangles) k.V.insert(k.V.end(), t.begin(), t.end());
  k.O = d.opposite;
  k.vertex_count = d.vertex_count;
  k.reversed.assign(trav.code.clers.rbegin(), trav.code.clers.rend());
  k.events = trav.code.events;
  return k;
}

// An n x m torus grid: genus 1, so its code has handle events.
std::vector<Triangle> torus(int n, int m) {
  std::vector<Triangle> out;
  const auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j) {
      out.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      out.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return out;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  const auto sphere = fest::test::eb::subdivided_icosahedron(2);
  out.push_back(decoded(sphere.triangles, sphere.vertex_count));
  out.push_back(decoded(fest::test::eb::tetrahedron().triangles, 4));
  out.push_back(decoded(torus(6, 7), 42));
  // Two pieces: a second sphere beside a torus (two components, events in the second).
  std::vector<Triangle> two = sphere.triangles;
  for (Triangle t : torus(5, 4)) {
    for (int& v : t) v += sphere.vertex_count;
    two.push_back(t);
  }
  out.push_back(decoded(two, sphere.vertex_count + 20));
  return out;
}

TEST(EdgebreakerReencodeCheck, AcceptsWhatTheDecoderBuilds) {
  for (const Case& k : cases()) {
    EXPECT_TRUE(reference(k));
    EXPECT_TRUE(one_pass(k));
    EXPECT_FALSE(k.events.empty() && k.vertex_count == 42);
  }
}

// Damage of every kind the check must see through; the one-pass check never accepts what
// the reference rejects (and, on these, agrees with it everywhere).
TEST(EdgebreakerReencodeCheck, NeverAcceptsWhatTheReferenceRejects) {
  std::mt19937 rng(23);
  int rejected = 0, total = 0;
  for (const Case& base : cases()) {
    const int n = static_cast<int>(base.V.size());
    for (int trial = 0; trial < 600; ++trial) {
      Case k = base;
      const auto pick = [&](int bound) { return static_cast<int>(rng() % static_cast<unsigned>(bound)); };
      switch (trial % 8) {
        case 0: k.V[static_cast<std::size_t>(pick(n))] = pick(k.vertex_count); break;
        case 1: {  // re-pair two opposite pairs: O stays an involution
          const int a = pick(n), c = pick(n);
          const int b = k.O[static_cast<std::size_t>(a)], d = k.O[static_cast<std::size_t>(c)];
          if (a == c || a == d) break;
          k.O[static_cast<std::size_t>(a)] = c, k.O[static_cast<std::size_t>(c)] = a;
          k.O[static_cast<std::size_t>(b)] = d, k.O[static_cast<std::size_t>(d)] = b;
          break;
        }
        case 2: k.reversed[static_cast<std::size_t>(pick(static_cast<int>(k.reversed.size())))] = static_cast<Symbol>(pick(5)); break;
        case 3:
          if (!k.events.empty()) {
            HandleEvent& e = k.events[static_cast<std::size_t>(pick(static_cast<int>(k.events.size())))];
            if (pick(2)) e.right_edge = !e.right_edge;
            else e.split = static_cast<std::uint32_t>(pick(static_cast<int>(e.source) + 1));
          } else {
            k.events.push_back({0, 1, false});
          }
          break;
        case 4: {  // swap two vertex ids everywhere: still a manifold, another visit order
          const int a = pick(k.vertex_count), b = pick(k.vertex_count);
          for (int& v : k.V) v = v == a ? b : v == b ? a : v;
          break;
        }
        case 5: {  // swap two triangles' places (their opposites follow)
          const int s = pick(n / 3), u = pick(n / 3);
          std::vector<int> where(static_cast<std::size_t>(n));
          for (int c = 0; c < n; ++c) {
            const int f = c / 3, f2 = f == s ? u : f == u ? s : f;
            where[static_cast<std::size_t>(c)] = 3 * f2 + c % 3;
          }
          Case m = k;
          for (int c = 0; c < n; ++c) {
            m.V[static_cast<std::size_t>(where[static_cast<std::size_t>(c)])] = k.V[static_cast<std::size_t>(c)];
            m.O[static_cast<std::size_t>(where[static_cast<std::size_t>(c)])] =
                where[static_cast<std::size_t>(k.O[static_cast<std::size_t>(c)])];
          }
          k = m;
          break;
        }
        case 6: {  // rotate one triangle's corners (opposites follow)
          const int f = pick(n / 3);
          Case m = k;
          const auto rot = [&](int c) { return c / 3 == f ? 3 * f + (c % 3 + 1) % 3 : c; };
          for (int c = 0; c < n; ++c) {
            m.V[static_cast<std::size_t>(rot(c))] = k.V[static_cast<std::size_t>(c)];
            m.O[static_cast<std::size_t>(rot(c))] = rot(k.O[static_cast<std::size_t>(c)]);
          }
          k = m;
          break;
        }
        default:  // a symbol too many or too few
          if (pick(2)) k.reversed.push_back(Symbol::E);
          else k.reversed.pop_back();
          break;
      }
      const bool ref = reference(k), fast = one_pass(k);
      ++total;
      rejected += ref ? 0 : 1;
      EXPECT_FALSE(fast && !ref) << "trial " << trial;
      EXPECT_EQ(fast, ref) << "trial " << trial;
    }
  }
  EXPECT_GT(rejected, total / 2);  // the damage is mostly caught (some edits are no-ops)
}

}  // namespace
