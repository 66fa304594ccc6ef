// Tutte's formula and the exhaustive enumeration of CLERS strings (docs/ebcode.md §6, the
// bijection check): the enumeration never trusts its pruning for the answer, only decode().
#include "edgebreaker/counting.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace fest::edgebreaker {

std::uint64_t tutte_rooted_triangulations(int n) {
  if (n < 0) throw bad_input("number of interior vertices {} is negative", n);
  // 2(4n+1)!/((n+1)!(3n+2)!) = 2 binom(4n+1, n) / ((n+1)(3n+2)); the binomial is built
  // as binom(3n+1+i, i), an integer after every step.
  std::uint64_t binom = 1;
  for (std::uint64_t i = 1; i <= static_cast<std::uint64_t>(n); ++i) {
    std::uint64_t product = 0;
    if (__builtin_mul_overflow(binom, 3 * static_cast<std::uint64_t>(n) + 1 + i, &product))
      throw bad_input("Tutte's count for {} interior vertices does not fit in 64 bits", n);
    binom = product / i;
  }
  std::uint64_t twice = 0;
  if (__builtin_mul_overflow(binom, std::uint64_t{2}, &twice))
    throw bad_input("Tutte's count for {} interior vertices does not fit in 64 bits", n);
  const auto m = static_cast<std::uint64_t>(n);
  return twice / ((m + 1) * (3 * m + 2));
}

namespace {

class Enumerator {
 public:
  Enumerator(int n, const std::function<void(const Clers&)>& visit)
      : cs_(n), others_(n + 1), visit_(visit), reversed_(static_cast<std::size_t>(2 * n + 1)) {}

  std::uint64_t run() {
    extend(0);
    return count_;
  }

 private:
  // Necessary conditions for decode() to finish: only S removes a loop, so the non-C
  // symbols left must cover all but one loop; only C shortens loops, and the loops must
  // end as one 3-loop, so the C's left must cover every edge beyond 3 on every loop
  // (S turns lengths a and b into a+b-1, which keeps that excess plus 2).
  bool can_finish() const {
    int excess = 0;
    for (int l : loops_) excess += l - 3;
    return cs_ >= excess && others_ >= static_cast<int>(loops_.size()) - 1;
  }

  void extend(std::size_t depth) {
    if (depth == reversed_.size()) {
      if (loops_.size() == 1 && loops_[0] == 3) try_string();
      return;
    }
    if (!can_finish()) return;
    for (Symbol s : {Symbol::C, Symbol::L, Symbol::E, Symbol::R, Symbol::S}) {
      const std::vector<int> saved = loops_;
      if (!apply(s)) continue;
      reversed_[depth] = s;
      extend(depth + 1);
      loops_ = saved;
      (s == Symbol::C ? cs_ : others_) += 1;
    }
  }

  // The decoder's preconditions for each inverse operation (decode.cpp).
  bool apply(Symbol s) {
    if (s == Symbol::C) {
      if (cs_ == 0 || loops_.empty() || loops_.back() <= 3) return false;
      --cs_;
      --loops_.back();
      return true;
    }
    if (others_ == 0) return false;
    switch (s) {
      case Symbol::E: loops_.push_back(3); break;
      case Symbol::L:
      case Symbol::R:
        if (loops_.empty()) return false;
        ++loops_.back();
        break;
      case Symbol::S: {
        if (loops_.size() < 2) return false;
        const int merged = loops_[loops_.size() - 1] + loops_[loops_.size() - 2] - 1;
        loops_.pop_back();
        loops_.back() = merged;
        break;
      }
      case Symbol::C: break;
    }
    --others_;
    return true;
  }

  void try_string() {
    Clers forward(reversed_.rbegin(), reversed_.rend());
    try {
      decode(forward);
    } catch (const Error&) {
      return;  // not the encoding of a triangulation
    }
    ++count_;
    if (visit_) visit_(forward);
  }

  int cs_, others_;
  const std::function<void(const Clers&)>& visit_;
  Clers reversed_;
  std::vector<int> loops_;
  std::uint64_t count_ = 0;
};

}  // namespace

std::uint64_t enumerate_clers(int n, const std::function<void(const Clers&)>& visit) {
  if (n < 0) throw bad_input("number of interior vertices {} is negative", n);
  return Enumerator(n, visit).run();
}

}  // namespace fest::edgebreaker
