#include "keys_io.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "core/text_lines.hpp"
#include "formats/table/table_io.hpp"

namespace fest::quatpath_tool {

using motionpath::Key;
using motionpath::Pose;
using motionpath::Way;

namespace {

std::vector<Key> read_table_keys(const std::string& bytes, const std::string& name, Way default_way, int& dropped) {
  const std::string header = bytes.substr(0, bytes.find('\n'));
  const auto fmt_in = header.find('\t') != std::string::npos ? formats::Format::tsv : formats::Format::csv;
  Table t;
  try {
    t = formats::read_table(bytes, fmt_in);
  } catch (const Error& e) {
    throw Error(e.status(), fmt::format("{} ({})", e.what(), name));
  }
  const char* need[] = {"t", "x", "y", "z", "qw", "qx", "qy", "qz"};
  std::size_t col[8];
  for (int i = 0; i < 8; ++i) {
    col[i] = t.find(need[i]);
    if (col[i] == Table::npos) throw bad_input("the key table has no column '{}' (header t,x,y,z,qw,qx,qy,qz) ({})", need[i], name);
  }
  const std::size_t way = t.find("way"), ten = t.find("tension"), con = t.find("continuity"), bia = t.find("bias");
  dropped = static_cast<int>(t.cols()) - 8 - (way != Table::npos) - (ten != Table::npos) - (con != Table::npos) -
            (bia != Table::npos);
  std::vector<Key> keys(t.rows());
  for (std::size_t r = 0; r < t.rows(); ++r) {
    Key& k = keys[r];
    k.t = t.columns[col[0]][r];
    k.p = {t.columns[col[1]][r], t.columns[col[2]][r], t.columns[col[3]][r]};
    k.q = {t.columns[col[4]][r], t.columns[col[5]][r], t.columns[col[6]][r], t.columns[col[7]][r]};
    k.way = default_way;
    if (way != Table::npos) {
      const double w = t.columns[way][r];
      if (w == 1) k.way = Way::longest;
      else if (w == 0) k.way = Way::shortest;
      else if (!std::isnan(w)) throw bad_input("row {}: way is 0 (short) or 1 (long), not {} ({})", r + 2, w, name);
    }
    if (ten != Table::npos) k.tension = t.columns[ten][r];
    if (con != Table::npos) k.continuity = t.columns[con][r];
    if (bia != Table::npos) k.bias = t.columns[bia][r];
  }
  return keys;
}

std::vector<Key> read_jsonl_keys(const std::string& bytes, const std::string& name, Way default_way) {
  std::vector<Key> keys;
  for_each_nonblank_line(bytes, [&](int line, const std::string& text) {
    const std::string where = fmt::format("{}:{}", name, line);
    try {
      const auto j = nlohmann::json::parse(text);
      Key k;
      k.t = j.at("t").get<double>();
      const auto& p = j.at("pos");
      const auto& q = j.at("quat");
      if (!p.is_array() || p.size() != 3 || !q.is_array() || q.size() != 4)
        throw bad_input("\"pos\" is [x,y,z] and \"quat\" is [w,x,y,z] ({})", where);
      k.p = {p[0].get<double>(), p[1].get<double>(), p[2].get<double>()};
      k.q = {q[0].get<double>(), q[1].get<double>(), q[2].get<double>(), q[3].get<double>()};
      k.way = default_way;
      if (j.contains("way")) {
        const std::string w = j["way"].get<std::string>();
        if (w == "long") k.way = Way::longest;
        else if (w == "short") k.way = Way::shortest;
        else throw bad_input("\"way\" is \"short\" or \"long\", not \"{}\" ({})", quoted_bytes(w), where);
      }
      k.tension = j.value("tension", 0.0);
      k.continuity = j.value("continuity", 0.0);
      k.bias = j.value("bias", 0.0);
      keys.push_back(k);
    } catch (const nlohmann::json::parse_error& e) {
      throw bad_input("malformed key: {} ({})", json_failure_words(e.what(), e.byte, text), where);
    } catch (const nlohmann::json::exception& e) {
      throw bad_input("malformed key: {} ({})", json_failure_words(e.what(), 0, {}), where);
    }
  });
  return keys;
}

}  // namespace

std::vector<Key> read_keys(const std::string& bytes, const std::string& name, Way default_way, int& dropped) {
  dropped = 0;
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) throw bad_input("no keys: the input is empty ({})", name);
  if (bytes[first] == '{') return read_jsonl_keys(bytes, name, default_way);
  return read_table_keys(bytes, name, default_way, dropped);
}

std::string write_csv(const std::vector<Pose>& poses) {
  Table t;
  std::vector<std::vector<double>> c(8);
  for (const Pose& p : poses) {
    const double v[8] = {p.t, p.p.x, p.p.y, p.p.z, p.q.w, p.q.x, p.q.y, p.q.z};
    for (int i = 0; i < 8; ++i) c[static_cast<std::size_t>(i)].push_back(v[i]);
  }
  const char* names[] = {"t", "x", "y", "z", "qw", "qx", "qy", "qz"};
  for (int i = 0; i < 8; ++i) t.add_column(names[i], std::move(c[static_cast<std::size_t>(i)]));
  return formats::write_table(t, formats::Format::csv);
}

std::string write_jsonl(const std::vector<Pose>& poses) {
  std::string out;
  for (const Pose& p : poses)
    out += fmt::format("{{\"t\":{},\"pos\":[{},{},{}],\"quat\":[{},{},{},{}]}}\n", p.t, p.p.x, p.p.y, p.p.z, p.q.w, p.q.x,
                       p.q.y, p.q.z);
  return out;
}

// The camera looks along its local -z with local +y up (the OpenGL and glTF camera
// convention); the pose's quaternion turns local axes into world axes.
std::string write_cameras(const std::vector<Pose>& poses, const CameraOptions& cam) {
  std::string out;
  for (const Pose& p : poses) {
    const motionpath::Vec3 fwd = motionpath::rotate(p.q, {0, 0, -1});
    const motionpath::Vec3 up = motionpath::rotate(p.q, {0, 1, 0});
    const motionpath::Vec3 target = p.p + cam.distance * fwd;
    out += fmt::format("{{\"t\":{},\"eye\":[{},{},{}],\"target\":[{},{},{}],\"up\":[{},{},{}],\"fovy_deg\":{},\"width\":{},"
                       "\"height\":{}",
                       p.t, p.p.x, p.p.y, p.p.z, target.x, target.y, target.z, up.x, up.y, up.z, cam.fovy_deg, cam.width,
                       cam.height);
    if (cam.tau_px > 0) out += fmt::format(",\"tau_px\":{}", cam.tau_px);
    out += "}\n";
  }
  return out;
}

std::string write_camera_args(const std::vector<Pose>& poses, const CameraOptions& cam) {
  std::string out;
  for (const Pose& p : poses) {
    const motionpath::Vec3 fwd = motionpath::rotate(p.q, {0, 0, -1});
    const motionpath::Vec3 up = motionpath::rotate(p.q, {0, 1, 0});
    const motionpath::Vec3 target = p.p + cam.distance * fwd;
    out += fmt::format("--eye {},{},{} --look-at {},{},{} --up {},{},{}\n", p.p.x, p.p.y, p.p.z, target.x, target.y, target.z,
                       up.x, up.y, up.z);
  }
  return out;
}

}  // namespace fest::quatpath_tool
