#include "fluidsim/frame.hpp"

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "fluidsim/simulator.hpp"

namespace fest::fluidsim {

int Frame::channels() const noexcept {
  int c = 0;
  for (const auto& f : fields) c += f.components;
  return c;
}

int Frame::channel_of(const std::string& name) const noexcept {
  int c = 0;
  for (const auto& f : fields) {
    if (f.name == name) return c;
    c += f.components;
  }
  return -1;
}

std::vector<double> Frame::component(int channel) const {
  const int C = channels();
  std::vector<double> out(nodes());
  for (std::size_t n = 0; n < out.size(); ++n) out[n] = data[n * C + channel];
  return out;
}

std::vector<double> Frame::magnitude(const std::string& name) const {
  const int c0 = channel_of(name);
  int comps = 1;
  for (const auto& f : fields)
    if (f.name == name) comps = f.components;
  const int C = channels();
  std::vector<double> out(nodes());
  for (std::size_t n = 0; n < out.size(); ++n) {
    if (comps == 1) {
      out[n] = data[n * C + c0];
      continue;
    }
    double s = 0.0;
    for (int k = 0; k < comps; ++k) s += data[n * C + c0 + k] * data[n * C + c0 + k];
    out[n] = std::sqrt(s);
  }
  return out;
}

std::string encode_frame(const Frame& f) {
  std::string fields;
  for (const auto& fl : f.fields) fields += (fields.empty() ? "" : ",") + fl.name + ":" + std::to_string(fl.components);
  std::string h = "NRRD0004\n";
  h += fmt::format("# fest-frame: index={} time={} fields={}\n", f.index, f.time, fields);
  h += fmt::format("type: {}\n", f.float64 ? "double" : "float");
  h += fmt::format("dimension: {}\n", f.dim + 1);
  h += fmt::format("sizes: {}", f.channels());
  for (int a = 0; a < f.dim; ++a) h += fmt::format(" {}", f.size[a]);
  h += "\nkinds: list";
  for (int a = 0; a < f.dim; ++a) h += " space";
  h += "\nspacings: nan";
  for (int a = 0; a < f.dim; ++a) h += fmt::format(" {}", f.spacing);
  h += "\nendian: little\nencoding: raw\n\n";
  const std::size_t count = f.data.size();
  std::string out = h;
  const std::size_t base = out.size();
  out.resize(base + count * (f.float64 ? 8 : 4));
  char* p = out.data() + base;
  for (std::size_t i = 0; i < count; ++i) {
    if (f.float64) {
      std::memcpy(p + 8 * i, &f.data[i], 8);
    } else {
      const float v = static_cast<float>(f.data[i]);
      std::memcpy(p + 4 * i, &v, 4);
    }
  }
  return out;
}

std::size_t decode_frame(std::string_view bytes, std::size_t offset, Frame& f, const std::string& where,
                         long frame_number) {
  const std::string loc = fmt::format("{}, frame {}", where, frame_number);
  if (bytes.substr(offset, 7) != "NRRD000") throw bad_input("not an NRRD frame ({})", loc);
  f = Frame{};
  f.index = frame_number;
  std::vector<long> sizes;
  bool raw = false, little = true, have_type = false, have_fields = false;
  std::size_t pos = offset;
  bool first = true;
  for (;;) {
    const std::size_t eol = bytes.find('\n', pos);
    if (eol == std::string_view::npos) throw bad_input("truncated NRRD frame header ({})", loc);
    std::string line(bytes.substr(pos, eol - pos));
    pos = eol + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (first) {
      first = false;
      continue;
    }
    if (line.empty()) break;
    if (line.rfind("# fest-frame:", 0) == 0) {
      std::istringstream in(line.substr(13));
      std::string tok;
      while (in >> tok) {
        const auto eq = tok.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = tok.substr(0, eq), val = tok.substr(eq + 1);
        try {
          if (key == "index") f.index = std::stol(val);
          if (key == "time") f.time = std::stod(val);
        } catch (const std::exception&) {
          throw bad_input("bad fest-frame {} \"{}\" ({})", quoted_bytes(key), quoted_bytes(val), loc);
        }
        if (key == "fields") {
          have_fields = true;
          std::istringstream fl(val);
          std::string item;
          while (std::getline(fl, item, ',')) {
            const auto colon = item.find(':');
            FrameField ff;
            ff.name = item.substr(0, colon);
            try {
              ff.components = colon == std::string::npos ? 1 : std::stoi(item.substr(colon + 1));
            } catch (const std::exception&) {
              throw bad_input("bad field \"{}\" in the fest-frame header ({})", quoted_bytes(item), loc);
            }
            if (ff.components < 1 || ff.components > 16 || ff.name.empty())
              throw bad_input("bad field \"{}\" in the fest-frame header ({})", quoted_bytes(item), loc);
            f.fields.push_back(ff);
          }
        }
      }
      continue;
    }
    if (line[0] == '#') continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) throw bad_input("malformed NRRD header line \"{}\" ({})", quoted_bytes(line), loc);
    const std::string key = line.substr(0, colon);
    std::string val = line.substr(colon + 1);
    while (!val.empty() && val.front() == ' ') val.erase(0, 1);
    if (key == "type") {
      have_type = true;
      if (val == "float") f.float64 = false;
      else if (val == "double") f.float64 = true;
      else throw bad_input("frame type must be float or double, not \"{}\" ({})", quoted_bytes(val), loc);
    } else if (key == "sizes") {
      std::istringstream in(val);
      long s;
      while (in >> s) sizes.push_back(s);
    } else if (key == "encoding") {
      raw = val == "raw";
    } else if (key == "endian") {
      little = val == "little";
    } else if (key == "spacings") {
      std::istringstream in(val);
      std::string tok;
      std::vector<std::string> toks;
      while (in >> tok) toks.push_back(tok);
      if (toks.size() >= 2) {
        double h = 0;
        try {
          h = std::stod(toks[1]);
        } catch (const std::exception&) {
        }
        if (!(h > 0) || !std::isfinite(h))
          throw bad_input("frame spacing \"{}\" is not a positive finite number ({})", quoted_bytes(toks[1]), loc);
        f.spacing = h;
      }
    }
  }
  if (!have_type) throw bad_input("NRRD frame without a type ({})", loc);
  if (!raw || !little) throw bad_input("frames must be raw little-endian NRRD ({})", loc);
  if (sizes.size() != 3 && sizes.size() != 4) throw bad_input("a frame has a channel axis and 2 or 3 space axes ({})", loc);
  f.dim = static_cast<int>(sizes.size()) - 1;
  // Checked axis by axis: four axes of 65536 would wrap the product to 0 and pass the
  // length check below with no data (fuzz_fluidsim, regress/fluidsim/).
  const std::size_t sample = f.float64 ? 8 : 4;
  std::size_t count = 1;
  for (long s : sizes) {
    if (s < 1 || s > 1 << 16) throw bad_input("frame size {} out of range ({})", s, loc);
    if (count > std::numeric_limits<std::size_t>::max() / sample / static_cast<std::size_t>(s))
      throw bad_input("frame sizes {} are too large ({})", fmt::join(sizes, " "), loc);
    count *= static_cast<std::size_t>(s);
  }
  for (int a = 0; a < f.dim; ++a) f.size[a] = static_cast<int>(sizes[a + 1]);
  if (!have_fields) f.fields.push_back({"value", static_cast<int>(sizes[0])});
  if (f.channels() != sizes[0])
    throw bad_input("fest-frame fields name {} channels, the array has {} ({})", f.channels(), sizes[0], loc);
  const std::size_t need = count * sample;
  const std::size_t have = bytes.size() - pos;
  if (have < need) throw bad_input("truncated NRRD frame: expected {} bytes, got {} ({})", need, have, loc);
  f.data.resize(count);
  const char* p = bytes.data() + pos;
  for (std::size_t i = 0; i < count; ++i) {
    if (f.float64) {
      std::memcpy(&f.data[i], p + 8 * i, 8);
    } else {
      float v;
      std::memcpy(&v, p + 4 * i, 4);
      f.data[i] = v;
    }
  }
  return pos + need;
}

Frame make_frame(const Layout& L, const State& st, const std::vector<std::string>& scalar_names,
                 const std::vector<std::string>& fields, long index, double time) {
  Frame f;
  f.index = index;
  f.time = time;
  f.dim = L.dim;
  f.size = L.size;
  f.spacing = L.h;
  std::vector<const Field*> channels;
  for (const std::string& name : fields) {
    if (name == "velocity") {
      f.fields.push_back({"velocity", 3});
      for (int c = 0; c < 3; ++c) channels.push_back(c < L.dim ? &st.u[c] : nullptr);
      continue;
    }
    bool found = false;
    for (std::size_t i = 0; i < scalar_names.size(); ++i)
      if (scalar_names[i] == name) {
        f.fields.push_back({name, 1});
        channels.push_back(&st.s[i]);
        found = true;
      }
    if (!found) throw usage_error("field \"{}\" is neither velocity nor a scalar of the state", name);
  }
  const std::size_t C = channels.size(), N = L.count();
  f.data.assign(C * N, 0.0);
  for (std::size_t c = 0; c < C; ++c)
    if (channels[c])
      for (std::size_t n = 0; n < N; ++n) f.data[n * C + c] = (*channels[c])[n];
  return f;
}

Frame blend_frames(const Frame& x, const Frame& y, double a) {
  if (x.dim != y.dim || x.size != y.size || x.channels() != y.channels())
    throw bad_input("frames differ in shape ({}x{}x{} with {} channels against {}x{}x{} with {})", x.size[0], x.size[1],
                    x.size[2], x.channels(), y.size[0], y.size[1], y.size[2], y.channels());
  Frame out = x;
  for (std::size_t i = 0; i < out.data.size(); ++i) out.data[i] = (1.0 - a) * x.data[i] + a * y.data[i];
  out.time = (1.0 - a) * x.time + a * y.time;
  return out;
}

}  // namespace fest::fluidsim
