#pragma once
// ebcode's commands (docs/ebcode.md), each taking its typed options. main.cpp fills these
// from flags; everything else in this folder is the fest_ebcode_app library.

#include <array>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "edgebreaker/ebm.hpp"
#include "edgebreaker/geometry_coder.hpp"
#include "edgebreaker/state_machine.hpp"

namespace fest::ebcode_tool {

enum class EncodeFormat { ebm, drc };

struct EncodeOptions {
  std::string input = "-";
  std::string output = "-";
  edgebreaker::ConnChoice conn = edgebreaker::ConnChoice::automatic;
  edgebreaker::NamedModel model = edgebreaker::named_model("m236");  // the static coder's state machine
  int qp = 14;  // position bits; 0: float32 exactly
  int qn = 10;
  int qt = 12;
  std::optional<std::array<float, 4>> box;  // X, Y, Z, extent; none: the bounding box
  edgebreaker::Predictor predictor = edgebreaker::Predictor::parallelogram;
  bool stitch = true;
  bool drop_isolated = false;
  bool geometry = true;
  bool strict = false;
  EncodeFormat format = EncodeFormat::ebm;
  int draco_cl = 7;        // Draco compression level 0..10 (format drc)
  std::string report;      // JSON report path; empty: none
  bool symbols = false;    // write the CLERS string instead of a stream
  bool verify = true;
  int ebm_version = 2;
  int geom_version = 0;  // EncodeOptions::geom_version
  bool quiet = false;
};

enum class ModelFormat { tsv, json, inc };

struct ModelOptions {
  std::optional<edgebreaker::NamedModel> model;  // none: the limits below
  int lmax = -1, pmax = -1, smax = -1;           // -1: not tracked
  int cmax = 19;
  bool all_patterns = false;
  bool literal = false;
  ModelFormat format = ModelFormat::tsv;
};

// ebcode [encode]: mesh -> .ebm (or Draco, or the CLERS string).
int encode_command(const EncodeOptions& o);
// ebcode model: a state machine of the chapter as TSV, JSON, or the committed tables.
int model_command(const ModelOptions& o);

// Flag values -> typed options; usage errors name the flag.
edgebreaker::ConnChoice parse_conn(const std::string& name);
edgebreaker::Predictor parse_predictor(const std::string& name);
std::array<float, 4> parse_box(const std::string& text);
EncodeFormat parse_encode_format(const std::string& name);
ModelFormat parse_model_format(const std::string& name);
// An error of lib/edgebreaker with its domain phrases replaced by the flags that set them
// ("(strict coding)" -> "(--strict)"), so that messages name what the user typed.
Error in_flag_terms(const Error& e);
// A tracked loop length 3..64, or "-" (-1: not tracked).
int parse_length_limit(const std::string& text, const char* flag);

}  // namespace fest::ebcode_tool
