#pragma once
// The rig JSON of fest-capture(5) (docs/hdrmerge.md §5), the one definition brdffit reads: per merged
// (angle, light) set the HDR image, the camera (brdffit cam.json fields) and the light
// (light.json fields), in the turntable frame T at that angle:
//   R = R_T0 Rz(theta), t = t_T0, light position q^T = Rz(-theta) R_T0^T (q - t_T0).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fest::capture {

struct RigImage {
  std::string file;   // relative to the session
  std::string mask;   // relative to the session
  int angle_index = 0;
  double angle_deg = 0;  // executed angle
  std::string light;
};

// `manifest` supplies "camera" (intrinsics), "turntable"."cal" and "station"."lights".
// Throws bad_input naming `where` (a light without position_mm, a missing calibration).
nlohmann::json build_rig(const nlohmann::json& manifest, const std::vector<RigImage>& images, const std::string& session,
                         const std::string& where);

}  // namespace fest::capture
