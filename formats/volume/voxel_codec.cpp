#include "formats/volume/voxel_codec.hpp"
#include "core/quote.hpp"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/gzip.hpp"

namespace fest::formats::volume_detail {

namespace {

// Assembling values byte by byte keeps the code independent of the host's byte order.
template <typename T>
T load(const unsigned char* p, bool big_endian) noexcept {
  using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
            std::conditional_t<sizeof(T) == 2, std::uint16_t,
            std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  U bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t shift = 8 * (big_endian ? sizeof(T) - 1 - i : i);
    bits = static_cast<U>(bits | (static_cast<U>(p[i]) << shift));
  }
  T value;
  std::memcpy(&value, &bits, sizeof(T));
  return value;
}

// Writes into a buffer sized beforehand: appending to a std::string voxel by voxel cost
// a quarter of `volwave decode` on a CT head (callgrind).
template <typename T>
void store(T value, bool big_endian, char* to) noexcept {
  using U = std::conditional_t<sizeof(T) == 1, std::uint8_t,
            std::conditional_t<sizeof(T) == 2, std::uint16_t,
            std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
  U bits;
  std::memcpy(&bits, &value, sizeof(T));
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t shift = 8 * (big_endian ? sizeof(T) - 1 - i : i);
    to[i] = static_cast<char>((bits >> shift) & 0xff);
  }
}

template <typename T>
void decode_as(std::string_view data, bool big_endian, std::vector<double>& values) {
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(load<T>(p + i * sizeof(T), big_endian));
}

// Rounds and clamps to an integer type. The bounds are compared in double: for 64-bit
// types the maximum is not a double, so "v >= 2^63" is the overflow test.
template <typename T>
T to_integer(double v) noexcept {
  if (std::isnan(v)) return 0;
  const double r = std::round(v);
  constexpr double lo = static_cast<double>(std::numeric_limits<T>::min());
  // 2^(digits) is exactly representable and one past the maximum.
  constexpr double hi_exclusive = 2.0 * static_cast<double>(std::numeric_limits<T>::max() / 2 + 1);
  if (r < lo) return std::numeric_limits<T>::min();
  if (r >= hi_exclusive) return std::numeric_limits<T>::max();
  return static_cast<T>(r);
}

float to_float(double v) noexcept {
  constexpr double max = std::numeric_limits<float>::max();
  // FLT_MAX + half its ulp (2^103) is where IEEE rounding overflows to infinity; the
  // conversion is written out because an out-of-range double->float cast is UB in C++.
  const double overflow = max + std::ldexp(1.0, 103);
  if (v >= overflow) return std::numeric_limits<float>::infinity();
  if (v <= -overflow) return -std::numeric_limits<float>::infinity();
  if (v > max) return std::numeric_limits<float>::max();
  if (v < -max) return -std::numeric_limits<float>::max();
  return static_cast<float>(v);
}

template <typename T>
void encode_as(const std::vector<double>& values, bool big_endian, std::string& out) {
  out.resize(values.size() * sizeof(T));
  char* to = out.data();
  for (double v : values) {
    if constexpr (std::is_same_v<T, float>)
      store<float>(to_float(v), big_endian, to);
    else if constexpr (std::is_same_v<T, double>)
      store<double>(v, big_endian, to);
    else
      store<T>(to_integer<T>(v), big_endian, to);
    to += sizeof(T);
  }
}

}  // namespace

void decode_voxels(std::string_view data, ScalarType type, bool big_endian, std::vector<double>& values) {
  switch (type) {
    case ScalarType::u8: return decode_as<std::uint8_t>(data, big_endian, values);
    case ScalarType::i8: return decode_as<std::int8_t>(data, big_endian, values);
    case ScalarType::u16: return decode_as<std::uint16_t>(data, big_endian, values);
    case ScalarType::i16: return decode_as<std::int16_t>(data, big_endian, values);
    case ScalarType::u32: return decode_as<std::uint32_t>(data, big_endian, values);
    case ScalarType::i32: return decode_as<std::int32_t>(data, big_endian, values);
    case ScalarType::u64: return decode_as<std::uint64_t>(data, big_endian, values);
    case ScalarType::i64: return decode_as<std::int64_t>(data, big_endian, values);
    case ScalarType::f32: return decode_as<float>(data, big_endian, values);
    case ScalarType::f64: return decode_as<double>(data, big_endian, values);
  }
}

std::string encode_voxels(const std::vector<double>& values, ScalarType type, bool big_endian) {
  std::string out;
  switch (type) {
    case ScalarType::u8: encode_as<std::uint8_t>(values, big_endian, out); break;
    case ScalarType::i8: encode_as<std::int8_t>(values, big_endian, out); break;
    case ScalarType::u16: encode_as<std::uint16_t>(values, big_endian, out); break;
    case ScalarType::i16: encode_as<std::int16_t>(values, big_endian, out); break;
    case ScalarType::u32: encode_as<std::uint32_t>(values, big_endian, out); break;
    case ScalarType::i32: encode_as<std::int32_t>(values, big_endian, out); break;
    case ScalarType::u64: encode_as<std::uint64_t>(values, big_endian, out); break;
    case ScalarType::i64: encode_as<std::int64_t>(values, big_endian, out); break;
    case ScalarType::f32: encode_as<float>(values, big_endian, out); break;
    case ScalarType::f64: encode_as<double>(values, big_endian, out); break;
  }
  return out;
}

double storable_value(double value, ScalarType type) noexcept {
  switch (type) {
    case ScalarType::u8: return to_integer<std::uint8_t>(value);
    case ScalarType::i8: return to_integer<std::int8_t>(value);
    case ScalarType::u16: return to_integer<std::uint16_t>(value);
    case ScalarType::i16: return to_integer<std::int16_t>(value);
    case ScalarType::u32: return to_integer<std::uint32_t>(value);
    case ScalarType::i32: return to_integer<std::int32_t>(value);
    case ScalarType::u64: return static_cast<double>(to_integer<std::uint64_t>(value));
    case ScalarType::i64: return static_cast<double>(to_integer<std::int64_t>(value));
    case ScalarType::f32: return to_float(value);
    case ScalarType::f64: return value;
  }
  return value;
}

void parse_text_voxels(std::string_view text, std::vector<double>& values, const char* what) {
  std::size_t pos = 0;
  const auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',' || c == '\f' || c == '\v'; };
  for (std::size_t i = 0; i < values.size(); ++i) {
    while (pos < text.size() && is_space(text[pos])) ++pos;
    if (pos >= text.size())
      throw bad_input("{}: text data ends after {} of {} values", what, i, values.size());
    std::size_t end = pos;
    while (end < text.size() && !is_space(text[end])) ++end;
    std::string_view word = text.substr(pos, end - pos);
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    double v = 0;
    const auto res = std::from_chars(word.data(), word.data() + word.size(), v);
    if (word.empty() || res.ec == std::errc::invalid_argument || res.ptr != word.data() + word.size())
      throw bad_input("{}: text value {} ('{}') at data byte {} is not a number", what, i + 1,
                      fest::quoted_bytes(text.substr(pos, end - pos), 32), pos);
    if (res.ec == std::errc::result_out_of_range)
      throw bad_input("{}: text value {} ('{}') is out of range", what, i + 1, fest::quoted_bytes(text.substr(pos, end - pos), 32));
    values[i] = v;
    pos = end;
  }
}

std::uint64_t max_inflated_bytes(std::uint64_t compressed_bytes) noexcept {
  constexpr std::uint64_t ratio = 1100;  // deflate's limit is 1032:1; a little slack
  if (compressed_bytes > std::numeric_limits<std::uint64_t>::max() / ratio) return std::numeric_limits<std::uint64_t>::max();
  return compressed_bytes * ratio + 1024;
}

std::string inflate_voxel_bytes(std::string_view compressed, std::uint64_t expected, const char* what) {
  if (expected > max_inflated_bytes(compressed.size()))
    throw bad_input("{}: {} bytes of compressed data cannot hold the {} bytes the header declares", what,
                    compressed.size(), expected);
  if (expected > max_input_bytes())
    throw bad_input("{}: {} bytes of voxel data exceed the input limit of {} bytes", what, expected, max_input_bytes());
  try {
    return inflate_exact(compressed, expected);
  } catch (const Error& e) {
    throw bad_input("{}: {}", what, e.what());
  }
}

}  // namespace fest::formats::volume_detail
