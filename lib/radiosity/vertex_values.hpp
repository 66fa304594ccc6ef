#pragma once
// Vertex radiosity by nodal averaging (docs/radiosity.md §6, Cohen & Greenberg): a
// vertex is shared by the elements of one object whose normals lie within the crease
// angle of each other (never across objects, so objects stay independent); its B and H
// are the area-weighted means over those elements. Display colours map L = B / pi through
// an exposure and the 1/2.2 display gamma.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "radiosity/model.hpp"

namespace fest::radiosity {

struct VertexValues {
  std::vector<Eigen::Vector3d> position, normal;
  std::vector<Rgb> B, H;
  std::vector<int> object;
  std::vector<int> elements;                      // the active elements, in index order
  std::vector<std::array<int, 4>> element_corners;  // their corners as vertex ids
};

VertexValues vertex_values(const Model& model, double crease_degrees);

// c = 255 clamp((k L)^(1/2.2)), L = B / pi; k = exposure, or 1 / (99th percentile of the
// vertex luminance) when exposure <= 0, over the vertices with reflector[v] != 0 when
// any (emitters would otherwise set the exposure whenever they hold more than 1 % of the
// vertices). Returns the k used through `used`.
std::vector<std::array<std::uint8_t, 3>> display_colours(const std::vector<Rgb>& B, double exposure, double* used,
                                                         const std::vector<std::uint8_t>& reflector = {});
// 1 for the vertices of objects that emit nothing.
std::vector<std::uint8_t> reflector_vertices(const Model& model, const VertexValues& vv);

struct RadiosityRange {
  Rgb min = Rgb::Zero(), max = Rgb::Zero(), mean = Rgb::Zero();  // mean weighted by area
};
// Over all active elements.
RadiosityRange radiosity_range(const Model& model);

}  // namespace fest::radiosity
