#pragma once
// Numeric flags: the range a value must lie in, stated in plain numbers, and the rule every
// floating-point flag obeys -- NaN and infinities are refused unless the flag says it takes
// them. CLI11's own Range lets NaN through (every comparison with NaN is false) and words its
// bounds with std::to_string (1e-15 as "0.000000", DBL_MAX as 309 digits); these replace it.
// Include only from tools/*/main.cpp (cli.hpp includes it; cli::run applies the rule).
//
//   ->check(fest::cli::range(1e-15, 1.0))     "--tol: must be in [1e-15, 1], not nan"
//   ->check(fest::cli::positive)              "--sigma: must be a positive number, not -1"
//   ->check(fest::cli::non_negative)          "--nu: must be 0 or more, not -1"
//   ->check(fest::cli::range(0.0, inf))       accepts inf: the bound says so
//   ->check(fest::cli::accepts_nan)           NaN is a meaningful value (a no-data marker)

#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace fest::cli {

// Names of the validators that mark a flag as taking infinities or NaN; check_numbers
// looks for them.
inline const std::string takes_infinity_mark = "fest-takes-infinity";
inline const std::string takes_nan_mark = "fest-takes-nan";

namespace detail {

// A flag's value as typed, shortened so that a pasted file does not fill the terminal.
inline std::string quoted_value(const std::string& text) {
  return text.size() <= 40 ? text : text.substr(0, 37) + "...";
}

// The value as a double, or false when it is not a number at all (CLI11's conversion error
// then names the problem).
inline bool as_double(const std::string& text, double& x) {
  return CLI::detail::lexical_cast(text, x);
}

// A bound written as a person writes it: 1e-15, 0.25, 10000000, inf.
template <typename T>
std::string bound_text(T v) {
  if constexpr (std::is_integral_v<T>) {
    return fmt::format("{}", v);
  } else {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    return fmt::format("{}", static_cast<double>(v));
  }
}

}  // namespace detail

// Values in [lo, hi], both inclusive; NaN never; an infinity only where that bound is one.
// (Whether an integer flag got a whole number is CLI11's conversion's to say: an integral
// range may also bound a floating-point flag.)
template <typename T>
CLI::Validator range(T lo, T hi) {
  const std::string interval = "[" + detail::bound_text(lo) + ", " + detail::bound_text(hi) + "]";
  const double dlo = static_cast<double>(lo), dhi = static_cast<double>(hi);
  CLI::Validator v(
      [interval, dlo, dhi](std::string& text) -> std::string {
        double x = 0;
        if (!detail::as_double(text, x)) return {};
        if (std::isnan(x) || x < dlo || x > dhi)
          return fmt::format("must be in {}, not {}", interval, detail::quoted_value(text));
        return {};
      },
      std::string(std::is_integral_v<T> ? "INT" : "FLOAT") + " in " + interval);
  if (std::isinf(dlo) || std::isinf(dhi)) v.name(takes_infinity_mark);
  return v;
}

// Finite and > 0 (CLI::PositiveNumber without its bounds' 309 digits).
inline const CLI::Validator positive(
    [](std::string& text) -> std::string {
      double x = 0;
      if (!detail::as_double(text, x)) return {};
      if (!(x > 0) || std::isinf(x)) return "must be a positive number, not " + detail::quoted_value(text);
      return {};
    },
    "POSITIVE");

// Finite and >= 0.
inline const CLI::Validator non_negative(
    [](std::string& text) -> std::string {
      double x = 0;
      if (!detail::as_double(text, x)) return {};
      if (!(x >= 0) || std::isinf(x)) return "must be 0 or more, not " + detail::quoted_value(text);
      return {};
    },
    "NONNEGATIVE");

// Marks a floating-point flag whose NaN means something (terrainlod's --nodata nan).
inline const CLI::Validator accepts_nan = CLI::Validator([](std::string&) { return std::string(); }, "", takes_nan_mark);

namespace detail {

inline bool has_mark(CLI::Option* opt, const std::string& mark) {
  try {
    return opt->get_validator(mark)->get_name() == mark;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

// The option's own type ("FLOAT", "[FLOAT,FLOAT]", "TEXT"), without the validators' words
// that get_type_name appends after a colon.
inline bool holds_floating_point(const CLI::Option* opt) {
  const std::string type = opt->get_type_name();
  return type.substr(0, type.find(':')).find("FLOAT") != std::string::npos;
}

}  // namespace detail

// The rule for every floating-point flag of `app` and of its subcommands, after parsing:
// NaN is refused unless the flag is marked accepts_nan; +-inf unless a range bound is
// infinite. A usage error (CLI::ValidationError) naming the flag.
inline void check_numbers(CLI::App& app) {
  for (CLI::Option* opt : app.get_options()) {
    if (opt->count() == 0 || !detail::holds_floating_point(opt)) continue;
    const bool nan_ok = detail::has_mark(opt, takes_nan_mark);
    const bool inf_ok = detail::has_mark(opt, takes_infinity_mark);
    for (const std::string& text : opt->results()) {
      double x = 0;
      if (!detail::as_double(text, x)) continue;
      if ((std::isnan(x) && !nan_ok) || (std::isinf(x) && !inf_ok))
        throw CLI::ValidationError(opt->get_name(), "must be a finite number, not " + detail::quoted_value(text));
    }
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) check_numbers(*sub);
}

}  // namespace fest::cli
