#pragma once
// exp(-y) for y >= 0, inline, for the per-sample opacity alpha = 1 - exp(-tau len)
// (docs/volrender.md "Acceleration"): a call to libm's exp made the caster spill every
// live register around each shaded sample. The standard table method: y = (k/64) ln 2 + r
// with |r| <= ln 2 / 128, exp(-y) = 2^(k/64) exp(-r), exp(-r) by its Taylor polynomial to
// r^5 (truncation r^6/720 < 4e-17), 2^(j/64) from a 64-entry table. Within 2 ulp of
// std::exp (tests/unit/test_raycast_exp_neg.cpp); 0 where exp(-y) < 2^-1022 (y > 708),
// where 1 - exp(-y) rounds to 1 either way.

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace fest::raycast {

namespace exp_neg_detail {
struct Table {
  std::array<double, 64> v;
  Table() {
    for (int j = 0; j < 64; ++j) v[j] = std::exp2(j / 64.0);
  }
};
inline const Table table;
}  // namespace exp_neg_detail

inline double exp_neg(double y) {
  if (!(y <= 708.0)) return y > 708.0 ? 0.0 : y;  // NaN stays NaN
  const double x = -y;
  // k = round(x 64 / ln 2) through the 1.5 * 2^52 shifter (round to nearest, |k| < 2^17)
  constexpr double kShift = 6755399441055744.0, kInvStep = 92.33248261689366;  // 64 / ln 2
  // ln 2 / 64 in two parts, the first with 32 trailing zero bits (k * hi is exact)
  constexpr double kStepHi = 0.01083042469326756, kStepLo = 2.9815858269852933e-12;
  const double kd = x * kInvStep + kShift;
  std::uint64_t kbits;
  std::memcpy(&kbits, &kd, sizeof kd);
  const auto k = static_cast<std::int32_t>(static_cast<std::uint32_t>(kbits));  // low 32 bits: k
  const double kf = kd - kShift;
  const double r = (x - kf * kStepHi) - kf * kStepLo;
  const double p = 1 + r * (1 + r * (0.5 + r * (1.0 / 6 + r * (1.0 / 24 + r * (1.0 / 120)))));
  const std::int32_t m = k >> 6;  // floor(k / 64), arithmetic shift; >= -1022 for y <= 708
  const std::uint64_t scale_bits = static_cast<std::uint64_t>(m + 1023) << 52;
  double scale;
  std::memcpy(&scale, &scale_bits, sizeof scale);
  return exp_neg_detail::table.v[static_cast<std::size_t>(k & 63)] * p * scale;
}

}  // namespace fest::raycast
