#pragma once
// The metrics and default checks of each kind of file, set on a compare::Metrics.

#include <string>
#include <utility>

#include "commands.hpp"
#include "compare/checks.hpp"
#include "formats/input.hpp"

namespace fest::fcompare_tool {

// Both inputs read by one reader, a first (its error is the one reported when both are
// bad): every kind but meshes (which may hold lines, see compare_mesh.cpp) starts so.
template <class Read>
auto parse_both(const formats::Input& a, const formats::Input& b, Read& read) {
  auto first = formats::parse(a, read);
  auto second = formats::parse(b, read);
  return std::make_pair(std::move(first), std::move(second));
}

// Measures a against b (both of one kind) into m, with that kind's checks.
void measure(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);

void compare_meshes(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);
void compare_images(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);
void compare_volumes(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);
void compare_tables(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);
void compare_datasets(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);
void compare_json(const formats::Input& a, const formats::Input& b, const CompareOptions& o, compare::Metrics& m);

// The check of a kind's main metric: --tol given is the user's own criterion (a -t on
// another metric of the family leaves it in place); otherwise it is a default that any
// -t on the family replaces (see compare::Metrics).
void require_main(compare::Metrics& m, const std::string& metric, const CompareOptions& o);

}  // namespace fest::fcompare_tool
