// capture plan: a plan.json from the typed options (docs/capture.md §2).

#include <cstdio>

#include "capture/plan.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "formats/table/table_io.hpp"

namespace fest::capture_tool {

int plan_command(const PlanOptions& o) {
  capture::Plan p;
  p.angles_deg = o.angles_deg.empty() ? capture::even_angles(24) : o.angles_deg;
  p.each_light = o.each_light;
  p.lights = o.lights;
  p.exposures_s = o.exposures_s.empty() ? capture::bracket_exposures(1.0 / 1000, 1, 12) : o.exposures_s;
  if (!o.silhouette_lights.empty()) {
    p.silhouette = true;
    p.silhouette_lights = o.silhouette_lights;
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
