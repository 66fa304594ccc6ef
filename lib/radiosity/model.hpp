#pragma once
// The discretised scene of docs/radiosity.md §2 and §2: objects (name, reflectance,
// emission) made of input faces, faces split into patches (the shooters), patches into
// elements (the receivers). Piecewise-constant radiosity B lives on the elements; a
// patch's B is the area average of its elements, and a patch carries the unshot U and
// the total shot S of progressive refinement (§4).

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fest::radiosity {

using Rgb = Eigen::Array3d;

// A planar convex polygon with 3 or 4 corners (counter-clockwise about its normal).
struct Polygon {
  int n = 0;
  std::array<Eigen::Vector3d, 4> p;

  double area() const;
  Eigen::Vector3d centroid() const;   // area centroid
  Eigen::Vector3d normal() const;     // unit (Newell's method); zero for a degenerate polygon
  double longest_edge() const;
  // The point of parameters (s, t) in [0,1]^2: bilinear for quads, the sqrt warp
  // (uniform in area) for triangles.
  Eigen::Vector3d sample(double s, double t) const;
};

struct Object {
  std::string name;
  Rgb reflectance = Rgb::Zero();
  Rgb emission = Rgb::Zero();  // exitance E (W m^-2 per channel)
};

struct Element {
  Polygon poly;
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
  int patch = -1;
  int level = 0;        // adaptive subdivision level (§5)
  bool active = true;   // leaves are active; a split element hands over to its children
  Rgb B = Rgb::Zero();  // radiosity
  Rgb H = Rgb::Zero();  // irradiance accumulated from shots (§4 step 4)
};

struct Patch {
  Polygon poly;
  double area = 0;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
  int object = -1;
  int face = -1;        // the input face (within its object) it was cut from
  Rgb rho = Rgb::Zero(), E = Rgb::Zero();
  Rgb B = Rgb::Zero(), U = Rgb::Zero(), S = Rgb::Zero();
  std::vector<int> elements;  // active elements (leaves) covering the patch
};

struct Model {
  std::vector<Object> objects;
  std::vector<Patch> patches;
  std::vector<Element> elements;   // every element ever made; the active ones tile the scene
  std::vector<Polygon> occluders;  // the input faces, for shadow rays
  double diagonal = 1;             // bounding-box diagonal of the scene

  std::vector<int> active_elements() const;
  // Resets B = E, U = E, S = 0, H = 0 (the start of §4).
  void reset_solution();
  // B_p as the area average of the patch's active elements.
  void update_patch_radiosity(int p);
};

// A patch's or an element's polygon with the quantities every shot reads from it.
template <class Piece>
void set_polygon(Piece& piece, const Polygon& p) {
  piece.poly = p;
  piece.area = p.area();
  piece.centroid = p.centroid();
  piece.normal = p.normal();
}

inline double luminance(const Rgb& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

}  // namespace fest::radiosity
