#pragma once
// Integers and strings read from untrusted JSON. nlohmann's get<integer>() converts a floating-point
// number with a plain cast, which is undefined when the value does not fit (1.2e31 into a
// size_t: found by fuzz_ltw), and narrows a wide integer by wrapping (4294967297 into an
// int gives 1). json_integer<T>(j) returns the value only when j is an integer, or a float
// with an integral value, that T holds exactly; otherwise it throws the library's own
// out_of_range (406) or type_error (302), so the caller's JSON error handling puts it in
// its words as it does any other wrong value. A template over the JSON type: lib/core does
// not include the JSON library.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace fest {

template <typename T, typename Json>
T json_integer(const Json& j) {
  static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>, "json_integer reads integers");
  using limits = std::numeric_limits<T>;
  auto out_of_range = [&](const std::string& got) {
    return Json::out_of_range::create(
        406, "expected an integer from " + std::to_string(limits::min()) + " to " + std::to_string(limits::max()) + ", got " + got,
        &j);
  };
  if (j.is_number_unsigned()) {
    const auto v = j.template get<std::uint64_t>();
    if (v > static_cast<std::uint64_t>(limits::max())) throw out_of_range(std::to_string(v));
    return static_cast<T>(v);
  }
  if (j.is_number_integer()) {
    const auto v = j.template get<std::int64_t>();
    if (v < 0 ? (!limits::is_signed || v < static_cast<std::int64_t>(limits::min()))
              : static_cast<std::uint64_t>(v) > static_cast<std::uint64_t>(limits::max()))
      throw out_of_range(std::to_string(v));
    return static_cast<T>(v);
  }
  if (j.is_number_float()) {
    const double d = j.template get<double>();
    // T's range as doubles: its minimum is 0 or -2^digits (exact), its maximum + 1 is 2^digits.
    const double lo = static_cast<double>(limits::min()), past_hi = std::ldexp(1.0, limits::digits);
    if (!(d >= lo && d < past_hi) || d != std::floor(d)) throw out_of_range(j.dump());
    return static_cast<T>(d);
  }
  // Not a number (the library itself would turn true into 1): its type_error 302 wording.
  throw Json::type_error::create(302, std::string("type must be number, but is ") + j.type_name(), &j);
}

// json_integer over an array's elements (the library's type_error for a non-array).
template <typename T, typename Json>
std::vector<T> json_integers(const Json& j) {
  if (!j.is_array()) return j.template get<std::vector<T>>();
  std::vector<T> out;
  out.reserve(j.size());
  for (const auto& e : j) out.push_back(json_integer<T>(e));
  return out;
}

// Object member `key` as json_integer<T>, or `fallback` when the object has no such member.
template <typename T, typename Json>
T json_integer_or(const Json& object, const char* key, T fallback) {
  const auto it = object.find(key);
  return it == object.end() ? fallback : json_integer<T>(*it);
}

// Object member `key` as a string, or `fallback` when the object has no such member. The
// library's value(key, "text") throws its type_error when the member is not a string; this
// does the same (302, "type must be string, but is number"), for callers that put the
// library's errors in their words, and says so by its name.
template <typename Json>
std::string json_string_or(const Json& object, const char* key, const std::string& fallback) {
  const auto it = object.find(key);
  if (it == object.end()) return fallback;
  if (!it->is_string()) throw Json::type_error::create(302, std::string("type must be string, but is ") + it->type_name(), &*it);
  return it->template get<std::string>();
}

}  // namespace fest
