#pragma once
// The rig file of fest-capture(5) (RIG) as brdffit reads it: JSON <-> the photographs'
// views. lib/capture writes it (build_rig); the file names stay as written, because
// where they point is the tool's business (the rig's folder, its "session", --root).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "brdffit/lumitexel_builder.hpp"

namespace fest::brdffit {

struct RigEntry {
  std::string file, mask;  // as written
  bool has_mask = false;
  int angle_index = 0;
  double angle_deg = 0;
  ImageView view;          // camera, and the light when the entry names one
  std::string light_id;
};

struct RigDocument {
  std::string frame = "mesh";
  std::string session;     // "" when the rig names none
  std::vector<RigEntry> images;
};

// Version 1 rigs; `where` names the document in messages (entries add ", image K").
RigDocument decode_rig(const nlohmann::json& j, const std::string& where);

}  // namespace fest::brdffit
