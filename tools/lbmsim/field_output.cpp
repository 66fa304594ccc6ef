// Field files of lbmsim (docs/lbmsim.md "Output").
#include "field_output.hpp"

#include <cstdio>
#include <regex>


#include "core/error.hpp"
#include "fluidsim/frame.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::lbmsim_tool {

std::string encode_vti(const FieldFrame& f, bool float64, bool zlib) {
  Dataset img = Dataset::image_data({f.size[0], f.size[1], f.size[2]}, {f.spacing, f.spacing, f.spacing}, {0, 0, 0});
  bool have_scalars = false;
  for (const lbm::Field& field : f.fields) {
    DataArray arr = DataArray::from_doubles(field.name, field.components, field.values,
                                            float64 ? vtk_type::double_ : vtk_type::float_);
    // Active vectors: velocity; active scalars: the first one-component field.
    if (field.name == "velocity" && field.components == 3) {
      arr.attribute = 1;
    } else if (field.components == 1 && !have_scalars) {
      arr.attribute = 0;
      have_scalars = true;
    }
    img.point_data.push_back(std::move(arr));
  }
  formats::DatasetWriteOptions o;
  o.zlib = zlib;
  return formats::write_dataset(img, formats::Format::vti, o);
}

namespace {

fluidsim::Frame to_frame(const FieldFrame& f, const std::vector<const lbm::Field*>& fields, bool float64) {
  fluidsim::Frame fr;
  fr.index = f.index;
  fr.time = f.time;
  fr.dim = f.dim;
  fr.size = f.size;
  fr.spacing = f.spacing;
  fr.float64 = float64;
  int C = 0;
  for (const lbm::Field* field : fields) {
    fr.fields.push_back({field->name, field->components});
    C += field->components;
  }
  const std::size_t N = fr.nodes();
  fr.data.resize(N * C);
  int c0 = 0;
  for (const lbm::Field* field : fields) {
    for (std::size_t n = 0; n < N; ++n)
      for (int k = 0; k < field->components; ++k) fr.data[n * C + c0 + k] = field->values[n * field->components + k];
    c0 += field->components;
  }
  return fr;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> encode_nrrd(const FieldFrame& f, const std::string& path, bool float64) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto slash = path.find_last_of('/');
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) dot = path.size();
  for (const lbm::Field& field : f.fields) {
    const std::string name = path.substr(0, dot) + "_" + field.name + path.substr(dot);
    if (field.components == 1) {
      Volume v;
      v.dims = {static_cast<std::size_t>(f.size[0]), static_cast<std::size_t>(f.size[1]), static_cast<std::size_t>(f.size[2])};
      v.spacing = {f.spacing, f.spacing, f.spacing};
      v.type = float64 ? ScalarType::f64 : ScalarType::f32;
      v.voxels = field.values;
      out.emplace_back(name, formats::write_volume(v, formats::Format::nrrd));
    } else {
      out.emplace_back(name, fluidsim::encode_frame(to_frame(f, {&field}, float64)));
    }
  }
  return out;
}

std::string encode_stream_frame(const FieldFrame& f, bool float64) {
  std::vector<const lbm::Field*> all;
  for (const lbm::Field& field : f.fields) all.push_back(&field);
  return fluidsim::encode_frame(to_frame(f, all, float64));
}

std::string encode_pvd(const std::vector<std::pair<double, std::string>>& entries) {
  std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n";
  for (const auto& [t, file] : entries)
    s += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t, file);
  s += "  </Collection>\n</VTKFile>\n";
  return s;
}

bool has_index_conversion(const std::string& pattern) {
  static const std::regex conv("%0?[0-9]*l?d");
  return std::regex_search(pattern, conv);
}

std::string expand_pattern(const std::string& pattern, long index) {
  static const std::regex conv("%(0?[0-9]*)l?d");
  std::smatch m;
  if (!std::regex_search(pattern, m, conv)) return pattern;
  char buf[64];
  const std::string spec = "%" + m[1].str() + "ld";
  std::snprintf(buf, sizeof buf, spec.c_str(), index);
  return m.prefix().str() + buf + m.suffix().str();
}

}  // namespace fest::lbmsim_tool
