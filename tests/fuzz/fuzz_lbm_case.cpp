// libFuzzer target: raw bytes as an lbmsim case file: JSON parse, the case codec with its
// validation, and (for small lattices) the shape flags and one solver step.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "lbm/case_json.hpp"
#include "lbm/geometry.hpp"
#include "lbm/solver.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded()) return 0;
  try {
    fest::lbm::Case c = fest::lbm::parse_case(doc, "fuzz");
    (void)fest::lbm::case_to_json(c);
    if (c.cells() > 4096 || !c.mask_file.empty() || !c.flags_file.empty() || !c.meshes.empty()) return 0;
    const fest::lbm::Flags f = fest::lbm::shape_flags(c);
    fest::lbm::SolverSetup s;
    s.c = &c;
    s.flags = &f;
    auto solver = fest::lbm::make_solver(s);
    solver->step();
  } catch (const fest::Error&) {
  }
  return 0;
}
