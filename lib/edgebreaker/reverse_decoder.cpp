// Spirale Reversi (Isenburg & Snoeyink; docs/ebcode.md §2), generalised to several components and
// to handles (§5). Robustness against hostile strings: every inverse operation
// checks what it needs (a loop to work on, C only on a loop longer than 3 while lengths
// are known, links only between open corners), every swing is bounded, and finish()
// re-encodes the result, so only exact encodings are accepted.
#include "edgebreaker/reverse_decoder.hpp"
#include "edgebreaker/reverse_decoder_steps.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <memory>

#include "edgebreaker/reencode_check.hpp"

#include "core/error.hpp"

namespace fest::edgebreaker {

ReverseDecoder::ReverseDecoder(std::size_t symbols, std::vector<HandleEvent> events, bool simple)
    : simple_(simple), symbols_(symbols), position_(symbols), events_(std::move(events)), next_event_(events_.size()) {
  // Corner ids are ints: 3 per triangle, at most symbols + components triangles.
  if (symbols > static_cast<std::size_t>(std::numeric_limits<int>::max() / 16))
    throw bad_input("invalid connectivity: {} symbols, more than supported", symbols);
  // Reserve for what is announced, up to a limit: beyond it memory grows only with the
  // symbols actually decoded, so a lying count costs nothing.
  const std::size_t expected = std::min<std::size_t>(symbols, std::size_t{1} << 16);
  decoded_.reserve(expected);
  V_.reserve(3 * (expected + 2));
  O_.reserve(3 * (expected + 2));
  vertices_.reserve(expected + 3);
  for (std::size_t k = 0; k < events_.size(); ++k) {
    const HandleEvent& e = events_[k];
    if (e.source >= symbols || e.split >= e.source)
      throw bad_input("invalid handle event {}: split {} and source {} (of {} symbols)", k, e.split, e.source, symbols);
    if (k > 0 && (events_[k - 1].source > e.source ||
                  (events_[k - 1].source == e.source && events_[k - 1].right_edge >= e.right_edge)))
      throw bad_input("invalid handle event {}: events are not in order", k);
  }
  next_event_source_ = events_.empty() ? std::numeric_limits<std::size_t>::max() : events_.back().source;
}

void ReverseDecoder::reserve(std::size_t symbols) {
  symbols = std::min(symbols, symbols_);
  if (keep_symbols_) decoded_.reserve(symbols);
  V_.reserve(3 * (symbols + 2));
  O_.reserve(3 * (symbols + 2));
  vertices_.reserve(symbols + 3);
  closed_at_.reserve(symbols / 2 + 1);
}

void ReverseDecoder::fail(const char* why) const {
  if (position_ >= symbols_) throw bad_input("invalid connectivity: {} (when closing the start triangles)", why);
  throw bad_input("invalid connectivity: {} (symbol {} of {})", why, position_, symbols_);
}

// Handle events whose source is the symbol just decoded: the corner across the edge
// towards the S waits for that S.
void ReverseDecoder::remember_events(int c) {
  while (next_event_ > 0 && events_[next_event_ - 1].source == position_) {
    const HandleEvent& e = events_[--next_event_];
    const int corner = e.right_edge ? c + 1 : c + 2;
    if (!pending_.emplace(e.split, corner).second) fail("two handle events for one S");
  }
  next_event_source_ = next_event_ > 0 ? events_[next_event_ - 1].source : std::numeric_limits<std::size_t>::max();
}

void ReverseDecoder::inverse_S() {
  if (loops_.empty()) fail("S without an open loop");
  const Loop left_branch = loops_.back();  // continued first by the encoder, so decoded last
  loops_.pop_back();
  Loop right_branch{-1, -1};
  const auto event = pending_.empty() ? pending_.end() : pending_.find(static_cast<std::uint32_t>(position_));
  if (event != pending_.end()) {  // the right branch was reached through a handle
    right_branch.gate = event->second;
    pending_.erase(event);
    // The corner may lie on any loop of the stack, which this S joins to the current one:
    // from here on no tracked length can be trusted.
    for (Loop& loop : loops_) loop.length = -1;
    if (O_[static_cast<std::size_t>(right_branch.gate)] != -1) fail("a handle event names a closed edge");
  } else {
    if (loops_.empty()) fail("S without two open loops (no matching E)");
    right_branch = loops_.back();
    loops_.pop_back();
  }
  const int at = left_branch.gate, ab = right_branch.gate;
  // The chapter's "unifies two vertices from the two loops": the split vertex.
  const int u = find(V_[static_cast<std::size_t>(prev(at))]), w = find(V_[static_cast<std::size_t>(next(ab))]);
  if (vertices_[static_cast<std::size_t>(u)].closed || vertices_[static_cast<std::size_t>(w)].closed)
    fail("S joins at a vertex that is already closed");
  if (u != w) {
    vertices_[static_cast<std::size_t>(u)].parent = w;
    vertices_[static_cast<std::size_t>(w)].degree += vertices_[static_cast<std::size_t>(u)].degree;
  }
  const int c = new_triangle();
  V_[static_cast<std::size_t>(c)] = V_[static_cast<std::size_t>(next(ab))];
  V_[static_cast<std::size_t>(c + 1)] = V_[static_cast<std::size_t>(next(at))];
  V_[static_cast<std::size_t>(c + 2)] = V_[static_cast<std::size_t>(prev(ab))];
  link(c + 2, at);
  link(c + 1, ab);
  const bool known = left_branch.length >= 0 && right_branch.length >= 0;
  loops_.push_back({c, known ? left_branch.length + right_branch.length - 1 : -1});
  ++vertices_[static_cast<std::size_t>(root_at(c))].degree;
  const int left = root_at(c + 1);
  ++vertices_[static_cast<std::size_t>(left)].degree;
  ++vertices_[static_cast<std::size_t>(root_at(c + 2))].degree;
  set_valence(vertices_[static_cast<std::size_t>(left)].degree);
  if (event_here()) remember_events(c);
}

DecodedConnectivity ReverseDecoder::finish(bool verify, bool opposite, bool valence) {
  if (verify && !keep_symbols_) throw runtime_failure("internal: verification without the decoded symbols");
  if (position_ != 0) throw bad_input("invalid connectivity: {} symbols missing", position_);
  position_ = symbols_;
  if (!pending_.empty() || next_event_ != 0) fail("a handle event has no S");
  const int symbol_triangles = static_cast<int>(V_.size() / 3);

  // Each remaining loop, popped in order, is one component's start triangle.
  DecodedConnectivity out;
  out.components = static_cast<int>(loops_.size());
  std::vector<int> start_corner;
  while (!loops_.empty()) {
    const Loop loop = loops_.back();
    loops_.pop_back();
    if (loop.length >= 0 && loop.length != 3) fail("a last open loop is not 3 edges long");
    const int a = loop.gate;
    const int e = incoming_open_edge(a);  // w -> x
    const int f = incoming_open_edge(e);  // p -> w
    if (f == e || find(V_[static_cast<std::size_t>(next(f))]) != find(V_[static_cast<std::size_t>(prev(a))]))
      fail("a last open loop is not a triangle");
    const int s = new_triangle();
    V_[static_cast<std::size_t>(s)] = V_[static_cast<std::size_t>(next(e))];
    V_[static_cast<std::size_t>(s + 1)] = V_[static_cast<std::size_t>(prev(a))];
    V_[static_cast<std::size_t>(s + 2)] = V_[static_cast<std::size_t>(next(a))];
    link(s, a);
    link(s + 1, e);
    link(s + 2, f);
    start_corner.push_back(s);
  }
  // Every link() joined two open corners (it refuses any other), so the edges are all
  // closed exactly when the links account for every corner.
  if (2 * links_ != V_.size()) fail("an edge is left open");

  // Components: label triangles from each start triangle. With one start triangle the
  // labels are all 0 without a search: every triangle was linked to the loop it was made
  // on (E makes a loop, S links the triangles of the two loops it joins), so the pieces
  // linked so far always number at most the open loops, and one loop is left at the end.
  const int t = static_cast<int>(V_.size() / 3);
  const bool one_component = out.components == 1;
  std::vector<int> component;
  if (!one_component) {
    component.assign(static_cast<std::size_t>(t), -1);
    std::vector<int> todo;
    for (int j = 0; j < out.components; ++j) {
      const int s0 = start_corner[static_cast<std::size_t>(j)] / 3;
      if (component[static_cast<std::size_t>(s0)] != -1) fail("two start triangles in one component");
      component[static_cast<std::size_t>(s0)] = j;
      todo.push_back(s0);
      while (!todo.empty()) {
        const int f = todo.back();
        todo.pop_back();
        for (int k = 0; k < 3; ++k) {
          const int g = O_[static_cast<std::size_t>(3 * f + k)] / 3;
          if (component[static_cast<std::size_t>(g)] == -1) {
            component[static_cast<std::size_t>(g)] = j;
            todo.push_back(g);
          }
        }
      }
    }
  }
  const auto in_component = [&](int triangle, int j) {
    return one_component || component[static_cast<std::size_t>(triangle)] == j;
  };

  // G numbering: per component its three start vertices, then its C vertices in forward
  // order (the reverse of the closing order), which must come grouped by component.
  const std::size_t provisional = vertices_.size();
  std::vector<int> final_id(provisional, -1);
  int next_id = 0;
  std::size_t next_c = closed_at_.size();  // walk closed_at_ backwards = forward order
  out.parallelogram.reserve(provisional);
  std::vector<int> g_corner;  // per G vertex: the C tip corner, or -1
  if (!one_component) g_corner.reserve(closed_at_.size() + 3 * start_corner.size());
  for (int j = 0; j < out.components; ++j) {
    const int s = start_corner[static_cast<std::size_t>(j)];
    for (int k = 0; k < 3; ++k) {
      const int r = find(V_[static_cast<std::size_t>(s + k)]);
      if (final_id[static_cast<std::size_t>(r)] != -1 || vertices_[static_cast<std::size_t>(r)].closed)
        fail("a start triangle's vertex is used twice");
      final_id[static_cast<std::size_t>(r)] = next_id++;
      if (!one_component) g_corner.push_back(-1);
    }
    while (next_c > 0 && in_component(closed_at_[next_c - 1] / 3, j)) {
      const int c = closed_at_[--next_c];
      const int r = find(V_[static_cast<std::size_t>(c)]);
      if (final_id[static_cast<std::size_t>(r)] != -1) fail("a vertex is closed twice");
      final_id[static_cast<std::size_t>(r)] = next_id++;
      if (!one_component) g_corner.push_back(c);
    }
  }
  if (next_c != 0) fail("the C symbols of the components are interleaved");
  out.vertex_count = next_id;
  // Every provisional vertex's G id, its root looked up once (not once per corner).
  std::vector<int> g_of(provisional);
  for (std::size_t v = 0; v < provisional; ++v) {
    g_of[v] = final_id[static_cast<std::size_t>(find(static_cast<int>(v)))];
    if (g_of[v] == -1) fail("a vertex is never closed by a C");
  }
  const int* const V = V_.data();
  const auto id = [&](int corner) { return g_of[static_cast<std::size_t>(V[corner])]; };
  if (valence) {
    // A root's degree counts every corner of its set made by a symbol (the valence
    // context's count); the start triangles, closed here, add theirs.
    out.valence.assign(static_cast<std::size_t>(next_id), 0);
    for (std::size_t v = 0; v < provisional; ++v)
      if (vertices_[v].parent == static_cast<int>(v)) out.valence[static_cast<std::size_t>(g_of[v])] = vertices_[v].degree;
    for (int s : start_corner)
      for (int k = 0; k < 3; ++k) ++out.valence[static_cast<std::size_t>(id(s + k))];
  }
  const auto parallelogram = [&](int c) {
    return std::array<int, 3>{id(c + 1), id(c + 2), id(O_[static_cast<std::size_t>(c)])};
  };
  if (one_component) {  // G order: the start triangle's vertices, then closed_at_ backwards
    out.parallelogram.assign(3, {-1, -1, -1});
    for (std::size_t k = closed_at_.size(); k-- > 0;) out.parallelogram.push_back(parallelogram(closed_at_[k]));
  } else {
    for (int c : g_corner) out.parallelogram.push_back(c < 0 ? std::array<int, 3>{-1, -1, -1} : parallelogram(c));
  }

  // Output faces: per component the start triangle, then its symbols in forward order
  // (symbol i was triangle symbol_triangles - 1 - i). new_index maps this decoder's
  // triangles to output positions, for the opposite table and the verification.
  const bool need_index = verify || opposite;
  out.triangles.resize(static_cast<std::size_t>(t));
  Triangle* faces = out.triangles.data();
  std::size_t made = 0;
  std::vector<int> new_index(need_index ? static_cast<std::size_t>(t) : 0, -1);
  std::size_t symbol = 0;
  for (int j = 0; j < out.components; ++j) {
    const int s = start_corner[static_cast<std::size_t>(j)];
    if (need_index) new_index[static_cast<std::size_t>(s / 3)] = static_cast<int>(made);
    faces[made++] = {id(s), id(s + 1), id(s + 2)};
    for (; symbol < symbols_; ++symbol) {
      const int tri = symbol_triangles - 1 - static_cast<int>(symbol);
      if (!in_component(tri, j)) break;
      if (need_index) new_index[static_cast<std::size_t>(tri)] = static_cast<int>(made);
      faces[made++] = {id(3 * tri), id(3 * tri + 1), id(3 * tri + 2)};
    }
  }
  if (symbol != symbols_) fail("the symbols of the components are interleaved");

  // Corners are >= 0 here: unsigned division and remainder (a multiply and a shift).
  const auto moved = [&](int c) {
    const unsigned q = static_cast<unsigned>(c) / 3u;
    return 3 * new_index[q] + (c - 3 * static_cast<int>(q));
  };
  if (need_index) out.opposite.resize(static_cast<std::size_t>(3 * t));
  for (int f = 0; f < t && need_index; ++f) {  // per triangle: one new_index lookup for its own corners
    const int base = 3 * new_index[static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k) out.opposite[static_cast<std::size_t>(base + k)] = moved(O_[static_cast<std::size_t>(3 * f + k)]);
  }

  if (verify) {
    // Re-encode the decoded corner table itself (not a table rebuilt from the faces, which
    // could not tell the two edges of a multi-edge apart). The one-pass check decides
    // every accepted stream; whatever it does not show goes through the reference check
    // below, which names the problem.
    static_assert(sizeof(Triangle) == 3 * sizeof(int), "faces are read as one array of corners");
    std::unique_ptr<int[]> corners_v(new int[static_cast<std::size_t>(3 * t)]);
    std::memcpy(corners_v.get(), out.triangles.data(), sizeof(int) * static_cast<std::size_t>(3 * t));
    if (reencodes_exactly(corners_v.get(), out.opposite.data(), t, out.vertex_count, decoded_.data(), decoded_.size(),
                          events_))
      return out;
    CornerTable table;
    table.vertex_count = out.vertex_count;
    table.V.resize(static_cast<std::size_t>(3 * t));
    table.O.resize(static_cast<std::size_t>(3 * t));
    for (int c = 0; c < 3 * t; ++c) table.V[static_cast<std::size_t>(moved(c))] = id(c);
    table.O = out.opposite;
    try {
      check_closed_manifold(table);
    } catch (const Error& e) {
      throw bad_input("invalid connectivity: it decodes to a mesh the coder does not take: {}", e.what());
    }
    const Traversal again = traverse(table);
    for (std::size_t g = 0; g < again.vertex_order.size(); ++g)
      if (again.vertex_order[g] != static_cast<int>(g)) fail("the decoded vertex numbering differs from the visit order");
    for (std::size_t k = 0; k < again.triangle_order.size(); ++k)
      if (again.triangle_order[k] != static_cast<int>(k)) fail("the decoded face order differs from the traversal");
    if (again.code.events != events_) fail("the decoded mesh has other handle events");
    if (!std::equal(again.code.clers.begin(), again.code.clers.end(), decoded_.rbegin(), decoded_.rend()))
      fail("the decoded mesh encodes to another symbol string");
  }
  return out;
}

}  // namespace fest::edgebreaker
