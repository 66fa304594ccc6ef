#include "capture/rig.hpp"

#include <cmath>

#include <Eigen/Core>

#include "capture/frames.hpp"
#include "capture/json_fields.hpp"
#include "capture/station.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"

namespace fest::capture {

using nlohmann::json;

namespace {

std::vector<double> flat(const Eigen::Matrix3d& m) {
  std::vector<double> v;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) v.push_back(m(r, c));
  return v;
}

}  // namespace

json build_rig(const json& manifest, const std::vector<RigImage>& images, const std::string& session,
               const std::string& where) {
  const JsonFields f(where);
  if (!manifest.contains("camera")) f.fail("missing", "camera");
  if (!manifest.contains("turntable") || !manifest["turntable"].contains("cal")) f.fail("missing", "turntable.cal");
  if (!manifest.contains("station")) f.fail("missing", "station");
  const CameraIntrinsics k = parse_intrinsics(manifest["camera"], where + ": camera");
  const TurntableCal cal = parse_turntable_cal(manifest["turntable"]["cal"], where + ": turntable.cal");
  const Station station = parse_station(manifest["station"], where + ": station");
  Eigen::Matrix3d r0;
  r0 << cal.R_T0[0], cal.R_T0[1], cal.R_T0[2], cal.R_T0[3], cal.R_T0[4], cal.R_T0[5], cal.R_T0[6], cal.R_T0[7], cal.R_T0[8];
  const Eigen::Vector3d t0(cal.t_T0[0], cal.t_T0[1], cal.t_T0[2]);

  json out = {{"version", 1}, {"frame", "turntable"}, {"session", session}, {"images", json::array()}};
  for (const RigImage& im : images) {
    const LightConfig* l = station.light(im.light);
    if (!l) f.fail(fmt::format("light \"{}\" is not in the station", quoted_bytes(im.light)), "station.lights");
    if (!l->position_mm)
      f.fail(fmt::format("light \"{}\" has no position_mm (run capture calib-lights)", quoted_bytes(im.light)), "station.lights");
    const Eigen::Vector3d q((*l->position_mm)[0], (*l->position_mm)[1], (*l->position_mm)[2]);
    const Eigen::Matrix3d R = r0 * rotation_about_axis(im.angle_deg);
    const Eigen::Vector3d q_t = rotation_about_axis(-im.angle_deg) * r0.transpose() * (q - t0);
    json camera = {{"K", k.K}, {"dist", k.dist}, {"R", flat(R)}, {"t", cal.t_T0}, {"width", k.width}, {"height", k.height}};
    json light = {{"id", im.light}, {"position", {q_t.x(), q_t.y(), q_t.z()}}, {"intensity", l->intensity}};
    json entry = {{"file", im.file}, {"angle_index", im.angle_index}, {"angle_deg", im.angle_deg},
                  {"camera", camera}, {"light", light}};
    if (!im.mask.empty()) entry["mask"] = im.mask;
    out["images"].push_back(entry);
  }
  return out;
}

}  // namespace fest::capture
