#include "formats/volume_source/volume_source.hpp"

#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/file_io.hpp"
#include "formats/concatenated.hpp"
#include "formats/dataset/dataset_io.hpp"
#include "formats/volume/voxel_codec.hpp"
#include "formats/volume/volume_io.hpp"

namespace fest::formats {
namespace {

constexpr std::string_view kTag = "# fest-frame:";

std::string_view next_line(std::string_view bytes, std::size_t& pos) {
  const std::size_t end = bytes.find('\n', pos);
  if (end == std::string_view::npos) throw bad_input("NRRD frame header without an end");
  const std::string_view line = bytes.substr(pos, end - pos);
  pos = end + 1;
  return line;
}

double component_value(const double* v, int components, VectorComponent c) {
  if (components == 1) return v[0];
  if (c == VectorComponent::x) return v[0];
  if (c == VectorComponent::y) return components > 1 ? v[1] : 0.0;
  if (c == VectorComponent::z) return components > 2 ? v[2] : 0.0;
  double s = 0;
  for (int k = 0; k < components; ++k) s += v[k] * v[k];
  return std::sqrt(s);
}

Volume decode_frame(const StreamFrame& fr, const VolumeSourceOptions& o);

Volume from_frames(const Input& in, const VolumeSourceOptions& o) {
  const auto frames = split_frame_stream(in.bytes, in.name);
  if (frames.empty()) throw bad_input("empty frame stream ({})", in.name);
  const long n = static_cast<long>(frames.size());
  const long f = o.frame < 0 ? n - 1 : o.frame;
  if (f >= n) throw usage_error("frame {} requested, the stream has {} frames (0..{})", f, n, n - 1);
  return decode_frame(frames[static_cast<std::size_t>(f)], o);
}

// One frame of a 4-D volume (a time series): --frame K, by default the last, as for
// frame streams; a 3-D volume is its own only frame.
Volume one_frame(Volume v, long frame, const std::string& where) {
  if (v.frames <= 1) return v;
  const long n = static_cast<long>(v.frames);
  const long f = frame < 0 ? n - 1 : frame;
  if (f >= n) throw usage_error("frame {} requested, the series has {} frames (0..{}) ({})", f, n, n - 1, where);
  return v.frame(static_cast<std::size_t>(f));
}

Volume decode_frame(const StreamFrame& fr, const VolumeSourceOptions& o) {
  int channel = 0, comps = fr.fields.front().second;
  bool found = o.field.empty();
  std::string names;
  int ch = 0;
  for (const auto& [name, c] : fr.fields) {
    names += (names.empty() ? "" : ", ") + name;
    if (!found && name == o.field) found = true, channel = ch, comps = c;
    ch += c;
  }
  if (!found) throw usage_error("no field '{}' in the frame stream (fields: {})", o.field, names);
  const int channels = ch;
  Volume v;
  v.resize(fr.size[0], fr.size[1], fr.size[2]);
  for (int a = 0; a < 3; ++a) v.spacing[a] = fr.spacing[a];
  v.type = ScalarType::f32;
  std::vector<double> val(static_cast<std::size_t>(comps));
  const std::size_t bytes_per = fr.float64 ? 8 : 4;
  for (std::size_t p = 0; p < v.size(); ++p) {
    for (int c = 0; c < comps; ++c) {
      const char* src = fr.data.data() + (p * channels + channel + c) * bytes_per;
      if (fr.float64) {
        std::memcpy(&val[c], src, 8);
      } else {
        float x;
        std::memcpy(&x, src, 4);
        val[c] = x;
      }
    }
    v.voxels[p] = component_value(val.data(), comps, o.component);
  }
  return v;
}

// The point array VTK's vtkPointData would hand out: GetScalars() (the active scalars),
// GetArray(name) (the first array of that name), GetArray(0); each only when numeric.
const DataArray* pick_array(const Dataset& img, const std::string& field) {
  const std::vector<DataArray>& pd = img.point_data;
  if (!field.empty()) {
    for (const DataArray& a : pd)
      if (a.name == field) return a.numeric() ? &a : nullptr;
    return nullptr;
  }
  for (const DataArray& a : pd)
    if (a.attribute == 0 && a.numeric()) return &a;
  if (!pd.empty() && pd.front().numeric()) return &pd.front();
  return nullptr;
}

Volume from_vti(const Input& in, const VolumeSourceOptions& o) {
  const Dataset img = parse(in, read_dataset);
  if (img.kind != DatasetKind::image) throw bad_input("VTI input holds no image data ({})", in.name);
  const DataArray* arr = pick_array(img, o.field);
  if (!arr) {
    std::string names;
    for (std::size_t k = 0; k < img.point_data.size(); ++k)
      names += (k ? ", " : "") + (img.point_data[k].name.empty() ? std::string("(unnamed)") : img.point_data[k].name);
    if (o.field.empty()) throw bad_input("VTI input has no point arrays ({})", in.name);
    throw usage_error("no point array '{}' in {} (arrays: {})", o.field, in.name, names);
  }
  const auto dims = img.dimensions();
  Volume v;
  v.resize(static_cast<std::size_t>(dims[0]), static_cast<std::size_t>(dims[1]), static_cast<std::size_t>(dims[2]));
  for (int a = 0; a < 3; ++a) v.spacing[a] = img.spacing[std::size_t(a)], v.origin[a] = img.origin[std::size_t(a)];
  for (int k = 0; k < 9; ++k) v.direction[k] = img.direction[std::size_t(k)];
  const int comps = arr->components;
  if (arr->tuples() != v.size())
    throw bad_input("VTI point array has {} tuples for {} points ({})", arr->tuples(), v.size(), in.name);
  std::vector<double> t(static_cast<std::size_t>(comps));
  for (std::size_t p = 0; p < v.size(); ++p) {
    for (int c = 0; c < comps; ++c) t[std::size_t(c)] = arr->component(p, c);
    v.voxels[p] = component_value(t.data(), comps, o.component);
  }
  v.type = ScalarType::f32;
  return v;
}

}  // namespace

bool is_frame_stream(std::string_view bytes) noexcept {
  if (bytes.substr(0, 7) != "NRRD000") return false;
  const std::size_t end = bytes.find("\n\n");
  const std::size_t tag = bytes.find(kTag);
  return tag != std::string_view::npos && tag < end;
}

std::vector<StreamFrame> split_frame_stream(std::string_view stream, const std::string& where) {
  // `bytes` is the rest of the stream, from this frame on.
  return split_concatenated<StreamFrame>(stream, [&](std::string_view bytes, std::size_t index, std::size_t& length)
                                                     -> std::optional<StreamFrame> {
    std::size_t pos = 0;
    const std::string loc = fmt::format("{}, frame {}", where, index);
    if (bytes.substr(pos, 7) != "NRRD000") throw bad_input("not an NRRD frame ({})", loc);
    StreamFrame f;
    std::vector<std::size_t> sizes;
    bool have_fields = false, raw = false, little = true, have_type = false;
    std::vector<double> spacings;
    try {
      next_line(bytes, pos);
      for (;;) {
        const std::string_view line = next_line(bytes, pos);
        if (line.empty()) break;
        const std::string s(line);
        if (s.rfind(kTag, 0) == 0) {
          const std::size_t at = s.find("fields=");
          if (at == std::string::npos) throw bad_input("fest-frame line without fields=");
          std::string list = s.substr(at + 7);
          list = list.substr(0, list.find(' '));
          std::stringstream ss(list);
          for (std::string item; std::getline(ss, item, ',');) {
            const std::size_t colon = item.find(':');
            if (colon == std::string::npos || colon == 0) throw bad_input("bad fields entry '{}'", item);
            const int c = std::atoi(item.c_str() + colon + 1);
            if (c < 1 || c > 16) throw bad_input("bad component count in '{}'", item);
            f.fields.emplace_back(item.substr(0, colon), c);
          }
          have_fields = !f.fields.empty();
        } else if (s[0] == '#') {
          continue;
        } else if (s.rfind("type:", 0) == 0) {
          const std::size_t word = s.find_first_not_of(' ', 5);  // npos: "type:" with no word
          const std::string t = word == std::string::npos ? std::string() : s.substr(word);
          if (t == "float") f.float64 = false;
          else if (t == "double") f.float64 = true;
          else throw bad_input("frame type '{}' (float or double expected)", t);
          have_type = true;
        } else if (s.rfind("sizes:", 0) == 0) {
          std::stringstream ss(s.substr(6));
          for (long long v; ss >> v;) {
            if (v < 1 || v > (1 << 20)) throw bad_input("frame size {} out of range", v);
            sizes.push_back(static_cast<std::size_t>(v));
          }
        } else if (s.rfind("spacings:", 0) == 0) {
          std::stringstream ss(s.substr(9));
          for (std::string w; ss >> w;) spacings.push_back(std::strtod(w.c_str(), nullptr));
        } else if (s.rfind("encoding:", 0) == 0) {
          raw = s.find("raw") != std::string::npos;
        } else if (s.rfind("endian:", 0) == 0) {
          little = s.find("little") != std::string::npos;
        }
      }
    } catch (const Error& e) {
      throw bad_input("{} ({})", e.what(), loc);
    }
    if (!have_fields || !have_type) throw bad_input("NRRD frame without fields or type ({})", loc);
    if (!raw || !little) throw bad_input("NRRD frame must be raw little-endian ({})", loc);
    if (sizes.size() < 3 || sizes.size() > 4) throw bad_input("NRRD frame with {} axes ({})", sizes.size(), loc);
    int channels = 0;
    for (const auto& fl : f.fields) channels += fl.second;
    if (sizes[0] != static_cast<std::size_t>(channels))
      throw bad_input("NRRD frame has {} channels, its fields name {} ({})", sizes[0], channels, loc);
    f.dim = static_cast<int>(sizes.size()) - 1;
    std::size_t count = sizes[0];
    for (int a = 0; a < f.dim; ++a) {
      f.size[a] = sizes[static_cast<std::size_t>(a) + 1];
      if (spacings.size() == sizes.size() && std::isfinite(spacings[static_cast<std::size_t>(a) + 1]) && spacings[a + 1] > 0)
        f.spacing[a] = spacings[static_cast<std::size_t>(a) + 1];
      if (count > (std::size_t{1} << 40) / f.size[a]) throw bad_input("NRRD frame too large ({})", loc);
      count *= f.size[a];
    }
    const std::size_t need = count * (f.float64 ? 8 : 4);
    if (bytes.size() - pos < need)
      throw bad_input("truncated NRRD frame: expected {} bytes, got {} ({})", need, bytes.size() - pos, loc);
    f.data = bytes.substr(pos, need);
    length = pos + need;
    return f;
  });
}

RawLayout parse_raw_layout(std::string_view text) {
  std::vector<std::string> items;
  std::stringstream ss{std::string(text)};
  for (std::string item; std::getline(ss, item, ',');) items.push_back(item);
  const std::string form = fmt::format("takes NX,NY,NZ,TYPE[,little|big], not '{}'", text);
  if (items.size() < 4 || items.size() > 5) throw std::invalid_argument(form);
  RawLayout layout;
  for (int a = 0; a < 3; ++a) {
    const std::string& d = items[static_cast<std::size_t>(a)];
    char* end = nullptr;
    const long long n = std::strtoll(d.c_str(), &end, 10);
    if (d.empty() || *end || n < 1 || n > (1LL << 31)) throw std::invalid_argument(form + " (sizes are whole numbers >= 1)");
    layout.dims[static_cast<std::size_t>(a)] = static_cast<std::size_t>(n);
  }
  if (!parse_scalar_type(items[3], layout.type))
    throw std::invalid_argument(fmt::format("type '{}' is not one of uint8, int8, uint16, int16, uint32, int32, uint64, int64, float32, float64", items[3]));
  if (items.size() == 5) {
    if (items[4] != "little" && items[4] != "big") throw std::invalid_argument(fmt::format("byte order '{}' is not little or big", items[4]));
    layout.big_endian = items[4] == "big";
  }
  return layout;
}

Volume read_raw_volume(std::string_view bytes, const RawLayout& layout, const std::string& where) {
  Volume v;
  v.resize(layout.dims[0], layout.dims[1], layout.dims[2]);  // bad_input for a zero or an overflow
  v.spacing = layout.spacing;
  v.type = layout.type;
  const std::size_t size = scalar_type_size(layout.type);
  const std::size_t need = v.size() * size;
  if (bytes.size() != need)
    throw bad_input("raw volume of {}x{}x{} {} needs {} bytes, got {} ({})", layout.dims[0], layout.dims[1], layout.dims[2],
                    scalar_type_name(layout.type), need, bytes.size(), where);
  volume_detail::decode_voxels(bytes, layout.type, layout.big_endian, v.voxels);
  return v;
}

Input load_volume_input(const std::string& path, const VolumeSourceOptions& o) {
  if (!o.raw) return load_input(path);
  Input in;
  in.name = path;
  in.bytes = read_input(path);
  in.format = Format::nrrd;  // unused: raw bytes are read with the layout alone
  return in;
}

Volume read_volume_source(const Input& in, const VolumeSourceOptions& o) {
  if (o.raw) {
    if (o.frame >= 0) throw usage_error("--frame applies to frame streams and 4-D series, not raw input ({})", in.name);
    if (!o.field.empty()) throw usage_error("--field applies to VTI and frame-stream input, not raw ({})", in.name);
    return read_raw_volume(in.bytes, *o.raw, in.name);
  }
  if (is_frame_stream(in.bytes)) return from_frames(in, o);
  if (in.format == Format::vti) return from_vti(in, o);
  if (kind_of(in.format) == Kind::volume) {
    if (!o.field.empty()) throw usage_error("--field applies to VTI and frame-stream input, not {} ({})", format_name(in.format), in.name);
    return one_frame(parse(in, read_volume), o.frame, in.name);
  }
  throw bad_input("expected a volume (NIfTI, NRRD, MHA, VTI or a fest frame stream), got {} ({})", format_name(in.format), in.name);
}

VolumeFrames::VolumeFrames(const Input& in, const VolumeSourceOptions& o) : options_(o) {
  if (!o.raw && is_frame_stream(in.bytes)) {
    stream_ = split_frame_stream(in.bytes, in.name);
    if (stream_.empty()) throw bad_input("empty frame stream ({})", in.name);
    count_ = stream_.size();
    return;
  }
  if (!o.raw && kind_of(in.format) == Kind::volume && in.format != Format::vti) {
    if (!o.field.empty()) throw usage_error("--field applies to VTI and frame-stream input, not {} ({})", format_name(in.format), in.name);
    series_ = parse(in, read_volume);  // every frame of a 4-D series
  } else {
    series_ = read_volume_source(in, o);  // raw, VTI: one frame; anything else throws
  }
  count_ = series_->frames;
}

Volume VolumeFrames::frame(std::size_t t) const {
  if (!series_) return decode_frame(stream_.at(t), options_);
  return series_->frames > 1 ? series_->frame(t) : *series_;
}

}  // namespace fest::formats
