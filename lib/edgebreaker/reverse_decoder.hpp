#pragma once
// Spirale Reversi for general closed meshes (docs/ebcode.md §2, with §5's handle events and
// several components), one symbol at a time, so that an entropy decoder can ask for the
// context of the next symbol (valence, previous symbol, whether C is possible) before it
// decodes it. The encoder runs the same class over its own symbols to get the same
// contexts: encoder and decoder cannot drift apart.

#include <algorithm>
#include <array>
#include <memory>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "edgebreaker/traversal.hpp"

namespace fest::edgebreaker {

struct DecodedConnectivity {
  // Output face order (traversal.hpp): per component its start triangle, then one triangle
  // per symbol; vertex ids are G ids (0 .. vertex_count-1).
  std::vector<Triangle> triangles;
  int vertex_count = 0;
  int components = 0;
  // Per G vertex: the vertices (a, b, o) of its parallelogram -- the C triangle's gate
  // (a, b) and the vertex o across it, all earlier in G -- or {-1,-1,-1} for a component's
  // start vertices.
  std::vector<std::array<int, 3>> parallelogram;
  // Per corner of `triangles` (3k + j): the opposite corner, for the multi-way predictor;
  // empty when finish() was told it is not needed.
  std::vector<int> opposite;
  // Per G vertex: its corners (triangles around it), from the decoder's counts; empty
  // unless finish() was asked (the hole flags' contexts need it).
  std::vector<int> valence;
};

// Plain values that grow without push_back's per-element capacity test: storage grows in
// doublings, and a triangle's three corners are made in one step (six push_backs per
// decoded triangle cost 2 % of the decoder's instructions).
template <class T>
class Growing {
 public:
  void reserve(std::size_t n) {
    if (n > cap_) grow(n);
  }
  // Makes room for `count` more values and returns the index of the first; the caller
  // writes them (through data()).
  std::size_t extend(std::size_t count) {
    if (n_ + count > cap_) grow_for(count);
    const std::size_t first = n_;
    n_ += count;
    return first;
  }
  // The same for two arrays that are always reserved and extended together, so that their
  // sizes and capacities are equal (the decoder's V and O): one capacity test for both.
  static std::size_t extend_pair(Growing& a, Growing& b, std::size_t count) {
    if (a.n_ + count > a.cap_) {
      a.grow_for(count);
      b.grow_for(count);
    }
    const std::size_t first = a.n_;
    a.n_ += count;
    b.n_ += count;
    return first;
  }
  std::size_t size() const noexcept { return n_; }
  T* data() noexcept { return data_.get(); }
  const T* data() const noexcept { return data_.get(); }
  T& operator[](std::size_t i) noexcept { return data_[i]; }
  const T& operator[](std::size_t i) const noexcept { return data_[i]; }
  const T* begin() const noexcept { return data_.get(); }
  const T* end() const noexcept { return data_.get() + n_; }

 private:
  [[gnu::noinline, gnu::cold]] void grow_for(std::size_t count) {
    grow(std::max<std::size_t>(2 * cap_, std::max<std::size_t>(n_ + count, 64)));
  }
  void grow(std::size_t cap) {
    std::unique_ptr<T[]> bigger(new T[cap]);
    std::copy(data_.get(), data_.get() + n_, bigger.get());
    data_ = std::move(bigger);
    cap_ = cap;
  }
  std::unique_ptr<T[]> data_;
  std::size_t n_ = 0, cap_ = 0;
};

class ReverseDecoder {
 public:
  // `symbols` is the total number of symbols that step() will be given; `events` sorted by
  // source (as traverse() emits them). With `simple`, C on a 3-loop is rejected (simple
  // triangulations, the chapter's setting); otherwise it is allowed, since meshes cut from
  // non-manifold input may have multi-edges. Throws bad_input for counts beyond what fits.
  ReverseDecoder(std::size_t symbols, std::vector<HandleEvent> events, bool simple = false);

  // Context of the next symbol: valence class 0..5 of the last triangle's left vertex
  // (docs/ebcode.md §4), the previous decoded symbol (0 none, else 1 + Symbol), and whether C is
  // possible (the current loop is longer than 3 and the previous symbol is not L).
  int valence_class() const noexcept { return valence_class_; }
  int previous() const noexcept { return previous_; }
  bool c_possible() const noexcept {
    if (loops_.empty() || last_was_L_) return false;
    const int length = loops_.back().length;
    return length == -1 || length > 3;
  }

  // Whether step() keeps the decoded symbols for finish(verify = true) (the default). A
  // decoder that will not verify is told so, and saves storing them.
  void keep_symbols(bool keep) noexcept { keep_symbols_ = keep; }

  // Storage for `symbols` symbols at once (the constructor reserves for at most 2^16, so
  // that a lying count costs nothing): for a caller that has bounded the count by the
  // bytes it holds. Growing by doubling copied each array about once.
  void reserve(std::size_t symbols);

  // Decodes the next symbol (forward index symbols-1, symbols-2, ... 0). Throws bad_input
  // when the symbol is impossible here; never loops or reads out of bounds. Defined in
  // reverse_decoder_steps.hpp, which a caller includes.
  [[gnu::always_inline]] inline void step(Symbol s);

  // Closes the start triangles and numbers vertices in G order. With `verify`, the result
  // is re-encoded and must give exactly the same symbols, events and orders, which makes
  // decoding the exact inverse of traverse() on every input it accepts (O(t log t)).
  // Without `opposite` (only the multi-way predictor reads it) and without `verify`, the
  // opposite table is not built: a tenth of the decoder's work.
  // With `valence`, DecodedConnectivity::valence is filled in.
  DecodedConnectivity finish(bool verify = true, bool opposite = true, bool valence = false);

 private:
  struct Loop {
    // On the stack, always the first corner of the triangle that made or last extended
    // the loop, a multiple of 3: its next and previous corners are gate + 1 and gate + 2.
    int gate;
    int length;  // -1 once a handle event made it unknown
  };
  // A provisional vertex: union-find parent, and at a root the decoded triangles around
  // the set (the valence context) and whether a C has closed it.
  struct Vertex {
    int parent;
    int degree;
    int closed;
  };
  [[noreturn, gnu::cold]] void fail(const char* why) const;
  // The inner operations, inlined into step() (each was a call of its own).
  [[gnu::always_inline]] inline int new_triangle();
  [[gnu::always_inline]] inline int new_vertex(int degree);
  [[gnu::always_inline]] inline int find(int v);
  [[gnu::always_inline]] inline int root_at(int corner);
  [[gnu::always_inline]] inline void link(int a, int b);
  [[gnu::always_inline]] inline void link_fresh(int fresh, int old);
  [[gnu::always_inline]] inline Loop& top(const char* op);
  [[gnu::always_inline]] inline int incoming_open_edge(int a);
  [[gnu::always_inline]] inline int swing_to_open(int a, int j);
  [[gnu::always_inline]] inline void set_valence(int left_degree);
  void remember_events(int c);
  // Most symbols are no handle event's source: checked inline before the call.
  bool event_here() const noexcept { return position_ == next_event_source_; }

  [[gnu::always_inline]] inline void inverse_E();
  [[gnu::always_inline]] inline void inverse_L();
  [[gnu::always_inline]] inline void inverse_R();
  [[gnu::always_inline]] inline void inverse_C();
  void inverse_S();

  bool simple_;
  std::size_t symbols_;
  std::size_t position_;  // forward index of the symbol being decoded
  std::vector<HandleEvent> events_;
  std::size_t next_event_;  // events_[0 .. next_event_) not yet reached (walked backwards)
  std::size_t next_event_source_;  // events_[next_event_ - 1].source, or -1 when none is left
  std::unordered_map<std::uint32_t, int> pending_;  // split symbol -> corner from its event

  Growing<int> V_, O_;          // corners, three per triangle; O_ is -1 while open; always reserved and extended together (extend_pair)
  std::size_t links_ = 0;       // link() calls: each closes two open corners
  Growing<Vertex> vertices_;    // provisional vertex ids
  std::vector<int> closed_at_;  // per C, in decode order: the tip corner that closed it
  std::vector<Loop> loops_;
  Clers decoded_;  // in decode order, for the verification
  bool keep_symbols_ = true;
  int valence_class_ = 0;
  int previous_ = 0;
  bool last_was_L_ = false;
};

}  // namespace fest::edgebreaker
