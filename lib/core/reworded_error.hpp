#pragma once
// A library's error in the user's words. lib/ reports in the domain's terms ("zone plate:
// numax must be positive"); a tool that knows which flag set the value rewords the message
// ("metrics --zoneplate: numax must be positive") and keeps its exit status.

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

#include "core/error.hpp"

namespace fest {

// A phrase of the domain and the words the user typed for it.
using Rewording = std::pair<std::string_view, std::string_view>;

// The error with the first occurrence of each domain phrase replaced by the user's words.
template <class Phrases>
Error reworded(const Error& e, const Phrases& phrases) {
  std::string what = e.what();
  for (const auto& [domain, user] : phrases) {
    const std::size_t at = what.find(domain);
    if (at != std::string::npos) what.replace(at, domain.size(), user);
  }
  return Error(e.status(), what);
}
inline Error reworded(const Error& e, std::initializer_list<Rewording> phrases) {
  return reworded<std::initializer_list<Rewording>>(e, phrases);
}

// f(), with any fest::Error it throws reworded.
template <class F>
decltype(auto) with_rewording(std::initializer_list<Rewording> phrases, F&& f) {
  try {
    return std::forward<F>(f)();
  } catch (const Error& e) {
    throw reworded(e, phrases);
  }
}

}  // namespace fest
