#pragma once
// Particle probes (seed chapter 4.3, fig. 4.4b): stream ribbons, stream tubes and glyphs
// as triangle meshes with per-vertex scalars, built from lemtrace's paths. Geometry only;
// the tool writes the meshes (PLY, VTP).
//
// A stream ribbon follows a streamline x(t) and a second, neighbouring one y(t) started
// a ribbon width w away; the ribbon edge at time t joins x(t) and y(t) (the points are
// paired by time, so both edges are material lines of the same particles). Its width
// |y - x| and its twist (the angle of y - x about the tangent, measured against a frame
// parallel-transported along x) show the local rotation: in a rigid rotation of rate
// Omega about the line the width stays w and the twist grows as Omega t, and in general
// d(twist)/dt = (omega . t_hat) / 2, half the streamwise vorticity (reported per vertex
// for comparison).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "lemtrace/tracer.hpp"

namespace fest::lemtrace {

struct ProbeMesh {
  std::vector<Vec3> points;
  std::vector<std::array<uint32_t, 3>> triangles;
  // Per-vertex scalars, each as long as `points`.
  std::vector<std::string> scalar_names;
  std::vector<std::vector<double>> scalars;

  // Index of a scalar array, added (zero-filled) when missing.
  std::size_t scalar(const std::string& name);
};

// Position of a path at time t, linear between its points (t outside: nullopt-like, false).
bool position_at(const Polyline& line, double t, Vec3& out);

// One ribbon edge per point of `main` whose time the neighbour also reached.
struct RibbonEdge {
  Vec3 a, b;        // on the main and the neighbouring line
  double t = 0;
  double width = 0;
  double twist = 0; // radians, cumulative, against the parallel-transported frame
};
std::vector<RibbonEdge> ribbon_edges(const Polyline& main, const Polyline& neighbour);

// A direction perpendicular to v (the ribbon's starting offset), deterministic.
Vec3 perpendicular(const Vec3& v);

// Adds the ribbon as a triangle strip with scalars "width", "twist", "time" and, given
// per-edge values, `extra_name`.
void append_ribbon(ProbeMesh& mesh, const std::vector<RibbonEdge>& edges, const std::string& extra_name = "",
                   const std::vector<double>& extra = {});

// A tube of `radius` and `sides` around the path (rotation-minimising frames), with the
// per-point values `values` (e.g. speed) as scalar `name`.
void append_tube(ProbeMesh& mesh, const Polyline& line, double radius, int sides, const std::string& name,
                 const std::vector<double>& values);

// An arrow glyph at p along dir: a shaft (cylinder) and a cone head, total `length`,
// all its vertices carrying `value` as scalar `name`.
void append_arrow(ProbeMesh& mesh, const Vec3& p, const Vec3& dir, double length, double radius, int sides,
                  const std::string& name, double value);

// Streamwise vorticity omega . v / |v| of the linear field v = A x + b (omega = curl v).
double streamwise_vorticity(const Eigen::Matrix3d& gradient, const Vec3& velocity);

}  // namespace fest::lemtrace
