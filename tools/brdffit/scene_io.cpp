#include "scene_io.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>

#include <opencv2/core.hpp>

#include "brdffit/image_metrics.hpp"
#include "brdffit/rig_json.hpp"
#include "core/srgb.hpp"
#include "core/error.hpp"
#include "core/quote.hpp"
#include "core/file_io.hpp"
#include "core/sha256.hpp"
#include "formats/image/image_io.hpp"
#include "formats/input.hpp"
#include "formats/mesh/mesh_io.hpp"
#include "formats/table/table_io.hpp"

namespace fest::brdffit_tool {

using reflectance::LafortuneBrdf;
using reflectance::PinholeCamera;
using reflectance::Rgb;

std::string mesh_sha256(const reflectance::TriangleMesh& mesh) {
  std::string bytes;
  bytes.reserve(mesh.vertices.size() * 24 + mesh.triangles.size() * 12);
  auto put = [&](std::uint64_t v, int n) {
    for (int k = 0; k < n; ++k) bytes.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  };
  for (const auto& v : mesh.vertices)
    for (int k = 0; k < 3; ++k) {
      std::uint64_t bits;
      const double d = v[k];
      std::memcpy(&bits, &d, 8);
      put(bits, 8);
    }
  for (const auto& t : mesh.triangles)
    for (std::uint32_t i : t) put(i, 4);
  return sha256_hex(bytes);
}

LoadedMesh load_mesh(const std::string& path) {
  Mesh m = formats::parse(formats::load_input(path), formats::read_mesh);
  LoadedMesh out;
  auto& tm = out.mesh;
  for (auto v : m.vertices()) {
    const auto& p = m.point(v);
    tm.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> idx;
    for (auto v : m.fv_range(f)) idx.push_back(static_cast<std::uint32_t>(v.idx()));
    for (std::size_t k = 1; k + 1 < idx.size(); ++k) tm.triangles.push_back({idx[0], idx[k], idx[k + 1]});
  }
  if (tm.triangles.empty()) throw bad_input("the mesh has no faces ({})", path);
  for (const auto& v : tm.vertices)
    if (!v.allFinite()) throw bad_input("the mesh has a non-finite vertex coordinate ({})", path);
  out.had_normals = m.has_vertex_normals();
  if (out.had_normals) {
    for (auto v : m.vertices()) {
      const auto& n = m.normal(v);
      Eigen::Vector3d e(n[0], n[1], n[2]);
      tm.normals.push_back(e.norm() > 0 && e.allFinite() ? Eigen::Vector3d(e.normalized()) : Eigen::Vector3d::UnitZ());
    }
  } else {
    reflectance::compute_vertex_normals(tm);
  }
  out.sha256 = mesh_sha256(tm);
  return out;
}

// Refined normals of `brdffit normals` (normals.ply: one point per lumitexel, in order).
std::vector<Eigen::Vector3d> load_refined_normals(const std::string& path, std::size_t lumitexels) {
  const Mesh m = formats::parse(formats::load_input(path), formats::read_mesh);
  if (!m.has_vertex_normals()) throw bad_input("the normals file has no nx ny nz ({})", path);
  if (m.n_vertices() != lumitexels)
    throw bad_input("the normals file holds {} points, the lumitexel file {} lumitexels ({})", m.n_vertices(), lumitexels,
                    path);
  std::vector<Eigen::Vector3d> out;
  out.reserve(lumitexels);
  for (auto v : m.vertices()) {
    const auto& n = m.normal(v);
    const Eigen::Vector3d e(n[0], n[1], n[2]);
    if (!e.allFinite() || e.norm() < 1e-9) throw bad_input("point {} has no usable normal ({})", v.idx(), path);
    out.push_back(e.normalized());
  }
  return out;
}

std::string encode_atlas_ply(const reflectance::TriangleMesh& tm, const brdffit::TextureAtlas& atlas) {
  Mesh m;
  m.request_vertex_normals();
  m.request_vertex_texcoords2D();
  for (std::size_t t = 0; t < tm.triangles.size(); ++t) {
    Mesh::VertexHandle vh[3];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = tm.triangles[t][static_cast<std::size_t>(k)];
      const auto& p = tm.vertices[v];
      const auto& n = tm.normals[v];
      const Eigen::Vector2d uv = atlas.uv(t, k);
      vh[k] = m.add_vertex(Mesh::Point(p.x(), p.y(), p.z()));
      m.set_normal(vh[k], Mesh::Normal(n.x(), n.y(), n.z()));
      m.set_texcoord2D(vh[k], Mesh::TexCoord2D(static_cast<float>(uv.x()), static_cast<float>(1 - uv.y())));
    }
    m.add_face(vh[0], vh[1], vh[2]);
  }
  return formats::write_mesh(m, formats::Format::ply);
}

std::string encode_mesh_ply(const reflectance::TriangleMesh& tm) {
  Mesh m;
  m.request_vertex_normals();
  std::vector<Mesh::VertexHandle> vh;
  for (std::size_t i = 0; i < tm.vertices.size(); ++i) {
    const auto& p = tm.vertices[i];
    vh.push_back(m.add_vertex(Mesh::Point(p.x(), p.y(), p.z())));
    const auto& n = tm.normals[i];
    m.set_normal(vh.back(), Mesh::Normal(n.x(), n.y(), n.z()));
  }
  for (const auto& t : tm.triangles) m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
  return formats::write_mesh(m, formats::Format::ply);
}

nlohmann::json load_json(const std::string& path) {
  const formats::Input in = formats::load_input(path);
  try {
    return formats::read_json(in.bytes);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), path));
  }
}

namespace {

Rgb rgb_of(const nlohmann::json& j, const std::string& where, const char* key) {
  if (!j.is_array() || j.size() != 3) throw bad_input("\"{}\" must hold RGB triples ({})", key, where);
  Rgb c;
  for (int k = 0; k < 3; ++k) {
    if (!j[static_cast<std::size_t>(k)].is_number()) throw bad_input("\"{}\" must hold numbers ({})", key, where);
    c[k] = j[static_cast<std::size_t>(k)].get<double>();
    if (!std::isfinite(c[k])) throw bad_input("\"{}\" holds a non-finite number ({})", key, where);
  }
  return c;
}

}  // namespace

LafortuneBrdf brdf_from_json(const nlohmann::json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("model") || j["model"] != "lafortune")
    throw bad_input("a BRDF must be an object with \"model\": \"lafortune\" ({})", where);
  LafortuneBrdf b;
  b.rho_d = rgb_of(j.value("rho_d", nlohmann::json()), where, "rho_d");
  const auto& cxy = j.value("Cxy", nlohmann::json::array());
  const auto& cz = j.value("Cz", nlohmann::json::array());
  const auto& n = j.value("N", nlohmann::json::array());
  if (!cxy.is_array() || !cz.is_array() || !n.is_array() || cxy.size() != cz.size() || cz.size() != n.size())
    throw bad_input("\"Cxy\", \"Cz\" and \"N\" must list the same number of lobes ({})", where);
  for (std::size_t k = 0; k < cxy.size(); ++k)
    b.lobes.push_back({rgb_of(cxy[k], where, "Cxy"), rgb_of(cz[k], where, "Cz"), rgb_of(n[k], where, "N")});
  return b;
}

reflectance::SurfaceMaterials materials_from_json(const nlohmann::json& j, const reflectance::TriangleMesh& mesh,
                                                  const std::string& where) {
  reflectance::SurfaceMaterials m;
  if (!j.is_object() || !j.contains("materials") || !j["materials"].is_array() || j["materials"].empty())
    throw bad_input("the materials file needs a non-empty \"materials\" array ({})", where);
  for (std::size_t i = 0; i < j["materials"].size(); ++i)
    m.brdfs.push_back(brdf_from_json(j["materials"][i], where + ", material " + std::to_string(i)));
  try {
    if (j.contains("vertex_weights")) {
      const auto& w = j["vertex_weights"];
      if (!w.is_array() || w.size() != mesh.vertices.size())
        throw bad_input("\"vertex_weights\" needs one row per vertex ({} vertices) ({})", mesh.vertices.size(), where);
      for (const auto& row : w) {
        if (!row.is_array() || row.size() != m.brdfs.size())
          throw bad_input("every \"vertex_weights\" row needs {} weights ({})", m.brdfs.size(), where);
        for (const auto& x : row) {
          // Checked before narrowing to float (1e300 does not fit; fuzz_brdffit_json).
          if (!x.is_number() || !(x.get<double>() >= 0) || x.get<double>() > 1e30)
            throw bad_input("vertex weights must be numbers in [0, 1e30], not {} ({})", quoted_bytes(x.dump()), where);
          m.vertex_weights.push_back(x.get<float>());
        }
      }
    } else if (j.contains("triangle_material")) {
      for (const auto& x : j["triangle_material"]) {
        if (!x.is_number_integer()) throw bad_input("material ids must be integers, not {} ({})", quoted_bytes(x.dump()), where);
        const auto id = x.get<long long>();
        if (id < 0 || id >= static_cast<long long>(m.brdfs.size()))
          throw bad_input("material id {} outside 0..{} ({})", id, m.brdfs.size() - 1, where);
        m.triangle_material.push_back(static_cast<std::uint16_t>(id));
      }
      if (m.triangle_material.size() != mesh.triangles.size())
        throw bad_input("{} material ids for {} triangles ({})", m.triangle_material.size(), mesh.triangles.size(),
                        where);
    } else if (m.brdfs.size() == 1) {
      m.triangle_material.assign(mesh.triangles.size(), 0);
    } else {
      throw bad_input("several materials need \"triangle_material\" or \"vertex_weights\" ({})", where);
    }
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("materials: {} ({})", json_failure_words(e.what(), 0, {}), where);
  }
  return m;
}

Rig load_rig(const std::string& path, const std::string& root_arg) {
  Rig rig;
  rig.doc = load_json(path);
  const brdffit::RigDocument d = brdffit::decode_rig(rig.doc, path);
  rig.frame = d.frame;
  std::filesystem::path root = root_arg;
  if (root_arg.empty()) {
    // fest-capture(5) RIG: file and mask are relative to "session", itself relative to
    // the rig's folder (hdrmerge writes "sess", synth ".").
    root = is_stdio(path) ? std::filesystem::path(".") : std::filesystem::path(path).parent_path();
    if (!d.session.empty()) root /= d.session;
  }
  for (const brdffit::RigEntry& e : d.images) {
    RigImage img;
    img.file = e.file;
    img.file_path = (root / e.file).string();
    if (e.has_mask) {
      img.mask = e.mask;
      img.mask_path = (root / e.mask).string();
    }
    img.angle_index = e.angle_index;
    img.angle_deg = e.angle_deg;
    img.view = e.view;
    img.light_id = e.light_id;
    rig.images.push_back(img);
  }
  return rig;
}

void load_radiance(const std::string& path, cv::Mat& rgb, cv::Mat& valid) {
  Image img = formats::parse(formats::load_input(path), formats::read_image);
  cv::Mat f;
  if (img.pixels.depth() != CV_32F)
    throw bad_input("{}-bit integer image: radiance must be float (EXR or PFM) ({})",
                    img.pixels.depth() == CV_8U ? 8 : 16, path);
  f = img.pixels;
  valid.release();
  std::vector<cv::Mat> planes;
  cv::split(f, planes);
  if (planes.size() == 1 || planes.size() == 2) {
    if (planes.size() == 2) valid = planes[1];
    cv::merge(std::vector<cv::Mat>{planes[0], planes[0], planes[0]}, rgb);
  } else {
    if (planes.size() == 4) valid = planes[3];
    cv::merge(std::vector<cv::Mat>{planes[0], planes[1], planes[2]}, rgb);
  }
}

cv::Mat load_mask(const std::string& path) {
  Image img = formats::parse(formats::load_input(path), formats::read_image);
  cv::Mat m = img.pixels;
  if (m.channels() > 1) {
    std::vector<cv::Mat> planes;
    cv::split(m, planes);
    m = planes[0];
  }
  cv::Mat out = m > 0;  // nonzero = object, for every depth
  return out;
}

std::string encode_exr(const cv::Mat& rgb) {
  return formats::write_image(Image{rgb, ColorSpace::linear}, formats::Format::exr, {});
}

std::string encode_png(const cv::Mat& mat) { return formats::write_image(Image{mat, ColorSpace::srgb}, formats::Format::png); }

cv::Mat tonemap(const cv::Mat& rgb, double exposure) {
  cv::Mat out(rgb.size(), CV_8UC3);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x) {
      const cv::Vec3f& p = rgb.at<cv::Vec3f>(y, x);
      cv::Vec3b& o = out.at<cv::Vec3b>(y, x);
      for (int c = 0; c < 3; ++c)
        o[c] = static_cast<std::uint8_t>(std::lround(255 * linear_to_srgb(std::isfinite(p[c]) ? exposure * p[c] : 0)));
    }
  return out;
}

void refuse_binary_terminal(const std::string& path, const char* advice) {
  if (is_stdio(path) && isatty(STDOUT_FILENO)) throw usage_error("refusing to write binary to a terminal ({})", advice);
}

void write_binary(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  refuse_binary_terminal(path);
  write_output(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

void write_report(const std::string& path, const nlohmann::json& j) {
  if (!path.empty()) write_output(path, formats::write_json(j));
}

reflectance::EnvironmentMap load_environment(const std::string& path) {
  cv::Mat rgb, valid;
  load_radiance(path, rgb, valid);
  reflectance::EnvironmentMap env;
  env.width = rgb.cols;
  env.height = rgb.rows;
  env.rgb.resize(static_cast<std::size_t>(rgb.cols) * rgb.rows * 3);
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = rgb.at<cv::Vec3f>(y, x)[c];
        env.rgb[(static_cast<std::size_t>(y) * rgb.cols + x) * 3 + static_cast<std::size_t>(c)] = std::isfinite(v) ? v : 0.f;
      }
  return env;
}

}  // namespace fest::brdffit_tool
