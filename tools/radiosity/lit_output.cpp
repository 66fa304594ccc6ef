#include "lit_output.hpp"

#include "formats/mesh/attributed_ply.hpp"

namespace fest::radiosity_tool {

std::string lit_ply(const radiosity::Model& model, const radiosity::VertexValues& vv,
                    const std::vector<std::array<std::uint8_t, 3>>& colours, int object) {
  std::vector<int> new_id(vv.position.size(), -1);
  std::vector<int> keep;
  for (std::size_t v = 0; v < vv.position.size(); ++v)
    if (object < 0 || vv.object[v] == object) {
      new_id[v] = static_cast<int>(keep.size());
      keep.push_back(static_cast<int>(v));
    }
  bool floats = true;
  for (int v : keep)
    for (int c = 0; c < 3; ++c)
      if (static_cast<double>(static_cast<float>(vv.position[v][c])) != vv.position[v][c]) floats = false;
  const std::string pt = floats ? "float" : "double";
  formats::AttributedPly ply;
  ply.comments.push_back("fest radiosity: B = rad_* (radiant exitance per channel), H = irr_* (irradiance)");
  for (std::size_t o = 0; o < model.objects.size(); ++o)
    if (object < 0 || static_cast<int>(o) == object)
      ply.comments.push_back("object " + std::to_string(o) + " " + model.objects[o].name);
  const char* names[] = {"x", "y", "z", "nx", "ny", "nz", "rad_r", "rad_g", "rad_b", "irr_r", "irr_g", "irr_b",
                         "red", "green", "blue"};
  for (int k = 0; k < 15; ++k)
    ply.vertex.push_back({names[k], k < 3 ? pt : k < 12 ? "float" : "uchar", {}});
  for (int v : keep) {
    for (int c = 0; c < 3; ++c) {
      ply.vertex[c].values.push_back(vv.position[v][c]);
      ply.vertex[3 + c].values.push_back(vv.normal[v][c]);
      ply.vertex[6 + c].values.push_back(vv.B[v][c]);
      ply.vertex[9 + c].values.push_back(vv.H[v][c]);
      ply.vertex[12 + c].values.push_back(colours[v][c]);
    }
  }
  ply.face.push_back({"object_id", "int", {}});
  ply.face.push_back({"level", "uchar", {}});
  for (std::size_t k = 0; k < vv.elements.size(); ++k) {
    const radiosity::Element& el = model.elements[vv.elements[k]];
    const int obj = model.patches[el.patch].object;
    if (object >= 0 && obj != object) continue;
    std::vector<std::uint32_t> face;
    for (int c = 0; c < el.poly.n; ++c) face.push_back(static_cast<std::uint32_t>(new_id[vv.element_corners[k][c]]));
    ply.faces.push_back(face);
    ply.face[0].values.push_back(obj);
    ply.face[1].values.push_back(el.level);
  }
  return formats::write_attributed_ply(ply);
}

}  // namespace fest::radiosity_tool
