#pragma once
// Whether this binary was built with AddressSanitizer (scripts/run-tests --sanitize, the
// fuzz build). Checks that compare run times (a cost fraction, a speed-up) are not
// representative in such a build, whose instrumentation slows some loops several times
// more than others: they report the figure and say it was not judged.

namespace fest {

#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kInstrumentedBuild = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kInstrumentedBuild = true;
#else
inline constexpr bool kInstrumentedBuild = false;
#endif
#else
inline constexpr bool kInstrumentedBuild = false;
#endif

}  // namespace fest
