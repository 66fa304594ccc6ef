// ebcode's flag values -> typed options. The messages name the flag: these are the
// user's words, which lib/edgebreaker does not know.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "commands.hpp"
#include "core/error.hpp"

namespace fest::ebcode {

using edgebreaker::ConnChoice;
using edgebreaker::Predictor;

std::array<float, 4> parse_box(const std::string& text) {
  std::array<float, 4> box{};
  std::stringstream in(text);
  std::string item;
  std::size_t k = 0;
  while (std::getline(in, item, ',')) {
    if (k == 4) throw usage_error("--box takes four numbers X,Y,Z,EXT");
    try {
      std::size_t used = 0;
      box[k] = std::stof(item, &used);
      if (used != item.size() || !std::isfinite(box[k])) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw usage_error("--box: '{}' is not a number", item);
    }
    ++k;
  }
  if (k != 4) throw usage_error("--box takes four numbers X,Y,Z,EXT");
  if (box[3] < 0) throw usage_error("--box: the extent must be >= 0");
  return box;
}

Predictor parse_predictor(const std::string& name) {
  if (name == "para") return Predictor::parallelogram;
  if (name == "delta") return Predictor::delta;
  if (name == "none") return Predictor::none;
  if (name == "multi") return Predictor::multi;
  throw usage_error("--predict: unknown predictor '{}' (para, multi, delta, none)", name);
}

ConnChoice parse_conn(const std::string& name) {
  if (name == "auto") return ConnChoice::automatic;
  if (name == "static") return ConnChoice::static_model;
  if (name == "adaptive") return ConnChoice::adaptive;
  if (name == "raw") return ConnChoice::raw;
  throw usage_error("--conn: unknown coder '{}' (auto, static, adaptive, raw)", name);
}

EncodeFormat parse_encode_format(const std::string& name) {
  if (name == "ebm") return EncodeFormat::ebm;
  if (name == "drc") return EncodeFormat::drc;
  throw usage_error("--to: unknown output '{}' (ebm, drc)", name);
}

ModelFormat parse_model_format(const std::string& name) {
  if (name == "tsv") return ModelFormat::tsv;
  if (name == "json") return ModelFormat::json;
  if (name == "inc") return ModelFormat::inc;
  throw usage_error("--to: unknown output '{}' (tsv, json, inc)", name);
}

Error in_flag_terms(const Error& e) {
  // lib/edgebreaker's phrase -> the flag the user sets it with (messages as ebcode(1) shows them).
  static const std::pair<const char*, const char*> phrases[] = {
      {"lossless positions (0 quantisation bits) store", "--qp 0 stores"},
      {"(strict coding)", "(--strict)"},
      {"use the adaptive coder, or let the encoder choose", "use --conn adaptive or auto"},
      {"position quantisation bits", "--qp"},
      {"normal quantisation bits", "--qn"},
      {"texture-coordinate quantisation bits", "--qt"},
      {"quantisation box:", "--box:"},
  };
  std::string what = e.what();
  for (const auto& [domain, flag] : phrases) {
    const std::size_t at = what.find(domain);
    if (at != std::string::npos) what.replace(at, std::string(domain).size(), flag);
  }
  return Error(e.status(), what);
}

int parse_length_limit(const std::string& text, const char* flag) {
  if (text == "-") return -1;
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size() && v >= 3 && v <= 64) return v;
  } catch (const std::exception&) {
  }
  throw usage_error("{}: '{}' is not a length 3..64 or -", flag, text);
}

}  // namespace fest::ebcode
