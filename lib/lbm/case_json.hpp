#pragma once
// The case file of lbmsim as a codec: JSON <-> Case (docs/lbmsim.md "Case file").
// Unknown keys are errors with a "did you mean" hint; values are range-checked.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "lbm/case.hpp"

namespace fest::lbm {

// Parses, converts physical units to lattice units and validates. Throws
// Status::bad_input: `case key "colision" is unknown (did you mean "collision"?) (case.json)`.
Case parse_case(const nlohmann::json& doc, const std::string& where);

// The case as JSON in lattice units (tau explicit), for reports.
nlohmann::json case_to_json(const Case& c);

// One override of a case key: the path of keys ({"collision", "tau"}) and the value's
// text, parsed as JSON, else taken as a string.
struct CaseOverride {
  std::vector<std::string> path;
  std::string value;
};

// Applies an override to a case document, making the objects on the path that are
// missing. Throws Status::usage when the document is not an object or a key on the path
// holds something other than an object ("\"size\" is not an object").
void apply_override(nlohmann::json& doc, const CaseOverride& override_);

// "a.b.c=value" -> CaseOverride. Throws Status::usage with the text quoted first, so that
// a tool can put its flag before it: "\"novalue\" must be key=value", "\"a..b=1\": empty
// key part".
CaseOverride parse_override(const std::string& assignment);

// parse_override, then apply_override.
void apply_override(nlohmann::json& doc, const std::string& assignment);


}  // namespace fest::lbm
