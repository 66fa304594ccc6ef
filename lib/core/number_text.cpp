#include "core/number_text.hpp"

#include <cmath>
#include <cstring>

namespace fest {

namespace {

__extension__ typedef unsigned __int128 u128;  // GCC and Clang; -Wpedantic needs the marker

constexpr std::uint64_t kTen16 = 10000000000000000ull;  // 10^16: the smallest 17-digit integer
constexpr std::uint64_t kTen17 = 100000000000000000ull;

// 5^p for p = 0..32 (5^32 < 2^75, so a 53-bit significand times it fits in 128 bits).
struct Powers5 {
  u128 v[33];
  constexpr Powers5() : v() {
    v[0] = 1;
    for (int p = 1; p < 33; ++p) v[p] = v[p - 1] * 5;
  }
};
constexpr Powers5 kPow5;

// N = round-half-even(|x| * 10^p) for x = m 2^e, exactly, in 128-bit integers:
// |x| 10^p = m 5^p 2^(p + e). Needs 0 <= p <= 32.
std::uint64_t scaled(std::uint64_t m, int e, int p) {
  const u128 a = static_cast<u128>(m) * kPow5.v[p];
  const int s = p + e;
  if (s >= 0) return static_cast<std::uint64_t>(a << s);  // callers keep the result below 10^18
  const int r = -s;
  if (r >= 128) return 0;
  const u128 q = a >> r;
  const u128 rem = a - (q << r);
  const u128 half = static_cast<u128>(1) << (r - 1);
  const bool up = rem > half || (rem == half && (q & 1) != 0);
  return static_cast<std::uint64_t>(q) + (up ? 1 : 0);
}

constexpr char kPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// 10^j for j = -16..17 as the nearest doubles (exact for j >= 0).
constexpr double kPow10[] = {1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5,
                             1e-4,  1e-3,  1e-2,  1e-1,  1e0,   1e1,   1e2,   1e3,  1e4,  1e5,  1e6,  1e7,
                             1e8,   1e9,   1e10,  1e11,  1e12,  1e13,  1e14,  1e15, 1e16, 1e17};

void write4(char* d, std::uint32_t v) {
  std::memcpy(d, kPairs + 2 * (v / 100), 2);
  std::memcpy(d + 2, kPairs + 2 * (v % 100), 2);
}

void write8(char* d, std::uint32_t v) {
  write4(d, v / 10000);
  write4(d + 4, v % 10000);
}

}  // namespace

char* write_g17(char* out, double x) noexcept {
  // The fast exact path: finite numbers with 1e-15 <= |x| < 1e16, the range where
  // |x| 10^(16 - k) and |x| 10^(17 - k) fit 128-bit arithmetic. Everything else (zero,
  // subnormals, huge, non-finite) takes the library's printf-exact formatter.
  const double ax = std::fabs(x);
  if (!(ax >= 1e-15 && ax < 1e16)) {
    return std::to_chars(out, out + 32, x, std::chars_format::general, 17).ptr;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const std::uint64_t m = (bits & ((1ull << 52) - 1)) | (1ull << 52);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1075;
  // k = floor(log10 |x|), the decimal exponent, first estimated from the binary one
  // (floor(e2 log10 2) with 78913 / 2^18 ~ log10 2): the estimate is k or k - 1, and
  // the 17-digit integer n tells which.
  const int e2 = e + 52;
  int k = e2 >= 0 ? (e2 * 78913) >> 18 : -((-e2 * 78913 + (1 << 18) - 1) >> 18);
  if (k > 15) k = 15;
  if (k < -15) k = -15;
  // One comparison with the next power of ten settles the estimate (a third of the
  // numbers would otherwise take a second `scaled`); near a power of ten below 1, where
  // the double is not the power itself, the checks on n below still correct it.
  if (ax >= kPow10[k + 1 + 16]) ++k;
  std::uint64_t n = scaled(m, e, 16 - k);
  if (n >= kTen17) {
    ++k;
    n = scaled(m, e, 16 - k);
  } else if (n < kTen16) {
    --k;
    n = scaled(m, e, 16 - k);
  }
  if (n == kTen16 && k <= -16) return std::to_chars(out, out + 32, x, std::chars_format::general, 17).ptr;
  if (n == kTen16) {  // 10^16 exactly, or a value below it rounded up: one digit more tells
    const std::uint64_t finer = scaled(m, e, 17 - k);
    if (finer < kTen17) {
      --k;
      n = finer;
    }
  }
  if (n < kTen16 || n > kTen17) return std::to_chars(out, out + 32, x, std::chars_format::general, 17).ptr;
  if (n == kTen17) {  // rounded up to the next power of ten
    n = kTen16;
    ++k;
  }
  // The 17 digits: the leading one, then two groups of eight in 32-bit arithmetic, two
  // digits at a time from a table of pairs. Past them the buffer holds '0's, so that the
  // copies below can have fixed sizes (inlined moves instead of memcpy calls; they may
  // write past the end they return, never past out + 32).
  char digits[40];
  std::memset(digits + 16, '0', 24);
  digits[0] = static_cast<char>('0' + n / kTen16);
  const std::uint64_t rest = n % kTen16;
  write8(digits + 1, static_cast<std::uint32_t>(rest / 100000000u));
  write8(digits + 9, static_cast<std::uint32_t>(rest % 100000000u));
  int nd = 17;
  while (nd > 1 && digits[nd - 1] == '0') --nd;  // %g removes trailing zeros
  char* p = out;
  if (std::signbit(x)) *p++ = '-';
  if (k >= -4 && k < 17) {  // fixed notation
    if (k >= 0) {
      const int int_digits = k + 1;
      std::memcpy(p, digits, 17);  // digits[nd..] are '0': whole numbers need no more
      if (nd <= int_digits) return p + int_digits;
      p[int_digits] = '.';
      // At most 17 - int_digits digits after the point: 8 bytes, or 16 when int_digits <= 8.
      std::memcpy(p + int_digits + 1, digits + int_digits, 8);
      if (nd - int_digits > 8) std::memcpy(p + int_digits + 9, digits + int_digits + 8, 8);
      return p + nd + 1;
    }
    std::memcpy(p, "0.000", 5);
    p += 1 - k;  // "0." and -k - 1 zeros
    std::memcpy(p, digits, 17);
    return p + nd;
  }
  *p++ = digits[0];  // scientific: d.ddde+XX, at least two exponent digits
  if (nd > 1) {
    *p++ = '.';
    std::memcpy(p, digits + 1, 16);
    p += nd - 1;
  }
  *p++ = 'e';
  *p++ = k < 0 ? '-' : '+';
  const int ak = k < 0 ? -k : k;
  if (ak >= 100) *p++ = static_cast<char>('0' + ak / 100);
  *p++ = static_cast<char>('0' + ak / 10 % 10);
  *p++ = static_cast<char>('0' + ak % 10);
  return p;
}

}  // namespace fest
