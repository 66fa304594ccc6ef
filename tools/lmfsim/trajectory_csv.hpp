#pragma once
// lmfsim's trajectory CSV (lmfsim(1), docs/lmfsim.md): `frame,t,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz`.

#include <string>
#include <vector>

#include "lmfsim/model.hpp"

namespace fest::lmfsim_tool {

struct TrajectoryRow {
  long frame = 0;
  double t = 0;
  std::string body;
  fest::lmfsim::Vec3 p, v, w;
  fest::lmfsim::Quat q;
};

inline const char* trajectory_header() { return "frame,t,body,px,py,pz,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz\n"; }
void append_row(std::string& out, const TrajectoryRow& r);
// Throws bad_input naming `name` and the line for anything malformed.
std::vector<TrajectoryRow> parse_trajectory(const std::string& bytes, const std::string& name);

}  // namespace fest::lmfsim_tool
