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
};

// Per-corner ints that grow without push_back's per-element capacity test: storage grows
// in doublings, and a triangle's three corners are written in one step (six push_backs
// per decoded triangle cost 2 % of the decoder's instructions).
class GrowingInts {
 public:
  void reserve(std::size_t n) {
    if (n > cap_) grow(n);
  }
  // Appends `count` (1..3) copies of `value`; returns the index of the first.
  int append(int value, std::size_t count) {
    if (n_ + count > cap_) grow(std::max<std::size_t>(2 * cap_, 64));
    int* p = data_.get() + n_;
    p[0] = value;
    if (count > 1) p[1] = value;
    if (count > 2) p[2] = value;
    const int first = static_cast<int>(n_);
    n_ += count;
    return first;
  }
  std::size_t size() const noexcept { return n_; }
  int& operator[](std::size_t i) noexcept { return data_[i]; }
  int operator[](std::size_t i) const noexcept { return data_[i]; }
  const int* begin() const noexcept { return data_.get(); }
  const int* end() const noexcept { return data_.get() + n_; }

 private:
  void grow(std::size_t cap) {
    std::unique_ptr<int[]> bigger(new int[cap]);
    std::copy(data_.get(), data_.get() + n_, bigger.get());
    data_ = std::move(bigger);
    cap_ = cap;
  }
  std::unique_ptr<int[]> data_;
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
  bool c_possible() const noexcept;

  // Decodes the next symbol (forward index symbols-1, symbols-2, ... 0). Throws bad_input
  // when the symbol is impossible here; never loops or reads out of bounds.
  void step(Symbol s);

  // Closes the start triangles and numbers vertices in G order. With `verify`, the result
  // is re-encoded and must give exactly the same symbols, events and orders, which makes
  // decoding the exact inverse of traverse() on every input it accepts (O(t log t)).
  // Without `opposite` (only the multi-way predictor reads it) and without `verify`, the
  // opposite table is not built: a tenth of the decoder's work.
  DecodedConnectivity finish(bool verify = true, bool opposite = true);

 private:
  struct Loop {
    int gate;
    int length;  // -1 once a handle event made it unknown
  };
  [[noreturn]] void fail(const char* why) const;
  int new_triangle();
  int new_vertex();
  int find(int v);
  void link(int a, int b);
  Loop& top(const char* op);
  int incoming_open_edge(int a);
  void count_triangle(int c);
  void remember_events(int c);
  // Most symbols are no handle event's source: checked inline before the call.
  bool event_here() const noexcept { return next_event_ > 0 && events_[next_event_ - 1].source == position_; }

  void inverse_E();
  void inverse_L();
  void inverse_R();
  void inverse_C();
  void inverse_S();

  bool simple_;
  std::size_t symbols_;
  std::size_t position_;  // forward index of the symbol being decoded
  std::vector<HandleEvent> events_;
  std::size_t next_event_;  // events_[0 .. next_event_) not yet reached (walked backwards)
  std::unordered_map<std::uint32_t, int> pending_;  // split symbol -> corner from its event

  GrowingInts V_, O_;
  std::vector<int> parent_, degree_;  // union-find over provisional vertex ids
  std::vector<int> closed_at_;        // per C, in decode order: the tip corner that closed it
  std::vector<char> closed_;          // per root: closed by a C
  std::vector<Loop> loops_;
  Clers decoded_;  // in decode order, for the verification
  int valence_class_ = 0;
  int previous_ = 0;
  bool last_was_L_ = false;
};

}  // namespace fest::edgebreaker
