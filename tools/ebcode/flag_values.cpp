// ebcode's flag values -> typed options. The messages name the flag: these are the
// user's words, which lib/edgebreaker does not know.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "cli/word_choice.hpp"
#include "commands.hpp"
#include "core/error.hpp"
#include "core/reworded_error.hpp"

namespace fest::ebcode_tool {

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
  return cli::word_choice<Predictor>(
      name, {{"para", Predictor::parallelogram}, {"multi", Predictor::multi}, {"delta", Predictor::delta}, {"none", Predictor::none}},
      "--predict", "predictor");
}

ConnChoice parse_conn(const std::string& name) {
  return cli::word_choice<ConnChoice>(name,
                                      {{"auto", ConnChoice::automatic},
                                       {"static", ConnChoice::static_model},
                                       {"adaptive", ConnChoice::adaptive},
                                       {"raw", ConnChoice::raw}},
                                      "--conn", "coder");
}

EncodeFormat parse_encode_format(const std::string& name) {
  return cli::word_choice<EncodeFormat>(name, {{"ebm", EncodeFormat::ebm}, {"drc", EncodeFormat::drc}}, "--to", "output");
}

ModelFormat parse_model_format(const std::string& name) {
  return cli::word_choice<ModelFormat>(name, {{"tsv", ModelFormat::tsv}, {"json", ModelFormat::json}, {"inc", ModelFormat::inc}},
                                       "--to", "output");
}

Error in_flag_terms(const Error& e) {
  // lib/edgebreaker's phrase -> the flag the user sets it with (messages as ebcode(1) shows them).
  return reworded(e, {{"lossless positions (0 quantisation bits) store", "--qp 0 stores"},
                      {"(strict coding)", "(--strict)"},
                      {"use the adaptive coder, or let the encoder choose", "use --conn adaptive or auto"},
                      {"position quantisation bits", "--qp"},
                      {"normal quantisation bits", "--qn"},
                      {"texture-coordinate quantisation bits", "--qt"},
                      {"quantisation box:", "--box:"}});
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

}  // namespace fest::ebcode_tool
