#pragma once
// fcompare's job (docs/fcompare.md), taking its typed options. main.cpp fills these from
// flags; everything else in this folder is the fest_fcompare_app library.

#include <cstddef>
#include <string>
#include <vector>

#include "compare/checks.hpp"

namespace fest::fcompare_tool {

struct CompareOptions {
  std::string a, b;
  double tol = 0;          // limit of the kind's main metric
  bool tol_given = false;  // --tol on the command line: a criterion the user asked for
  std::vector<compare::Check> thresholds;  // extra checks, replacing defaults of their family
  std::size_t samples = 100000;            // meshes: surface samples besides the vertices
  int threads = 0;
  bool ignore_counts = false;
  bool ignore_topology = false;
  // Meshes: also compare vertex i with vertex i (vertex_max_abs). Off by default: a
  // correct conversion may reorder vertices (Draco's and fest's Edgebreaker coders do).
  bool ordered = false;
  std::string report;  // JSON of every metric and check; "" : none
  bool quiet = false;
};

// Compares o.a with o.b; prints the summary, writes the report; 0 when every check
// holds, 1 when one fails (named on standard error).
int compare_command(const CompareOptions& o);

}  // namespace fest::fcompare_tool
