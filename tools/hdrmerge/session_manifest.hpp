#pragma once
// A capture session's manifest (capture(1), version 1) as hdrmerge session reads it: the
// exposure sets to merge and the silhouette shots, checked before any picture is opened.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace fest::hdrmerge_tool {

struct SessionShot {
  std::string file, sha256;
  double exposure_s = 0;
  int angle_index = 0;
  double angle_deg = 0;
};

struct ExposureSet {
  int angle_index = 0;
  double angle_deg = 0;
  std::string light;
  // The shots of each exposure time, in order: one, or a plan's "repeat" takes (the
  // manifest lists the takes of one exposure next to each other).
  std::vector<std::vector<SessionShot>> exposures;
};

struct SessionManifest {
  std::string session;  // the "session" field (where the pictures are when read from stdin)
  std::vector<ExposureSet> sets;
  std::map<int, SessionShot> silhouettes;  // per angle, the first silhouette shot there
};

// Throws bad_input naming the field and `where` for anything hdrmerge cannot use: another
// version, an unfinished session, a shot index out of range, a file outside the session, a
// light id that is not a plain name, a set with fewer than two exposures.
SessionManifest parse_session_manifest(const nlohmann::json& manifest, const std::string& where);

}  // namespace fest::hdrmerge_tool
