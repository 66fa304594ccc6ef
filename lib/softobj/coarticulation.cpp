#include "softobj/coarticulation.hpp"
#include "core/quote.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/error.hpp"

namespace fest::softobj {

namespace {

using json = nlohmann::json;

double finite_number(const json& j, const std::string& where) {
  if (!j.is_number() || !std::isfinite(j.get<double>())) throw bad_input("phoneme table: {} is not a number", where);
  return j.get<double>();
}

// Parameter index -> sagittal row 0 (tip), 1 (middle), 2 (back).
int row_of(int i) {
  static const int rows[TongueParams::count] = {0, 0, 0, 0, 1, 2, 0, 0, 1, 1, 2, 2, 0, 1, 2, 0, 0, 1, 1, 2, 2};
  return rows[i];
}

}  // namespace

PhonemeTable decode_phoneme_table(std::string_view text) {
  json doc;
  try {
    doc = json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw bad_input("phoneme table: {}", json_failure_words(e.what(), e.byte, text));
  } catch (const json::exception& e) {  // a number beyond double's range: out_of_range, not parse_error
    throw bad_input("phoneme table: {}", json_failure_words(e.what(), 0, text));
  }
  if (!doc.is_object() || !doc.contains("phonemes") || !doc["phonemes"].is_object())
    throw bad_input("phoneme table: no \"phonemes\" object");
  PhonemeTable t;
  for (auto it = doc["phonemes"].begin(); it != doc["phonemes"].end(); ++it) {
    const std::string name = it.key();
    const json& p = it.value();
    if (!p.is_object()) throw bad_input("phoneme table: phoneme \"{}\" is not an object", name);
    PhonemeSpec s;
    if (p.contains("class")) {
      if (!p["class"].is_string()) throw bad_input("phoneme table: {}.class is not a string", name);
      const auto c = p["class"].get<std::string>();
      if (c != "vowel" && c != "consonant") throw bad_input("phoneme table: {}.class \"{}\" is not vowel or consonant", name, c);
      s.vowel = c == "vowel";
    }
    if (p.contains("deformable")) {
      if (!p["deformable"].is_boolean()) throw bad_input("phoneme table: {}.deformable is not true/false", name);
      s.deformable = p["deformable"].get<bool>();
    }
    if (p.contains("tongue") && !p["tongue"].is_null()) {
      if (!p["tongue"].is_object()) throw bad_input("phoneme table: {}.tongue is not an object or null", name);
      TongueParams tp = neutral_tongue();
      for (auto m = p["tongue"].begin(); m != p["tongue"].end(); ++m) {
        const int k = TongueParams::index_of(m.key());
        if (k < 0) throw bad_input("phoneme table: {}.tongue has unknown parameter \"{}\"", name, m.key());
        tp[k] = finite_number(m.value(), name + ".tongue." + m.key());
      }
      s.tongue = tp;
    }
    t.phonemes[name] = s;
  }
  if (doc.contains("max_speed")) {
    const json& m = doc["max_speed"];
    if (m.contains("length")) t.max_speed_length = finite_number(m["length"], "max_speed.length");
    if (m.contains("angle")) t.max_speed_angle = finite_number(m["angle"], "max_speed.angle");
    if (!(t.max_speed_length > 0) || !(t.max_speed_angle > 0)) throw bad_input("phoneme table: max_speed must be positive");
  }
  if (doc.contains("lag_s")) {
    const json& m = doc["lag_s"];
    if (m.contains("tip")) t.lag_tip = finite_number(m["tip"], "lag_s.tip");
    if (m.contains("middle")) t.lag_middle = finite_number(m["middle"], "lag_s.middle");
    if (m.contains("back")) t.lag_back = finite_number(m["back"], "lag_s.back");
  }
  return t;
}

std::vector<TimedPhoneme> decode_timeline(std::string_view text, const PhonemeTable& table) {
  std::vector<TimedPhoneme> out;
  std::istringstream in{std::string(text)};
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (const auto h = line.find('#'); h != std::string::npos) line.erase(h);
    std::istringstream ls(line);
    TimedPhoneme p;
    if (!(ls >> p.name)) continue;
    if (out.empty() && p.name == "phoneme") continue;  // header
    std::string a, b;
    if (!(ls >> a >> b)) throw bad_input("timeline line {}: expected \"phoneme start end\"", n);
    char* end = nullptr;
    p.start = std::strtod(a.c_str(), &end);
    const bool ok_a = *end == '\0';
    p.end = std::strtod(b.c_str(), &end);
    if (!ok_a || *end != '\0' || !std::isfinite(p.start) || !std::isfinite(p.end))
      throw bad_input("timeline line {}: start/end are not numbers", n);
    if (!(p.end > p.start)) throw bad_input("timeline line {}: end {} is not after start {}", n, p.end, p.start);
    if (!out.empty() && p.start < out.back().end - 1e-9)
      throw bad_input("timeline line {}: starts at {} before the previous phoneme ends ({})", n, p.start, out.back().end);
    if (!table.phonemes.count(p.name)) throw bad_input("timeline line {}: phoneme \"{}\" is not in the table", n, p.name);
    out.push_back(p);
  }
  if (out.empty()) throw bad_input("timeline: no phonemes");
  return out;
}

std::vector<KeyFrame> key_frames(const std::vector<TimedPhoneme>& tl, const PhonemeTable& table) {
  const std::size_t n = tl.size();
  std::vector<std::optional<TongueParams>> own(n);
  for (std::size_t i = 0; i < n; ++i) own[i] = table.phonemes.at(tl[i].name).tongue;
  std::vector<KeyFrame> keys(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (own[i]) {  // rule 1: key at the midpoint
      keys[i] = {0.5 * (tl[i].start + tl[i].end), *own[i]};
      continue;
    }
    // Rule 2: anticipate the next target from this phoneme's start; else hold the
    // previous one; a timeline without any target uses the neutral shape.
    std::optional<TongueParams> target;
    for (std::size_t j = i + 1; j < n && !target; ++j) target = own[j];
    for (std::size_t j = i; j-- > 0 && !target;) target = own[j];
    keys[i] = {tl[i].start, target ? *target : neutral_tongue()};
  }
  // Rule 3: deformable phonemes move half-way towards their neighbours' mean.
  std::vector<KeyFrame> blended = keys;
  for (std::size_t i = 0; i < n; ++i) {
    if (!table.phonemes.at(tl[i].name).deformable || !own[i]) continue;
    const TongueParams& prev = keys[i > 0 ? i - 1 : i].params;
    const TongueParams& next = keys[i + 1 < n ? i + 1 : i].params;
    for (int k = 0; k < TongueParams::count; ++k)
      blended[i].params[k] = 0.5 * keys[i].params[k] + 0.25 * (prev[k] + next[k]);
  }
  // Rule 4: displacements (origin, lengths) undershoot beyond the maximum speed.
  for (std::size_t i = 1; i < n; ++i) {
    const double dt = blended[i].time - blended[i - 1].time;
    for (int k = 0; k < 12; ++k) {
      const double reach = table.max_speed_length * std::max(dt, 0.0);
      const double d = blended[i].params[k] - blended[i - 1].params[k];
      if (std::abs(d) > reach) blended[i].params[k] = blended[i - 1].params[k] + std::copysign(reach, d);
    }
  }
  // Keys must be strictly increasing in time: a later key at the same time replaces.
  std::vector<KeyFrame> out;
  for (const auto& k : blended) {
    if (!out.empty() && k.time <= out.back().time + 1e-12) out.back() = k;
    else out.push_back(k);
  }
  return out;
}

TongueParams params_at(const std::vector<KeyFrame>& keys, const PhonemeTable& table, double t) {
  TongueParams p;
  const double lags[3] = {table.lag_tip, table.lag_middle, table.lag_back};
  const std::size_t n = keys.size();
  for (int k = 0; k < TongueParams::count; ++k) {
    const double tk = t - lags[row_of(k)];
    if (n == 1 || tk <= keys.front().time) { p[k] = keys.front().params[k]; continue; }
    if (tk >= keys.back().time) { p[k] = keys.back().params[k]; continue; }
    std::size_t i = 0;
    while (keys[i + 1].time < tk) ++i;
    // Hermite on [t_i, t_i+1] with Catmull-Rom tangents (p_i+1 - p_i-1)/(t_i+1 - t_i-1).
    auto val = [&](std::size_t j) { return keys[j].params[k]; };
    auto tangent = [&](std::size_t j) {
      const std::size_t a = j > 0 ? j - 1 : j, b = j + 1 < n ? j + 1 : j;
      return (val(b) - val(a)) / (keys[b].time - keys[a].time);
    };
    const double h = keys[i + 1].time - keys[i].time, s = (tk - keys[i].time) / h;
    const double s2 = s * s, s3 = s2 * s;
    p[k] = (2 * s3 - 3 * s2 + 1) * val(i) + (s3 - 2 * s2 + s) * h * tangent(i) + (-2 * s3 + 3 * s2) * val(i + 1) +
           (s3 - s2) * h * tangent(i + 1);
  }
  return p;
}

}  // namespace fest::softobj
