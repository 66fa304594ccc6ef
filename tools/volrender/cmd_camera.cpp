// volrender camera: the camera(s) of the camera flags as JSON -- rays' frame, off-axis
// frustum and view matrix (docs/volrender.md "Cameras").
#include <cstdio>

#include <nlohmann/json.hpp>

#include "camera_args.hpp"
#include "commands.hpp"
#include "volume_input.hpp"

namespace fest::volrender_tool {

int run_camera_print(const CameraPrintArgs& a) {
  std::vector<raycast::Camera> cams;
  if (!a.input.empty()) {
    formats::VolumeSourceOptions vo;
    vo.raw = a.raw;
    const LoadedVolume L = load_volume(a.input, vo);
    cams = make_cameras(a.camera, &L.grid);
  } else {
    cams = make_cameras(a.camera, nullptr);
  }
  nlohmann::json j = nlohmann::json::array();
  for (const auto& c : cams) j.push_back(camera_json(c));
  const std::string text = j.dump(2) + "\n";
  std::fwrite(text.data(), 1, text.size(), stdout);
  return 0;
}

}  // namespace fest::volrender_tool
