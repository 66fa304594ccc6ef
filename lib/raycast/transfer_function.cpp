#include "raycast/transfer_function.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace fest::raycast {
namespace {

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

double parse_number(const std::string& s, bool& ok) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  ok = !s.empty() && end && *end == 0 && std::isfinite(v);
  return v;
}

void check_points(const std::vector<ControlPoint>& p, OpacityMode mode) {
  if (p.size() < 2) throw std::invalid_argument("transfer function needs at least 2 points, got " + std::to_string(p.size()));
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (k > 0 && !(p[k].value > p[k - 1].value))
      throw std::invalid_argument("transfer function values must increase (point " + std::to_string(k + 1) + ")");
    for (double c : {p[k].r, p[k].g, p[k].b})
      if (!(c >= 0 && c <= 1)) throw std::invalid_argument("colour outside [0,1] (point " + std::to_string(k + 1) + ")");
    if (!(p[k].a >= 0) || (mode == OpacityMode::opacity && p[k].a > 1))
      throw std::invalid_argument("opacity outside [0,1] (point " + std::to_string(k + 1) + ")");
  }
}

std::vector<ControlPoint> parse_paraview(std::string_view text, double lo, double hi) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const std::exception&) {
    throw std::invalid_argument("transfer function JSON does not parse");
  }
  if (j.is_array() && !j.empty()) j = j[0];
  if (!j.is_object() || !j.contains("RGBPoints") || !j["RGBPoints"].is_array())
    throw std::invalid_argument("transfer function JSON lacks an RGBPoints array");
  std::vector<ControlPoint> p;
  const auto& rgb = j["RGBPoints"];
  if (rgb.size() % 4) throw std::invalid_argument("RGBPoints length is not a multiple of 4");
  for (std::size_t k = 0; k + 3 < rgb.size(); k += 4) {
    if (!rgb[k].is_number() || !rgb[k + 1].is_number() || !rgb[k + 2].is_number() || !rgb[k + 3].is_number())
      throw std::invalid_argument("RGBPoints holds a non-number");
    p.push_back({rgb[k].get<double>(), rgb[k + 1].get<double>(), rgb[k + 2].get<double>(), rgb[k + 3].get<double>(), 1.0});
  }
  if (j.contains("Points") && j["Points"].is_array() && j["Points"].size() >= 8) {
    // opacity points x, a, 0.5, 0: interpolate them at the colour points' positions
    const auto& op = j["Points"];
    std::vector<std::pair<double, double>> a;
    for (std::size_t k = 0; k + 3 < op.size(); k += 4) {
      if (!op[k].is_number() || !op[k + 1].is_number()) throw std::invalid_argument("Points holds a non-number");
      a.emplace_back(op[k].get<double>(), op[k + 1].get<double>());
    }
    for (auto& c : p) {
      if (c.value <= a.front().first) c.a = a.front().second;
      else if (c.value >= a.back().first) c.a = a.back().second;
      else
        for (std::size_t k = 1; k < a.size(); ++k)
          if (c.value <= a[k].first) {
            const double w = (c.value - a[k - 1].first) / (a[k].first - a[k - 1].first);
            c.a = a[k - 1].second + w * (a[k].second - a[k - 1].second);
            break;
          }
    }
  }
  (void)lo, (void)hi;
  return p;
}

}  // namespace

std::vector<ControlPoint> parse_transfer_function(std::string_view text, double lo, double hi, OpacityMode mode) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string_view::npos && (text[first] == '{' || text[first] == '[')) {
    auto p = parse_paraview(text, lo, hi);
    check_points(p, mode);
    return p;
  }
  std::vector<ControlPoint> p;
  std::stringstream ss{std::string(text)};
  int line_no = 0;
  for (std::string line; std::getline(ss, line);) {
    ++line_no;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ls(line);
    for (std::string c; std::getline(ls, c, ',');) cells.push_back(trim(c));
    if (cells.size() != 5) throw std::invalid_argument("transfer function line " + std::to_string(line_no) + ": 5 columns value,r,g,b,a expected");
    std::string v = cells[0];
    const bool percent = !v.empty() && v.back() == '%';
    if (percent) v.pop_back();
    bool ok[5];
    double x[5];
    x[0] = parse_number(v, ok[0]);
    for (int k = 1; k < 5; ++k) x[k] = parse_number(cells[k], ok[k]);
    if (!(ok[0] && ok[1] && ok[2] && ok[3] && ok[4])) {
      if (p.empty() && line_no == 1 && !ok[0]) continue;  // a header line
      throw std::invalid_argument("transfer function line " + std::to_string(line_no) + ": not a number");
    }
    if (percent) x[0] = lo + x[0] / 100 * (hi - lo);
    p.push_back({x[0], x[1], x[2], x[3], x[4]});
  }
  check_points(p, mode);
  return p;
}

bool is_preset(const std::string& n) {
  for (const char* p : {"grey", "ct-bone", "ct-skin-bone", "mri", "flow", "rainbow", "contour-only"})
    if (n == p) return true;
  return false;
}

std::vector<ControlPoint> preset_transfer_function(const std::string& name, double lo, double hi) {
  const double w = hi > lo ? hi - lo : 1.0;
  auto at = [&](double f) { return lo + f * w; };
  if (name == "grey") return {{lo, 0, 0, 0, 0}, {hi > lo ? hi : lo + 1, 1, 1, 1, 0.05}};
  if (name == "ct-bone")
    return {{std::min(lo, 99.0), 0, 0, 0, 0}, {100, 0.6, 0.3, 0.2, 0}, {300, 0.95, 0.9, 0.8, 0.4}, {std::max(hi, 1301.0) + 1, 1, 1, 0.95, 0.9}};
  if (name == "ct-skin-bone")
    return {{std::min(lo, -1001.0), 0, 0, 0, 0},  {-400, 0.8, 0.5, 0.4, 0},      {-150, 0.9, 0.6, 0.5, 0.03},
            {-50, 0.9, 0.65, 0.55, 0.03},          {100, 0.9, 0.7, 0.6, 0.0},     {200, 0.95, 0.9, 0.8, 0.3},
            {std::max(hi, 1001.0) + 1, 1, 1, 0.95, 0.9}};
  if (name == "mri") return {{at(0), 0, 0, 0, 0}, {at(0.25), 0.6, 0.45, 0.4, 0}, {at(0.5), 0.9, 0.8, 0.7, 0.05}, {at(1), 1, 1, 1, 0.3}};
  if (name == "flow")
    return {{at(0), 0.23, 0.30, 0.75, 0.0}, {at(0.5), 0.87, 0.87, 0.87, 0.01}, {at(1), 0.71, 0.02, 0.15, 0.2}};
  if (name == "rainbow")
    return {{at(0), 0, 0, 1, 0}, {at(0.25), 0, 1, 1, 0.02}, {at(0.5), 0, 1, 0, 0.05}, {at(0.75), 1, 1, 0, 0.1}, {at(1), 1, 0, 0, 0.2}};
  if (name == "contour-only") return {{lo, 0, 0, 0, 0}, {hi > lo ? hi : lo + 1, 1, 1, 1, 0}};
  throw std::invalid_argument("unknown transfer function preset '" + name + "'");
}

TransferFunction::TransferFunction(std::vector<ControlPoint> p, double lo, double hi, OpacityMode mode, double tf_unit)
    : lo_(lo), hi_(hi > lo ? hi : lo + 1) {
  width_ = (hi_ - lo_) / (kBins - 1);
  inv_width_ = (kBins - 1) / (hi_ - lo_);
  tau_.resize(kBins), r_.resize(kBins), g_.resize(kBins), b_.resize(kBins);
  for (int k = 0; k < kBins; ++k) {
    const double v = lo_ + k * width_;
    ControlPoint c;
    if (v <= p.front().value) c = p.front();
    else if (v >= p.back().value) c = p.back();
    else {
      const auto it = std::upper_bound(p.begin(), p.end(), v, [](double x, const ControlPoint& q) { return x < q.value; });
      const ControlPoint& a = *(it - 1);
      const ControlPoint& b = *it;
      const double w = (v - a.value) / (b.value - a.value);
      c = {v, a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b), a.a + w * (b.a - a.a)};
    }
    double tau = mode == OpacityMode::opacity ? (c.a >= 1 ? 1e6 : -std::log1p(-c.a)) : c.a;
    tau_[k] = tau / tf_unit;
    r_[k] = c.r, g_[k] = c.g, b_[k] = c.b;
  }
  lut_.resize(4 * kBins);
  for (int k = 0; k < kBins; ++k) lut_[4 * k] = tau_[k], lut_[4 * k + 1] = r_[k], lut_[4 * k + 2] = g_[k], lut_[4 * k + 3] = b_[k];
  // Exact integrals of the piecewise-linear tau and tau*c over each bin.
  T_.assign(kBins, 0.0);
  K_.assign(kBins, {0, 0, 0});
  nonzero_prefix_.assign(kBins + 1, 0);
  for (int k = 0; k < kBins; ++k) nonzero_prefix_[k + 1] = nonzero_prefix_[k] + (tau_[k] > 0);
  for (int k = 1; k < kBins; ++k) {
    T_[k] = T_[k - 1] + width_ * 0.5 * (tau_[k - 1] + tau_[k]);
    const double* cs[3] = {r_.data(), g_.data(), b_.data()};
    for (int ch = 0; ch < 3; ++ch) {
      // int_0^w (t0 + dt x/w)(c0 + dc x/w) dx = w (t0 c0 + (t0 dc + dt c0)/2 + dt dc/3)
      const double t0 = tau_[k - 1], dt = tau_[k] - t0, c0 = cs[ch][k - 1], dc = cs[ch][k] - c0;
      K_[k][ch] = K_[k - 1][ch] + width_ * (t0 * c0 + (t0 * dc + dt * c0) / 2 + dt * dc / 3);
    }
  }
}

double TransferFunction::integral_tau(double v) const {
  // Outside the range tau is constant (clamped): integrate it linearly there.
  const double x = (v - lo_) / width_;
  if (x <= 0) return tau_[0] * (v - lo_);
  if (x >= kBins - 1) return T_[kBins - 1] + tau_[kBins - 1] * (v - hi_);
  const int k = std::min(static_cast<int>(x), kBins - 2);
  const double d = (x - k) * width_, t0 = tau_[k], dt = (tau_[k + 1] - t0) / width_;
  return T_[k] + t0 * d + dt * d * d / 2;
}

std::array<double, 3> TransferFunction::integral_tau_color(double v) const {
  const double x = (v - lo_) / width_;
  const double* cs[3] = {r_.data(), g_.data(), b_.data()};
  std::array<double, 3> out{};
  if (x <= 0) {
    for (int ch = 0; ch < 3; ++ch) out[ch] = tau_[0] * cs[ch][0] * (v - lo_);
    return out;
  }
  if (x >= kBins - 1) {
    for (int ch = 0; ch < 3; ++ch) out[ch] = K_[kBins - 1][ch] + tau_[kBins - 1] * cs[ch][kBins - 1] * (v - hi_);
    return out;
  }
  const int k = std::min(static_cast<int>(x), kBins - 2);
  const double d = (x - k) * width_, t0 = tau_[k], dt = (tau_[k + 1] - t0) / width_;
  for (int ch = 0; ch < 3; ++ch) {
    const double c0 = cs[ch][k], dc = (cs[ch][k + 1] - c0) / width_;
    out[ch] = K_[k][ch] + t0 * c0 * d + (t0 * dc + dt * c0) * d * d / 2 + dt * dc * d * d * d / 3;
  }
  return out;
}

bool TransferFunction::transparent(double vlo, double vhi) const {
  const int a = static_cast<int>(std::floor(position(vlo)));
  const int b = std::min(static_cast<int>(std::ceil(position(vhi))), kBins - 1);
  return nonzero_prefix_[b + 1] - nonzero_prefix_[a] == 0;
}

}  // namespace fest::raycast
