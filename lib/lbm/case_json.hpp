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

// Applies one override "a.b.c=value" (value parsed as JSON, else taken as a string) to a
// case document. Throws Status::usage for a malformed assignment.
void apply_override(nlohmann::json& doc, const std::string& assignment);


}  // namespace fest::lbm
