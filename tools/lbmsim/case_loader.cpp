// Case file + geometry files -> Case and Flags.
#include "case_loader.hpp"

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/quote.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/volume/volume_io.hpp"
#include "lbm/case_json.hpp"

namespace fest::lbmsim_tool {

using nlohmann::json;

namespace {

std::string resolve(const std::string& base_dir, const std::string& file) {
  if (file.empty() || file == "-" || std::filesystem::path(file).is_absolute() || base_dir.empty()) return file;
  return (std::filesystem::path(base_dir) / file).string();
}

}  // namespace

lbm::TriangleSoup read_closed_mesh(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  if (formats::kind_of(in.format) != formats::Kind::mesh)
    throw bad_input("not a mesh: {} data ({})", formats::format_name(in.format), path);
  const Mesh mesh = formats::parse(in, formats::read_mesh);
  lbm::TriangleSoup soup;
  soup.vertices.reserve(mesh.n_vertices());
  for (auto v : mesh.vertices()) {
    const auto p = mesh.point(v);
    soup.vertices.push_back({p[0], p[1], p[2]});
  }
  for (auto f : mesh.faces()) {
    std::vector<int> ids;
    for (auto v : mesh.fv_range(f)) ids.push_back(v.idx());
    for (std::size_t k = 1; k + 1 < ids.size(); ++k) soup.triangles.push_back({ids[0], ids[k], ids[k + 1]});
  }
  if (soup.triangles.empty()) throw bad_input("mesh has no faces ({})", path);
  const auto open = lbm::count_open_edges(soup);
  if (open.boundary > 0 || open.nonmanifold > 0)
    throw bad_input("mesh is not closed: {} boundary edges, {} edges shared by more than two faces; "
                    "voxelization needs a watertight mesh ({})",
                    open.boundary, open.nonmanifold, path);
  return soup;
}

std::string override_text(const lbm::CaseOverride& o) {
  std::string key;
  for (const std::string& part : o.path) key += (key.empty() ? "" : ".") + part;
  return key + "=" + o.value;
}

LoadedCase load_case(const std::string& path, const std::vector<lbm::CaseOverride>& sets) {
  LoadedCase L;
  L.where = input_name(path);
  const std::string text = read_input(path.empty() ? "-" : path);
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) throw bad_input("empty case ({})", L.where);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw bad_input("case: {} ({})", json_failure_words(e.what(), e.byte, text), L.where);
  } catch (const json::exception& e) {  // out_of_range: a number beyond double's range
    throw bad_input("case: {} ({})", json_failure_words(e.what(), 0, text), L.where);
  }
  for (const lbm::CaseOverride& s : sets) {
    if (!doc.is_object()) throw usage_error("--set needs a case object");
    try {
      lbm::apply_override(doc, s);
    } catch (const Error& e) {
      throw usage_error("--set \"{}\": {}", override_text(s), e.what());
    }
  }
  try {
    L.c = lbm::parse_case(doc, L.where);
  } catch (const Error& e) {
    // A value that came from --set is a usage error (status 2), not bad input.
    const std::string what = e.what();
    for (const lbm::CaseOverride& s : sets) {
      const std::string given = override_text(s);
      const std::string key = given.substr(0, given.find('='));
      if (what.find(key) != std::string::npos) throw usage_error("--set {}: {}", given, what);
    }
    throw;
  }
  const std::string dir =
      path == "-" || path.empty() ? std::string() : std::filesystem::path(path).parent_path().string();
  L.flags = lbm::shape_flags(L.c);
  const lbm::Case& c = L.c;
  if (!c.mask_file.empty()) {
    const std::string file = resolve(dir, c.mask_file);
    const formats::Input in = formats::load_input(file);
    if (formats::kind_of(in.format) != formats::Kind::image) throw bad_input("mask is not an image ({})", file);
    const Image img = formats::parse(in, formats::read_image);
    const cv::Mat& m = img.pixels;
    if (m.cols != c.size[0] || m.rows != c.size[1])
      throw bad_input("mask is {}x{} but size is {}x{} ({})", m.cols, m.rows, c.size[0], c.size[1], file);
    if (m.depth() != CV_8U || m.channels() != 1) throw bad_input("mask must be 8-bit grey: pixel value = flag id ({})", file);
    // Image row 0 is the top: lattice y grows upwards.
    for (int y = 0; y < c.size[1]; ++y)
      for (int x = 0; x < c.size[0]; ++x) {
        const std::uint8_t v = m.at<std::uint8_t>(c.size[1] - 1 - y, x);
        if (v >= 2 && v <= 5) throw bad_input("mask pixel ({}, {}) = {}: flags 2..5 are set on faces ({})", x, y, v, file);
        if (v) L.flags.id[L.flags.index(x, y, 0)] = v;
      }
  }
  if (!c.flags_file.empty()) {
    const std::string file = resolve(dir, c.flags_file);
    const formats::Input in = formats::load_input(file);
    if (formats::kind_of(in.format) != formats::Kind::volume) throw bad_input("flags file is not a volume ({})", file);
    const Volume v = formats::parse(in, formats::read_volume);
    if (static_cast<int>(v.dims[0]) != c.size[0] || static_cast<int>(v.dims[1]) != c.size[1] ||
        static_cast<int>(v.dims[2]) != c.size[2])
      throw bad_input("flags volume is {}x{}x{} but size is {}x{}x{} ({})", v.dims[0], v.dims[1], v.dims[2], c.size[0],
                      c.size[1], c.size[2], file);
    for (std::size_t k = 0; k < v.voxels.size(); ++k) {
      const double d = v.voxels[k];
      if (d < 0 || d > 255 || d != static_cast<int>(d)) throw bad_input("flags volume holds {} (not a flag id 0..255) ({})", d, file);
      const int id = static_cast<int>(d);
      if (id >= 2 && id <= 5) throw bad_input("flags volume holds {}: flags 2..5 are set on faces ({})", id, file);
      if (id) L.flags.id[k] = static_cast<std::uint8_t>(id);
    }
  }
  for (const lbm::MeshGeometry& m : c.meshes) {
    const std::string file = resolve(dir, m.file);
    const lbm::TriangleSoup soup = read_closed_mesh(file);
    lbm::VoxelizeOptions vo;
    vo.fit_box = m.fit_box;
    vo.margin = m.margin;
    vo.region = m.region;
    vo.flag = m.flag;
    try {
      lbm::voxelize(soup, vo, L.flags);
    } catch (const Error& e) {
      throw Error(e.status(), with_location(e.what(), file));
    }
  }
  return L;
}

}  // namespace fest::lbmsim_tool
