#pragma once
// The acquisition plan, plan.json (docs/capture.md §2, fest-capture(5)), and its expansion into the
// ordered list of shots the loop takes: mechanics outermost (angles), then the per-view
// shots (silhouette, light calibration, dark), then for every light its exposure series.

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "capture/station.hpp"

namespace fest::capture {

struct ViewShots {
  int count = 0;
  double exposure_s = 0;  // 0: the plan's shortest exposure
};

struct Plan {
  std::vector<double> angles_deg;
  bool each_light = false;          // "lights": "each" -- every light whose role is "light"
  std::vector<std::string> lights;  // when not each_light
  std::vector<double> exposures_s;  // increasing
  bool silhouette = false;
  std::vector<std::string> silhouette_lights;  // lit for the silhouette shot
  double silhouette_exposure_s = 0.01;
  ViewShots lightcal, dark;
  int repeat = 1;  // takes of every exposure of a series (hdrmerge averages them)
};

// Throws bad_input naming `where` and the JSON path. Refuses what is not supported yet
// ("auto_bracket": true) with a message saying so.
Plan parse_plan(const nlohmann::json& doc, const std::string& where);
nlohmann::json plan_to_json(const Plan& plan);

// The text notations of a plan's angles and exposures (capture(1) writes its flags in
// them): angles "24" (a count of equal steps) or a list "0,15,30" in degrees; exposures
// "1/1000:1:12" (base : stops : count) or an increasing list "0.001,0.002". Throws
// usage_error in those terms; the tool adds the flag's name.
std::vector<double> angles_from_flag(const std::string& text);
// `count` equal steps over a revolution from 0 degrees.
std::vector<double> even_angles(int count);
// base_s * 2^(stops k) for k = 0 .. count-1.
std::vector<double> bracket_exposures(double base_s, double stops, int count);
std::vector<double> exposures_from_flag(const std::string& text);
double seconds_from_text(const std::string& text);  // "0.001", "1e-3", "1/1000"

enum class ShotKind { hdr, silhouette, lightcal, dark };
const char* shot_kind_name(ShotKind k);

struct PlannedShot {
  ShotKind kind = ShotKind::hdr;
  int angle_index = 0;
  double angle_cmd_deg = 0;
  std::string light;                    // hdr and lightcal: the light that is on
  std::vector<std::string> lights_on;   // every light on during the shot
  int exposure_index = 0;               // hdr: k of e{k:02}; other kinds: their number
  int repeat_index = 0;                 // hdr: the take r of e{k:02}_r{r} when the plan repeats
  double exposure_s = 0;
  std::string file;                     // relative to the session, extension included
};

// The shots in acquisition order. Checks the plan against the station (every light
// named exists; silhouette lights are lit by the station; a light's on-time per series
// stays under its max_on_s) and throws bad_input naming `where`. `extension` is ".png",
// ".tiff" or ".jpg".
std::vector<PlannedShot> expand_plan(const Plan& plan, const Station& station, const std::string& extension,
                                     const std::string& where);

// The lights an expanded plan switches for exposure series, in order.
std::vector<std::string> plan_lights(const Plan& plan, const Station& station);

}  // namespace fest::capture
