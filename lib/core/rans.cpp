#include "core/rans.hpp"

#include <algorithm>
#include <cmath>

namespace fest::range_coding {

namespace {

int bit_width(std::uint32_t v) noexcept { return v == 0 ? 0 : 32 - __builtin_clz(v); }

// A frequency as written: its bit length (1..12) and up to three bits below the leading
// one; the bits further down are zero.
std::uint32_t representable(std::uint32_t f, std::uint32_t total) noexcept {
  const int n = bit_width(f);
  if (n <= 4) return f;
  const int drop = n - 4;
  std::uint32_t r = ((f + (1u << (drop - 1))) >> drop) << drop;  // to nearest
  return std::min<std::uint32_t>(r, total);
}

// Elias gamma of v >= 1: the bit length minus one in unary (ones, then a zero), then the
// bits below the leading one.
void put_gamma(BitWriter& w, std::uint32_t v) {
  const int n = bit_width(v) - 1;
  for (int k = 0; k < n; ++k) w.put(1, 1);
  w.put(0, 1);
  w.put(v, n);
}

bool get_gamma(BitReader& r, std::uint32_t& v) {
  // The unary part: the ones before the first zero (at most 12: nothing written here is
  // longer), counted in one peek.
  const int n = __builtin_ctzll(~r.peek(13));
  if (n > 12) return false;
  (void)r.get(n + 1);
  v = (1u << n) | static_cast<std::uint32_t>(r.get(n));
  return !r.overrun();
}

}  // namespace

bool normalise_table(const std::uint32_t* counts, int alphabet, RansTable& out, int bits) {
  out.freq.fill(0);
  out.cum.fill(0);
  out.implied = 0;
  const std::uint32_t scale = 1u << bits;
  std::uint64_t total = 0;
  int used = 0, largest = -1;
  for (int s = 0; s < alphabet; ++s) {
    total += counts[s];
    if (counts[s]) {
      ++used;
      if (largest < 0 || counts[s] > counts[largest]) largest = s;
    }
  }
  if (used == 0) return true;  // an empty table: nothing is coded with it
  std::uint32_t sum = 0;
  for (int s = 0; s < alphabet; ++s) {
    if (!counts[s] || s == largest) continue;
    const double exact = static_cast<double>(counts[s]) * scale / static_cast<double>(total);
    const auto f = representable(std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::lround(exact))), scale);
    out.freq[static_cast<std::size_t>(s)] = static_cast<std::uint16_t>(f);
    sum += f;
  }
  if (sum >= scale) return false;
  out.freq[static_cast<std::size_t>(largest)] = static_cast<std::uint16_t>(scale - sum);
  out.implied = largest;
  std::uint32_t cum = 0;
  for (int s = 0; s < alphabet; ++s) {
    out.cum[static_cast<std::size_t>(s)] = static_cast<std::uint16_t>(cum);
    cum += out.freq[static_cast<std::size_t>(s)];
  }
  return true;
}

void write_tables(BitWriter& w, const std::vector<RansTable>& tables, const std::vector<int>& alphabets) {
  for (std::size_t t = 0; t < tables.size(); ++t) {
    const RansTable& tab = tables[t];
    std::vector<int> used;
    for (int s = 0; s < alphabets[t]; ++s)
      if (tab.freq[static_cast<std::size_t>(s)]) used.push_back(s);
    put_gamma(w, static_cast<std::uint32_t>(used.size()) + 1);
    if (used.empty()) continue;
    int prev = -1;
    for (int s : used) {
      put_gamma(w, static_cast<std::uint32_t>(s - prev));
      prev = s;
    }
    if (used.size() == 1) continue;
    const auto implied = static_cast<std::size_t>(std::find(used.begin(), used.end(), tab.implied) - used.begin());
    put_gamma(w, static_cast<std::uint32_t>(implied) + 1);
    for (std::size_t i = 0; i < used.size(); ++i) {
      if (i == implied) continue;
      const std::uint32_t f = tab.freq[static_cast<std::size_t>(used[i])];
      const int n = bit_width(f);
      const int kept = std::min(n - 1, 3);
      w.put(static_cast<std::uint32_t>(n - 1), 4);
      w.put(f >> (n - 1 - kept), kept);
    }
  }
}

bool read_tables(BitReader& r, std::vector<RansTable>& tables, const std::vector<int>& alphabets, int bits) {
  const std::uint32_t scale = 1u << bits;
  tables.resize(alphabets.size());
  for (std::size_t t = 0; t < tables.size(); ++t) {
    RansTable& tab = tables[t];
    const auto alphabet = static_cast<std::size_t>(alphabets[t]);
    std::fill_n(tab.freq.begin(), alphabet, std::uint16_t{0});
    std::fill_n(tab.cum.begin(), alphabet, std::uint16_t{0});
    tab.implied = 0;
    std::uint32_t count = 0;
    if (!get_gamma(r, count)) return false;
    const std::uint32_t n = count - 1;
    if (n == 0) continue;
    if (n > static_cast<std::uint32_t>(alphabets[t])) return false;
    std::array<int, kRansAlphabet> used;
    int prev = -1;
    for (std::uint32_t i = 0; i < n; ++i) {
      int& s = used[i];
      std::uint32_t gap = 0;
      if (!get_gamma(r, gap)) return false;
      s = prev + static_cast<int>(gap);
      if (s >= alphabets[t]) return false;
      prev = s;
    }
    std::uint32_t implied = 0;
    if (n > 1) {
      if (!get_gamma(r, implied)) return false;
      implied -= 1;
      if (implied >= n) return false;
    }
    std::uint32_t sum = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      if (i == implied) continue;
      const int len = static_cast<int>(r.get(4)) + 1;  // 1..16
      if (len > bits) return false;  // below the implied one's share: < 2^bits
      const int kept = std::min(len - 1, 3);
      const std::uint32_t top = static_cast<std::uint32_t>(r.get(kept)) | (1u << kept);
      const std::uint32_t f = top << (len - 1 - kept);
      sum += f;
      if (sum >= scale) return false;
      tab.freq[static_cast<std::size_t>(used[i])] = static_cast<std::uint16_t>(f);
    }
    tab.freq[static_cast<std::size_t>(used[implied])] = static_cast<std::uint16_t>(scale - sum);
    tab.implied = used[implied];
    std::uint32_t cum = 0;
    for (int s = 0; s < alphabets[t]; ++s) {
      tab.cum[static_cast<std::size_t>(s)] = static_cast<std::uint16_t>(cum);
      cum += tab.freq[static_cast<std::size_t>(s)];
    }
  }
  return !r.overrun();
}

void fill_decode_table(const RansTable& t, int alphabet, RansEntry* out) {
  for (int s = 0; s < alphabet; ++s) {
    const std::uint32_t f = t.freq[static_cast<std::size_t>(s)], c = t.cum[static_cast<std::size_t>(s)];
    const RansEntry base = static_cast<RansEntry>(s) | (f << 7);
    for (std::uint32_t k = 0; k < f; ++k) out[c + k] = base | (k << 19);
  }
}

const RansEntry* identity_decode_table(int bits) {
  // One table per precision, 2^bits entries from offset 2^bits (4094 entries in all).
  static const std::array<RansEntry, 2 * kRansTotal> tables = [] {
    std::array<RansEntry, 2 * kRansTotal> t{};
    for (int b = 0; b <= kRansBits; ++b)
      for (std::uint32_t k = 0; k < (1u << b); ++k) t[(1u << b) + k] = ((1u << b) << 7) | (k << 19);
    return t;
  }();
  return tables.data() + (std::size_t{1} << std::clamp(bits, 0, kRansBits));
}

}  // namespace fest::range_coding
