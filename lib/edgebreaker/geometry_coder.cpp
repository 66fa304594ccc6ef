// Position coding (docs/ebcode.md §5).
#include "edgebreaker/geometry_coder.hpp"

#include <algorithm>

#include "core/error.hpp"
#include "edgebreaker/range_coder.hpp"
#include "edgebreaker/residual_tokens.hpp"

namespace fest::edgebreaker {
namespace {

constexpr int length_levels = 6;  // bit lengths 0..63 (lossless residuals reach 34 bits)

std::uint64_t zigzag(std::int64_t r) {
  return r >= 0 ? static_cast<std::uint64_t>(r) << 1 : (static_cast<std::uint64_t>(-(r + 1)) << 1) | 1u;
}
std::int64_t unzigzag(std::uint64_t z) {
  return (z & 1u) ? -static_cast<std::int64_t>(z >> 1) - 1 : static_cast<std::int64_t>(z >> 1);
}
int bit_length(std::uint64_t z) { return z == 0 ? 0 : 64 - __builtin_clzll(z); }  // one instruction, not a loop

// ---- .ebm 1.x: the bit length through a 6-level binary tree --------------------------

// Adaptive contexts of the residual coder: the bit length through a binary tree per
// (axis, previous length on that axis), the two bits below the leading one per (axis, length).
struct TreeCoder {
  std::array<std::array<std::array<std::uint16_t, 1 << length_levels>, 16>, 3> length;
  std::array<std::array<std::array<std::uint16_t, 4>, 64>, 3> high;
  std::array<int, 3> previous{};
  explicit TreeCoder(int /*bits*/) {
    for (auto& a : length)
      for (auto& b : a) b.fill(probability_half);
    for (auto& a : high)
      for (auto& b : a) b.fill(probability_half);
  }

  void put(RangeEncoder& enc, int axis, std::int64_t r) {
    const std::uint64_t z = zigzag(r);
    const int k = bit_length(z);
    auto& tree = length[static_cast<std::size_t>(axis)][static_cast<std::size_t>(std::min(previous[static_cast<std::size_t>(axis)], 15))];
    int node = 1;
    for (int level = length_levels - 1; level >= 0; --level) {
      const int b = (k >> level) & 1;
      enc.bit(tree[static_cast<std::size_t>(node)], b);
      node = node * 2 + b;
    }
    previous[static_cast<std::size_t>(axis)] = k;
    if (k <= 1) return;
    // Bits below the leading one: the top two adaptive, the rest bypass.
    auto& h = high[static_cast<std::size_t>(axis)][static_cast<std::size_t>(k)];
    int below = k - 1;
    int hnode = 1;
    for (int step = 0; step < 2 && below > 0; ++step) {
      --below;
      const int b = static_cast<int>((z >> below) & 1u);
      enc.bit(h[static_cast<std::size_t>(hnode)], b);
      hnode = std::min(hnode * 2 + b, 3);
    }
    while (below > 0) {
      const int chunk = std::min(below, 16);
      below -= chunk;
      enc.bypass_bits(static_cast<std::uint32_t>((z >> below) & ((1u << chunk) - 1u)), chunk);
    }
  }

  std::int64_t get(RangeDecoder& dec, int axis) {
    auto& tree = length[static_cast<std::size_t>(axis)][static_cast<std::size_t>(std::min(previous[static_cast<std::size_t>(axis)], 15))];
    int node = 1;
    for (int level = 0; level < length_levels; ++level) node = node * 2 + dec.bit(tree[static_cast<std::size_t>(node)]);
    const int k = node - (1 << length_levels);
    previous[static_cast<std::size_t>(axis)] = k;
    if (k > 40) throw bad_input("geometry: a residual of {} bits", k);
    std::uint64_t z = k == 0 ? 0 : 1;
    if (k > 1) {
      auto& h = high[static_cast<std::size_t>(axis)][static_cast<std::size_t>(k)];
      int below = k - 1;
      int hnode = 1;
      for (int step = 0; step < 2 && below > 0; ++step) {
        --below;
        const int b = dec.bit(h[static_cast<std::size_t>(hnode)]);
        z = (z << 1) | static_cast<std::uint64_t>(b);
        hnode = std::min(hnode * 2 + b, 3);
      }
      while (below > 0) {
        const int chunk = std::min(below, 16);
        below -= chunk;
        z = (z << chunk) | dec.bypass_bits(chunk);
      }
    }
    return unzigzag(z);
  }
};

// ---- .ebm 2.x: the bit length as a signed distance from the previous one -------------

// An adaptive decision that also counts its uses: its first decisions move the
// probability by 1/2, 1/4, ... (about the Krichevsky-Trofimov estimate of a new
// context), from the 16th on by 1/32 as every other context of the format. Small meshes
// spend most of their decisions in contexts that are still new.
struct CountedBit {
  std::uint16_t p = probability_half;
  std::uint16_t n = 0;
};
constexpr std::array<std::uint8_t, 16> counted_shift = {1, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5};

inline void put_counted(RangeEncoder& enc, CountedBit& c, int b) {
  enc.bit_at_rate(c.p, b, counted_shift[c.n]);
  c.n = static_cast<std::uint16_t>(c.n + (c.n < 15 ? 1 : 0));
}
// A context that has settled (15 uses, on a large mesh almost every decision) adapts at
// the fixed rate without looking at the table or counting further. A context that is
// still new gets its shift, and its use counted, from an out-of-line function that does
// not take the range decoder: inlined, GCC made the shift a table load and a select on
// every decision; a call that took the decoder kept its state in memory through the
// whole position loop (17 % of the loop's instructions; docs/ebcode.md §6).
[[gnu::noinline]] int new_context_shift(CountedBit& c) { return counted_shift[c.n++]; }
[[gnu::always_inline]] inline int get_counted(RangeDecoder& dec, CountedBit& c) {
  if (__builtin_expect(c.n == 15, 1)) return dec.bit_at_rate(c.p, adapt_shift);
  return dec.bit_at_rate(c.p, new_context_shift(c));
}
// The same for a bit that is only stored (the two below a residual's leading one, close
// to uniform): the range decoder's mask form, without a branch on the outcome.
[[gnu::always_inline]] inline int get_counted_value(RangeDecoder& dec, CountedBit& c) {
  if (__builtin_expect(c.n == 15, 1)) return dec.bit_value_at_rate(c.p, adapt_shift);
  return dec.bit_value_at_rate(c.p, new_context_shift(c));
}

// The length k of a coordinate's zigzagged residual is coded around m, the length of the
// same axis's previous residual: "k == m?", then the side, then unary steps away from m
// (each step its own context up to 8, truncated at 0 and at the largest length the
// quantisation allows). A smooth surface keeps k within one of m, so most coordinates
// cost two or three decisions where the tree always cost six.
struct DistanceCoder {
  static constexpr int max_length = 33;  // lossless: |r| < 2^32, zigzag < 2^33
  static constexpr int steps = 8;
  struct AxisContexts {
    std::array<CountedBit, max_length + 1> same, above;
    std::array<std::array<CountedBit, steps>, max_length + 1> up, down;
    std::array<std::array<CountedBit, 3>, max_length + 1> high;  // the two bits below the leading one
  };
  std::array<AxisContexts, 3> axes;
  std::array<int, 3> previous{};
  int kmax;
  explicit DistanceCoder(int bits) : kmax(bits == 0 ? max_length : bits) {}

  void put(RangeEncoder& enc, int axis, std::int64_t r) {
    const std::uint64_t z = zigzag(r);
    const int k = bit_length(z);
    AxisContexts& a = axes[static_cast<std::size_t>(axis)];
    const int m = previous[static_cast<std::size_t>(axis)];
    previous[static_cast<std::size_t>(axis)] = k;
    const auto mi = static_cast<std::size_t>(m);
    put_counted(enc, a.same[mi], k != m);
    if (k != m) {
      bool up = k > m;
      if (m > 0 && m < kmax) put_counted(enc, a.above[mi], up);
      if (up)
        for (int j = m + 1; j < kmax; ++j) {
          put_counted(enc, a.up[mi][static_cast<std::size_t>(std::min(j - m - 1, steps - 1))], k > j);
          if (k == j) break;
        }
      else
        for (int j = m - 1; j > 0; --j) {
          put_counted(enc, a.down[mi][static_cast<std::size_t>(std::min(m - 1 - j, steps - 1))], k < j);
          if (k == j) break;
        }
    }
    if (k <= 1) return;
    auto& h = a.high[static_cast<std::size_t>(k)];
    int below = k - 1;
    --below;
    const int b0 = static_cast<int>((z >> below) & 1u);
    put_counted(enc, h[0], b0);
    if (below > 0) {
      --below;
      put_counted(enc, h[static_cast<std::size_t>(1 + b0)], static_cast<int>((z >> below) & 1u));
    }
    while (below > 0) {
      const int chunk = std::min(below, 16);
      below -= chunk;
      enc.bypass_bits(static_cast<std::uint32_t>((z >> below) & ((1u << chunk) - 1u)), chunk);
    }
  }

  // The inverse of put(). The unary steps walk a pointer over the step contexts (the
  // last one repeats), the same decisions as put() makes in the same contexts.
  [[gnu::always_inline]] std::int64_t get(RangeDecoder& dec, int axis) {
    AxisContexts& a = axes[static_cast<std::size_t>(axis)];
    const int m = previous[static_cast<std::size_t>(axis)];
    const auto mi = static_cast<std::size_t>(m);
    int k = m;
    if (get_counted(dec, a.same[mi])) {
      const bool up = m == 0 || (m < kmax && get_counted(dec, a.above[mi]));
      if (up) {
        CountedBit* step = a.up[mi].data();
        CountedBit* const last = step + (steps - 1);
        k = m + 1;
        while (k < kmax && get_counted(dec, *step)) {
          ++k;
          step += step != last;
        }
      } else {
        CountedBit* step = a.down[mi].data();
        CountedBit* const last = step + (steps - 1);
        k = m - 1;
        while (k > 0 && get_counted(dec, *step)) {
          --k;
          step += step != last;
        }
      }
    }
    previous[static_cast<std::size_t>(axis)] = k;
    if (k <= 1) return -k;  // zigzag 0 -> 0, 1 -> -1
    auto& h = a.high[static_cast<std::size_t>(k)];
    int below = k - 2;
    const int b0 = get_counted_value(dec, h[0]);
    std::uint64_t z = 2u | static_cast<std::uint64_t>(b0);
    if (below > 0) {
      --below;
      z = (z << 1) | static_cast<std::uint64_t>(get_counted_value(dec, h[static_cast<std::size_t>(1 + b0)]));
      while (below > 0) {
        const int chunk = std::min(below, 16);
        below -= chunk;
        z = (z << chunk) | dec.bypass_bits(chunk);
      }
    }
    return unzigzag(z);
  }
};

// Value range of one coordinate: [lo, hi]; residuals are wrapped into it when quantised.
struct Domain {
  std::int64_t lo, hi;
  bool wrap;
  explicit Domain(int bits)
      : lo(bits == 0 ? -(std::int64_t{1} << 31) : 0),
        hi(bits == 0 ? (std::int64_t{1} << 31) - 1 : (std::int64_t{1} << bits) - 1),
        wrap(bits != 0) {}
  std::int64_t clamp(std::int64_t v) const { return std::clamp(v, lo, hi); }
  std::int64_t centre() const { return bits_zero() ? 0 : (hi + 1) / 2; }
  bool bits_zero() const { return !wrap; }
  // The range has 2^bits values: reduction modulo its size is a mask in two's complement
  // (the same values as the remainder arithmetic the format describes, without a division).
  std::int64_t wrap_residual(std::int64_t r) const {
    if (!wrap) return r;
    const std::int64_t half = (hi + 1) / 2;
    return ((r + half) & hi) - half;
  }
  std::int64_t unwrap(std::int64_t prediction, std::int64_t r) const {
    if (!wrap) return prediction + r;
    return (prediction + r) & hi;
  }
};

// floor((a + b) / 2) without overflow surprises for the value ranges here.
std::int64_t mean2(std::int64_t a, std::int64_t b) {
  const std::int64_t s = a + b;
  return s >= 0 ? s / 2 : -((-s + 1) / 2);
}

class Prediction {
 public:
  Prediction(const GeometryPlan& plan, const Domain& domain, Predictor predictor)
      : plan_(plan), domain_(domain), predictor_(predictor) {
    if (predictor_ == Predictor::multi) {
      if (!plan.triangles || !plan.opposite) throw bad_input("geometry: the multi-way predictor needs connectivity");
      // Corners per vertex (CSR), for the triangles around the vertex being predicted.
      const auto& tris = *plan.triangles;
      start_.assign(plan.unusable.size() + 1, 0);
      for (const auto& t : tris)
        for (int v : t) ++start_[static_cast<std::size_t>(v) + 1];
      for (std::size_t v = 0; v + 1 < start_.size(); ++v) start_[v + 1] += start_[v];
      corners_.resize(3 * tris.size());
      std::vector<int> fill(start_.begin(), start_.end() - 1);
      for (std::size_t f = 0; f < tris.size(); ++f)
        for (int j = 0; j < 3; ++j)
          corners_[static_cast<std::size_t>(fill[static_cast<std::size_t>(tris[f][static_cast<std::size_t>(j)])]++)] =
              static_cast<int>(3 * f) + j;
    }
  }
  QPoint operator()(const std::vector<QPoint>& q, int g, const QPoint& previous) const {
    if (predictor_ == Predictor::none) return {0, 0, 0};
    if (predictor_ == Predictor::delta) return previous;
    if (predictor_ == Predictor::multi) {
      // Cohen-Or / Isenburg-style: the mean of every parallelogram around g whose three
      // other vertices are already decoded (earlier in G, not dummies).
      const auto& tris = *plan_.triangles;
      const auto known = [&](int v) { return v < g && !plan_.unusable[static_cast<std::size_t>(v)]; };
      std::array<std::int64_t, 3> sum{0, 0, 0};
      std::int64_t count = 0;
      for (int k = start_[static_cast<std::size_t>(g)]; k < start_[static_cast<std::size_t>(g) + 1]; ++k) {
        const int c = corners_[static_cast<std::size_t>(k)];
        const int n = c - c % 3 + (c + 1) % 3, p = c - c % 3 + (c + 2) % 3;
        const int y = tris[static_cast<std::size_t>(n / 3)][static_cast<std::size_t>(n % 3)];
        const int z = tris[static_cast<std::size_t>(p / 3)][static_cast<std::size_t>(p % 3)];
        const int oc = (*plan_.opposite)[static_cast<std::size_t>(c)];
        const int o = tris[static_cast<std::size_t>(oc / 3)][static_cast<std::size_t>(oc % 3)];
        if (!known(y) || !known(z) || !known(o)) continue;
        for (std::size_t a = 0; a < 3; ++a)
          sum[a] += q[static_cast<std::size_t>(y)][a] + q[static_cast<std::size_t>(z)][a] - q[static_cast<std::size_t>(o)][a];
        ++count;
      }
      if (count > 0) {
        QPoint out{};
        for (std::size_t a = 0; a < 3; ++a) {
          const std::int64_t m = sum[a] >= 0 ? sum[a] / count : -((-sum[a] + count - 1) / count);  // floor
          out[a] = domain_.clamp(m);
        }
        return out;
      }
    }
    const auto& pg = plan_.parallelogram[static_cast<std::size_t>(g)];
    if (pg[0] < 0) return previous;  // a start vertex
    const bool a = usable(pg[0]), b = usable(pg[1]), o = usable(pg[2]);
    QPoint out{};
    for (std::size_t k = 0; k < 3; ++k) {
      if (a && b && o)
        out[k] = domain_.clamp(q[static_cast<std::size_t>(pg[0])][k] + q[static_cast<std::size_t>(pg[1])][k] -
                               q[static_cast<std::size_t>(pg[2])][k]);
      else if (a && b)
        out[k] = mean2(q[static_cast<std::size_t>(pg[0])][k], q[static_cast<std::size_t>(pg[1])][k]);
      else if (a || b)
        out[k] = q[static_cast<std::size_t>(a ? pg[0] : pg[1])][k];
      else
        out[k] = previous[k];
    }
    return out;
  }

 private:
  bool usable(int v) const { return !plan_.unusable[static_cast<std::size_t>(v)]; }
  const GeometryPlan& plan_;
  const Domain& domain_;
  Predictor predictor_;
  std::vector<int> start_, corners_;  // multi: corners of each vertex
};

}  // namespace

namespace {

// The prediction of G vertex g: the parallelogram of its C triangle inline (almost every
// vertex), everything else through Prediction.
[[gnu::always_inline]] inline QPoint predict_at(const Prediction& predict, const GeometryPlan& plan, const Domain& domain, bool fast,
                         const std::vector<QPoint>& q, std::size_t g, const QPoint& previous) {
  if (fast) {
    const auto& pg = plan.parallelogram[g];
    if (pg[0] >= 0 && !plan.unusable[static_cast<std::size_t>(pg[0])] && !plan.unusable[static_cast<std::size_t>(pg[1])] &&
        !plan.unusable[static_cast<std::size_t>(pg[2])]) {
      const QPoint& a = q[static_cast<std::size_t>(pg[0])];
      const QPoint& b = q[static_cast<std::size_t>(pg[1])];
      const QPoint& o = q[static_cast<std::size_t>(pg[2])];
      return {domain.clamp(a[0] + b[0] - o[0]), domain.clamp(a[1] + b[1] - o[1]), domain.clamp(a[2] + b[2] - o[2])};
    }
  }
  return predict(q, static_cast<int>(g), previous);
}

template <class Coder>
std::string encode_with(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits, Predictor predictor) {
  const Domain domain(bits);
  const Prediction predict(plan, domain, predictor);
  const bool fast = predictor == Predictor::parallelogram;
  RangeEncoder enc;
  Coder coder(bits);
  QPoint previous{domain.centre(), domain.centre(), domain.centre()};
  for (std::size_t g = 0; g < q.size(); ++g) {
    if (plan.unusable[g]) continue;
    if (plan.same_as[g] < 0) {
      const QPoint p = predict_at(predict, plan, domain, fast, q, g, previous);
      for (int k = 0; k < 3; ++k)
        coder.put(enc, k, domain.wrap_residual(q[g][static_cast<std::size_t>(k)] - p[static_cast<std::size_t>(k)]));
    }
    previous = q[g];
  }
  return enc.finish();
}

// Quantised coordinates (wrap) come out of the mask in [0, 2^bits - 1] already; only
// lossless ones are range-checked.
template <class Coder, bool wrap>
std::vector<QPoint> decode_loop(std::string_view bytes, const GeometryPlan& plan, int bits, Predictor predictor) {
  const Domain domain(bits);
  const Prediction predict(plan, domain, predictor);
  const bool fast = predictor == Predictor::parallelogram;
  RangeDecoder dec(bytes);
  Coder coder(bits);
  std::vector<QPoint> q(plan.unusable.size(), QPoint{0, 0, 0});
  const QPoint centre{domain.centre(), domain.centre(), domain.centre()};
  const QPoint* previous = &centre;  // the last decoded vertex (q does not move)
  for (std::size_t g = 0; g < q.size(); ++g) {
    if (plan.unusable[g]) continue;
    const int same = plan.same_as[g];
    if (same >= 0) {
      if (static_cast<std::size_t>(same) >= g) throw bad_input("geometry: a stitch partner comes later");
      q[g] = q[static_cast<std::size_t>(same)];
    } else {
      const QPoint p = predict_at(predict, plan, domain, fast, q, g, *previous);
      // The three axes written out, so that each one's contexts sit at a fixed place.
      const auto coordinate = [&](std::size_t k, std::int64_t r) {
        std::int64_t v;
        if constexpr (wrap) {
          v = (p[k] + r) & domain.hi;
        } else {
          v = p[k] + r;
          if (v < domain.lo || v > domain.hi) throw bad_input("geometry: a coordinate outside the quantisation range");
        }
        q[g][k] = v;
      };
      coordinate(0, coder.get(dec, 0));
      coordinate(1, coder.get(dec, 1));
      coordinate(2, coder.get(dec, 2));
      if (dec.overrun() > 12) throw bad_input("geometry section is truncated");
    }
    previous = &q[g];
  }
  if (dec.truncated()) throw bad_input("geometry section is truncated");
  return q;
}

template <class Coder>
std::vector<QPoint> decode_with(std::string_view bytes, const GeometryPlan& plan, int bits, Predictor predictor) {
  return bits != 0 ? decode_loop<Coder, true>(bytes, plan, bits, predictor) : decode_loop<Coder, false>(bytes, plan, bits, predictor);
}

// GEOM version 3: the residuals of encode_with's loop, collected for the two passes of
// the token coder.
std::optional<std::string> encode_tokens(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits, Predictor predictor) {
  const Domain domain(bits);
  const Prediction predict(plan, domain, predictor);
  const bool fast = predictor == Predictor::parallelogram;
  std::vector<std::int64_t> residuals;
  residuals.reserve(3 * q.size());
  QPoint previous{domain.centre(), domain.centre(), domain.centre()};
  for (std::size_t g = 0; g < q.size(); ++g) {
    if (plan.unusable[g]) continue;
    if (plan.same_as[g] < 0) {
      const QPoint p = predict_at(predict, plan, domain, fast, q, g, previous);
      for (std::size_t k = 0; k < 3; ++k) residuals.push_back(domain.wrap_residual(q[g][k] - p[k]));
    }
    previous = q[g];
  }
  return encode_residual_tokens(residuals, bits);
}

// decode_loop for GEOM version 3 (quantised only, so always wrapped): the token reader's
// state is a local copy (ResidualTokenReader), and nothing in the loop branches on the
// data but the predictor's choice of parallelogram.
std::vector<QPoint> decode_tokens(std::string_view bytes, const GeometryPlan& plan, int bits, Predictor predictor) {
  const Domain domain(bits);
  const Prediction predict(plan, domain, predictor);
  const bool fast = predictor == Predictor::parallelogram;
  const ResidualTokenDecoder decoder(bytes, bits);
  ResidualTokenReader in = decoder.reader();
  const std::int64_t mask = domain.hi;
  std::vector<QPoint> q(plan.unusable.size(), QPoint{0, 0, 0});
  const QPoint centre{domain.centre(), domain.centre(), domain.centre()};
  const QPoint* previous = &centre;  // the last decoded vertex (q does not move)
  for (std::size_t g = 0; g < q.size(); ++g) {
    if (plan.unusable[g]) continue;
    const int same = plan.same_as[g];
    if (same >= 0) {
      if (static_cast<std::size_t>(same) >= g) throw bad_input("geometry: a stitch partner comes later");
      q[g] = q[static_cast<std::size_t>(same)];
    } else {
      const QPoint p = predict_at(predict, plan, domain, fast, q, g, *previous);
      const std::int64_t r0 = in.get(0), r1 = in.get(1), r2 = in.get(2);
      q[g] = {(p[0] + r0) & mask, (p[1] + r1) & mask, (p[2] + r2) & mask};
    }
    previous = &q[g];
  }
  if (!in.complete()) throw bad_input("GEOM section: the residual streams do not end with the positions");
  return q;
}

}  // namespace

std::optional<std::string> encode_position_tokens(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits,
                                                  Predictor predictor) {
  if (bits < 1 || bits > 30) return std::nullopt;
  return encode_tokens(q, plan, bits, predictor);
}

std::string encode_positions(const std::vector<QPoint>& q, const GeometryPlan& plan, int bits, Predictor predictor,
                             ResidualCoding coding) {
  if (coding == ResidualCoding::tokens_v3) {
    auto tokens = encode_position_tokens(q, plan, bits, predictor);
    if (!tokens) throw runtime_failure("internal: GEOM version 3 cannot code these positions");
    return std::move(*tokens);
  }
  return coding == ResidualCoding::tree_v1 ? encode_with<TreeCoder>(q, plan, bits, predictor)
                                           : encode_with<DistanceCoder>(q, plan, bits, predictor);
}

std::vector<QPoint> decode_positions(std::string_view bytes, const GeometryPlan& plan, int bits, Predictor predictor,
                                     ResidualCoding coding) {
  if (coding == ResidualCoding::tokens_v3) {
    if (bits < 1 || bits > 30) throw bad_input("GEOM version 3 needs 1..30 quantisation bits, not {}", bits);
    return decode_tokens(bytes, plan, bits, predictor);
  }
  return coding == ResidualCoding::tree_v1 ? decode_with<TreeCoder>(bytes, plan, bits, predictor)
                                           : decode_with<DistanceCoder>(bytes, plan, bits, predictor);
}

std::string encode_point_list(const std::vector<QPoint>& q, int bits, ResidualCoding coding) {
  GeometryPlan plan;
  plan.parallelogram.assign(q.size(), {-1, -1, -1});
  plan.unusable.assign(q.size(), 0);
  plan.same_as.assign(q.size(), -1);
  return encode_positions(q, plan, bits, Predictor::delta, coding);
}

std::vector<QPoint> decode_point_list(std::string_view bytes, std::size_t count, int bits, ResidualCoding coding) {
  GeometryPlan plan;
  plan.parallelogram.assign(count, {-1, -1, -1});
  plan.unusable.assign(count, 0);
  plan.same_as.assign(count, -1);
  return decode_positions(bytes, plan, bits, Predictor::delta, coding);
}

}  // namespace fest::edgebreaker
