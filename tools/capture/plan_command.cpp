// capture plan: a plan.json from flags (docs/capture.md §2).

#include <cstdio>

#include "capture/plan.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {

namespace {

std::vector<std::string> ids(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t p = text.find(',', start);
    const std::string id = text.substr(start, p == std::string::npos ? std::string::npos : p - start);
    if (id.empty()) throw usage_error("empty light id in '{}'", text);
    out.push_back(id);
    if (p == std::string::npos) return out;
    start = p + 1;
  }
}

}  // namespace

int plan_command(const PlanOptions& o) {
  capture::Plan p;
  p.angles_deg = capture::angles_from_flag(o.angles);
  if (o.lights == "each") p.each_light = true;
  else p.lights = ids(o.lights);
  p.exposures_s = capture::exposures_from_flag(o.bracket);
  if (!o.silhouette.empty()) {
    p.silhouette = true;
    p.silhouette_lights = ids(o.silhouette);
    p.silhouette_exposure_s = o.silhouette_exposure_s;
  }
  p.lightcal.count = o.lightcal;
  p.dark.count = o.dark;
  p.repeat = o.repeat;
  // Round trip through the parser: what is printed is what `capture run` accepts.
  const nlohmann::json doc = capture::plan_to_json(p);
  capture::parse_plan(doc, "capture plan");
  std::fputs(formats::write_json(doc).c_str(), stdout);
  return 0;
}

}  // namespace fest::capture_tool
