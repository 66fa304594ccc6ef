#pragma once
// Wiring of segbrain's subcommands (segbrain(1)).

#include <array>
#include <string>
#include <vector>

namespace segbrain_tool {

extern const char* const kDefaultKbName;
extern const char* const kDefaultKb;

struct RunArgs {
  std::string input = "-";
  std::string output = "-";
  std::string to;
  std::vector<std::string> kb;
  std::string goal = "segment_head";
  std::vector<std::string> sets;
  std::string objects;      // --objects head,brain,...: goal segment_objects([...])
  std::string masks;        // --masks DIR
  std::string label_table;  // --label-table FILE
  std::string report;
  std::string trace;
  std::string modality = "t1";  // --modality: must be a supported_modality/1 of the KB
  bool tissue = false;          // --tissue: grey/white matter labels (tissue_classification/0)
  int max_depth = 10000;
  double max_inferences = 1e7;
  double time_limit = 0;
  int threads = 0;  // --threads: 0 = all cores; the output is the same for any count
  bool quiet = false;
};

struct KbCheckArgs {
  std::vector<std::string> files;
};

struct SynthArgs {
  std::string output;
  std::string truth;
  std::string size = "160,192,160";
  std::string spacing = "1,1,1";
  double noise = 0.03;
  double bias = 0.2;
  unsigned long long seed = 1;
};

struct EvalArgs {
  std::string ref;
  std::string seg;
  std::string map;
  std::string ref_map;
};

struct SlicesArgs {
  std::string input;
  std::string labels;
  std::string output;
  std::vector<std::string> kb;
  double scale = 2;
};

// An output label of the knowledge base: label(Index, Name, Parent, [R, G, B]).
struct LabelEntry {
  int index = 0;
  std::string name, parent;
  std::array<int, 3> rgb{0, 0, 0};
};
// The label/4 facts of the given rule files (none: the built-in knowledge base).
std::vector<LabelEntry> kb_labels(const std::vector<std::string>& kb);

int run_segment(const RunArgs& a);
int run_slices(const SlicesArgs& a);
int run_kb_check(const KbCheckArgs& a);
int run_ops(bool json);
int run_synth(const SynthArgs& a);
int run_eval(const EvalArgs& a);

}  // namespace segbrain_tool
