// Spirale Reversi (Isenburg & Snoeyink; spec 2.3): the CLERS string read back to front
// rebuilds the mesh without the split offsets that forward decoding would need.
//
// The decoder keeps a stack of open loops; each entry is the tip corner of the loop's gate
// triangle and the loop's length. Tracking lengths is what keeps garbage harmless: every
// inverse operation checks the preconditions it needs (a loop to work on, C only on loops
// longer than 3, End on one 3-loop), so the corner table never gets a 1- or 2-gon and every
// swing is bounded. A string that passes those checks may still describe a non-manifold
// or non-simple result, so the mesh is finally re-encoded: only strings that are exactly
// the encoding of what they decode to are accepted, which makes decode the inverse of
// encode on its whole domain.
#include <algorithm>
#include <limits>
#include <numeric>

#include "core/error.hpp"
#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"

namespace fest::edgebreaker {
namespace {

struct Loop {
  int gate;    // tip corner of the triangle whose open edge (V[next], V[prev]) is the gate
  int length;  // edges on the loop
};

class ReverseDecoder {
 public:
  explicit ReverseDecoder(const Clers& clers) : clers_(clers) {
    const std::size_t triangles = clers.size() + 1;
    V_.reserve(3 * triangles);
    O_.reserve(3 * triangles);
    // Every C closes one vertex; the encoder visited C tips in forward order after the
    // three start vertices, and this decoder meets them in reverse.
    const auto cs = std::count(clers.begin(), clers.end(), Symbol::C);
    next_closed_ = 3 + static_cast<int>(cs) - 1;
  }

  std::vector<Triangle> run() {
    for (std::size_t i = clers_.size(); i-- > 0;) {
      position_ = i;
      switch (clers_[i]) {
        case Symbol::E: inverse_E(); break;
        case Symbol::L: inverse_L(); break;
        case Symbol::R: inverse_R(); break;
        case Symbol::C: inverse_C(); break;
        case Symbol::S: inverse_S(); break;
      }
    }
    close_start_triangle();
    return output();
  }

 private:
  [[noreturn]] void fail(const char* why) const {
    if (position_ >= clers_.size()) throw bad_input("invalid CLERS string: {} (when closing the start triangle)", why);
    throw bad_input("invalid CLERS string: {} (symbol {} of {}, '{}')", why, position_, clers_.size(),
                    to_char(clers_[position_]));
  }

  int new_triangle() {
    const int c = static_cast<int>(V_.size());
    V_.insert(V_.end(), {-1, -1, -1});
    O_.insert(O_.end(), {-1, -1, -1});
    return c;
  }
  int new_vertex() {
    parent_.push_back(static_cast<int>(parent_.size()));
    final_.push_back(-1);
    return parent_.back();
  }
  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];  // path halving
    return v;
  }
  void link(int a, int b) {
    if (O_[a] != -1 || O_[b] != -1) fail("an edge would get a third triangle");
    O_[a] = b;
    O_[b] = a;
  }
  Loop& top(const char* op) {
    if (loops_.empty()) fail(op);
    return loops_.back();
  }

  // The open edge that ends at V[next(a)] other than a's gate, found by swinging around
  // that vertex away from the gate. Returns the corner opposite it. Each vertex is swung
  // around at most twice (once when closed, once at the end), so the total is linear.
  int incoming_open_edge(int a) {
    int k = next(a);
    const int limit = static_cast<int>(V_.size());
    for (int step = 0; step < limit; ++step) {
      const int j = next(k);  // opposite the edge V[prev(k)] -> V[k], which ends at the vertex
      if (O_[j] == -1) {
        if (j == a) fail("a loop closed on itself");
        return j;
      }
      k = next(O_[j]);
    }
    fail("a vertex fan does not end");
  }

  void close_vertex(int v, int id) {
    const int r = find(v);
    if (final_[r] != -1) fail("a vertex is closed twice");
    final_[r] = id;
  }

  void inverse_E() {
    const int c = new_triangle();
    for (int k = 0; k < 3; ++k) V_[c + k] = new_vertex();
    loops_.push_back({c, 3});
  }
  void inverse_L() {
    Loop& loop = top("L with no open loop");
    const int a = loop.gate, c = new_triangle();
    V_[c] = V_[next(a)];
    V_[prev(c)] = V_[prev(a)];
    V_[next(c)] = new_vertex();
    link(next(c), a);
    loop = {c, loop.length + 1};
  }
  void inverse_R() {
    Loop& loop = top("R with no open loop");
    const int a = loop.gate, c = new_triangle();
    V_[next(c)] = V_[next(a)];
    V_[c] = V_[prev(a)];
    V_[prev(c)] = new_vertex();
    link(prev(c), a);
    loop = {c, loop.length + 1};
  }
  void inverse_C() {
    Loop& loop = top("C with no open loop");
    if (loop.length <= 3) fail("C on a loop of 3 edges");
    const int a = loop.gate;
    const int x = V_[next(a)];
    close_vertex(x, next_closed_--);
    const int e = incoming_open_edge(a);  // the open edge y -> x
    const int c = new_triangle();
    V_[c] = x;
    V_[next(c)] = V_[next(e)];
    V_[prev(c)] = V_[prev(a)];
    link(next(c), a);
    link(prev(c), e);
    loop = {c, loop.length - 1};
  }
  void inverse_S() {
    if (loops_.size() < 2) fail("S without two open loops (no matching E)");
    const Loop left_branch = loops_.back();  // continued first by the encoder, so decoded last
    loops_.pop_back();
    const Loop right_branch = loops_.back();
    loops_.pop_back();
    const int at = left_branch.gate, ab = right_branch.gate;
    // The chapter's "unifies two vertices from the two loops": the split vertex.
    const int u = find(V_[prev(at)]), w = find(V_[next(ab)]);
    if (final_[u] != -1 || final_[w] != -1) fail("S joins at a vertex that is already closed");
    parent_[u] = w;
    const int c = new_triangle();
    V_[c] = V_[next(ab)];
    V_[next(c)] = V_[next(at)];
    V_[prev(c)] = V_[prev(ab)];
    link(prev(c), at);
    link(next(c), ab);
    loops_.push_back({c, left_branch.length + right_branch.length - 1});
  }

  // The last open loop must be the start triangle's 3-loop x -> p -> w -> x.
  void close_start_triangle() {
    position_ = clers_.size();  // errors from here on concern the whole string
    if (clers_.empty()) throw bad_input("invalid CLERS string: empty (a closed mesh has at least one E)");
    if (loops_.size() != 1)
      throw bad_input("invalid CLERS string: #E - #S is {}, a closed genus-0 mesh needs 1", loops_.size());
    if (loops_.back().length != 3) fail("the last open loop has more than 3 edges");
    const int a = loops_.back().gate;
    const int e = incoming_open_edge(a);  // w -> x
    const int w = V_[next(e)];
    const int f = incoming_open_edge(e);  // p -> w: e's open edge w -> x leaves w
    if (f == e || find(V_[next(f)]) != find(V_[prev(a)])) fail("the last open loop is not a triangle");
    const int s = new_triangle();
    V_[s] = w;
    V_[next(s)] = V_[prev(a)];
    V_[prev(s)] = V_[next(a)];
    link(s, a);
    link(next(s), e);
    link(prev(s), f);
    const int ids[3] = {find(V_[s]), find(V_[next(s)]), find(V_[prev(s)])};
    if (ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0]) fail("the start triangle is degenerate");
    for (int k = 0; k < 3; ++k) close_vertex(ids[k], k);
  }

  std::vector<Triangle> output() {
    for (std::size_t v = 0; v < parent_.size(); ++v)
      if (final_[find(static_cast<int>(v))] == -1)
        throw bad_input("invalid CLERS string: a vertex is never closed by a C");
    const int t = static_cast<int>(V_.size() / 3);
    std::vector<Triangle> out;
    out.reserve(static_cast<std::size_t>(t));
    // Start triangle (created last) first, then the others in forward symbol order.
    for (int i = t - 1; i >= 0; --i)
      out.push_back({final_[find(V_[3 * i])], final_[find(V_[3 * i + 1])], final_[find(V_[3 * i + 2])]});
    return out;
  }

  const Clers& clers_;
  std::size_t position_ = 0;
  int next_closed_ = 0;
  std::vector<int> V_, O_;
  std::vector<int> parent_, final_;  // union-find over provisional vertex ids; final index
  std::vector<Loop> loops_;
};

}  // namespace

std::vector<Triangle> decode(const Clers& clers) {
  if (clers.empty()) throw bad_input("invalid CLERS string: empty (a closed mesh has at least one E)");
  if (clers.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 16))
    throw bad_input("invalid CLERS string: {} symbols, more than supported", clers.size());
  std::vector<Triangle> triangles = ReverseDecoder(clers).run();

  const int vertex_count = static_cast<int>(std::count(clers.begin(), clers.end(), Symbol::C)) + 3;
  Encoded again;
  try {
    again = encode(triangles, vertex_count);
  } catch (const Error& e) {
    throw bad_input("invalid CLERS string: it decodes to a mesh the coder does not take: {}", e.what());
  }
  if (again.clers != clers) {
    const auto mismatch = std::mismatch(clers.begin(), clers.end(), again.clers.begin(), again.clers.end());
    throw bad_input("invalid CLERS string: the mesh it decodes to encodes differently from symbol {}",
                    mismatch.first - clers.begin());
  }
  std::vector<int> identity(static_cast<std::size_t>(vertex_count));
  std::iota(identity.begin(), identity.end(), 0);
  if (again.vertex_order != identity)
    throw bad_input("invalid CLERS string: decoded vertex numbering differs from the visit order");
  return triangles;
}

}  // namespace fest::edgebreaker
