#include "volume_input.hpp"

#include <string_view>
#include <vector>


#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "fluidsim/frame.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/input.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::volwave_tool {

namespace {

// "velocity.y" -> ("velocity", 1); "density" -> ("density", -1).
std::pair<std::string, int> split_component(const std::string& field) {
  const auto dot = field.rfind('.');
  if (dot != std::string::npos && dot + 2 == field.size()) {
    const char c = field.back();
    if (c >= 'x' && c <= 'z') return {field.substr(0, dot), c - 'x'};
    if (c >= '0' && c <= '9') return {field.substr(0, dot), c - '0'};
  }
  return {field, -1};
}

struct Candidate {
  std::string name;
  int components;
};

std::string list_names(const std::vector<Candidate>& c) {
  std::string s;
  for (const auto& x : c) s += (s.empty() ? "" : ", ") + x.name + (x.components > 1 ? fmt::format("[{}]", x.components) : "");
  return s;
}

// Picks one (field, component) among candidates, or refuses naming them.
std::pair<std::size_t, int> choose(const std::vector<Candidate>& c, const std::string& field, const std::string& where) {
  if (c.empty()) throw bad_input("no scalar arrays to code ({})", where);
  if (field.empty()) {
    if (c.size() == 1 && c[0].components == 1) return {0, 0};
    throw bad_input("{} fields ({}): name one with --field (a component as name.x) ({})", c.size(), list_names(c), where);
  }
  auto [name, comp] = split_component(field);
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (c[i].name == field && c[i].components == 1) return {i, 0};
    if (c[i].name == name && comp >= 0) {
      if (comp >= c[i].components)
        throw bad_input("field {} has {} components, no component {} ({})", name, c[i].components, comp, where);
      return {i, comp};
    }
    if (c[i].name == field) throw bad_input("field {} has {} components: name one as {}.x ({})", field, c[i].components, field, where);
  }
  throw bad_input("no field {} (have {}) ({})", field, list_names(c), where);
}

Volume from_frame_stream(const std::string& bytes, const InputSelect& sel, const std::string& where) {
  std::vector<fluidsim::Frame> frames;
  std::size_t pos = 0;
  long n = 0;
  while (pos < bytes.size()) {
    fluidsim::Frame f;
    pos = fluidsim::decode_frame(bytes, pos, f, where, n++);
    if (sel.frame < 0 || static_cast<long>(frames.size()) <= sel.frame) frames.push_back(std::move(f));
  }
  std::size_t which = 0;
  if (sel.frame < 0) {
    if (frames.size() != 1)
      throw bad_input("frame stream of {} frames: choose one with --frame ({})", frames.size(), where);
  } else {
    if (static_cast<std::size_t>(sel.frame) >= frames.size())
      throw bad_input("frame stream has {} frames, no frame {} ({})", n, sel.frame, where);
    which = static_cast<std::size_t>(sel.frame);
  }
  const fluidsim::Frame& f = frames[which];
  std::vector<Candidate> cands;
  for (const auto& fd : f.fields) cands.push_back({fd.name, fd.components});
  const auto [idx, comp] = choose(cands, sel.field, where);
  int channel = 0;
  for (std::size_t i = 0; i < idx; ++i) channel += f.fields[i].components;
  Volume v;
  v.resize(static_cast<std::size_t>(f.size[0]), static_cast<std::size_t>(f.size[1]), static_cast<std::size_t>(f.size[2]));
  v.spacing = {f.spacing, f.spacing, f.spacing};
  v.type = f.float64 ? ScalarType::f64 : ScalarType::f32;
  v.voxels = f.component(channel + comp);
  return v;
}

Volume from_image_data(const Dataset& img, const InputSelect& sel, const std::string& where) {
  const auto d = img.dimensions();
  std::vector<Candidate> cands;
  std::vector<const DataArray*> arrays;
  for (std::size_t a = 0; a < img.point_data.size(); ++a) {
    const DataArray& arr = img.point_data[a];
    if (!arr.numeric()) continue;  // string arrays hold no samples
    cands.push_back({arr.name.empty() ? fmt::format("array{}", a) : arr.name, arr.components});
    arrays.push_back(&arr);
  }
  const auto [idx, comp] = choose(cands, sel.field, where);
  const DataArray* arr = arrays[idx];
  Volume v;
  v.resize(static_cast<std::size_t>(d[0]), static_cast<std::size_t>(d[1]), static_cast<std::size_t>(d[2]));
  v.spacing = {img.spacing[0], img.spacing[1], img.spacing[2]};
  v.origin = {img.origin[0], img.origin[1], img.origin[2]};
  switch (arr->type) {
    case vtk_type::unsigned_char: v.type = ScalarType::u8; break;
    case vtk_type::signed_char: case vtk_type::char_: v.type = ScalarType::i8; break;
    case vtk_type::unsigned_short: v.type = ScalarType::u16; break;
    case vtk_type::short_: v.type = ScalarType::i16; break;
    case vtk_type::unsigned_int: v.type = ScalarType::u32; break;
    case vtk_type::int_: v.type = ScalarType::i32; break;
    case vtk_type::float_: v.type = ScalarType::f32; break;
    default: v.type = ScalarType::f64; break;
  }
  if (arr->tuples() != v.size())
    throw bad_input("array {} has {} values for {} points ({})", cands[idx].name, arr->tuples(), v.size(), where);
  for (std::size_t i = 0; i < v.size(); ++i) v.voxels[i] = arr->component(i, comp);
  return v;
}

}  // namespace

Volume read_any_volume(const std::string& path, const InputSelect& select) {
  const std::string where = input_name(path);
  formats::Input in = formats::load_input(path);
  if (in.bytes.empty()) throw bad_input("empty input ({})", where);
  const std::string_view b(in.bytes);
  const auto header_end = b.find("\n\n");
  if (b.rfind("NRRD", 0) == 0 && b.find("# fest-frame:") < header_end) return from_frame_stream(in.bytes, select, where);
  if (formats::kind_of(in.format) == formats::Kind::volume) {
    if (!select.field.empty() || select.frame >= 0)
      throw bad_input("--field/--frame apply to VTI and frame streams; {} holds one scalar volume ({})",
                      formats::format_name(in.format), where);
    return formats::parse(in, formats::read_volume);
  }
  if (in.format == formats::Format::vti) {
    const Dataset img = formats::parse(in, formats::read_dataset);
    if (img.kind != DatasetKind::image) throw bad_input("VTI input holds no image data ({})", where);
    return from_image_data(img, select, where);
  }
  throw bad_input("expected a volume (NIfTI, NRRD, MHA, VTI or a frame stream), got {} ({})",
                  formats::format_name(in.format), where);
}

void write_any_volume(const Volume& v, const std::string& path, const std::string& to) {
  formats::OutputFormat of{formats::Format::nrrd, false};
  if (!to.empty()) of = formats::output_format_from_name(to);
  else if (!is_stdio(path)) of = formats::output_format_from_path(path);
  if (formats::kind_of(of.format) != formats::Kind::volume)
    throw usage_error("cannot write a volume as {} (use nii, nrrd or mha)", formats::format_name(of.format));
  formats::store_output(path, formats::write_volume(v, of.format), of.gzip);
}

}  // namespace fest::volwave_tool
