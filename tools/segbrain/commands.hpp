#pragma once
// segbrain's subcommands (segbrain(1)): the typed options main.cpp
// fills from the flags, and one function per subcommand. Everything in tools/segbrain
// but main.cpp is the library fest_segbrain_app, which tests and benchmarks link.

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "formats/detect.hpp"
#include "segbrain/phantom.hpp"

namespace fest::segbrain_tool {

// The contrast of the input volume (--modality); the knowledge base says which it
// supports (supported_modality/1).
enum class Modality { t1, t2, pd };
const char* modality_name(Modality m);  // the knowledge base's atom: "t1", "t2", "pd"

// --set NAME=VALUE: the fact to replace and its value, a term in the knowledge base's
// syntax (parsed by the engine's reader, like --goal).
struct FactSetting {
  std::string name;
  std::string value;
};

// segbrain [run] IN: segment a volume.
struct RunArgs {
  std::string input = "-";
  std::string output = "-";
  std::optional<formats::OutputFormat> to;  // --to; none: from -o's extension, else NIfTI
  std::vector<std::string> kb;              // rule files; none: the built-in head_t1.pl
  std::string goal = "segment_head";        // a term in the knowledge base's syntax
  std::vector<FactSetting> sets;
  std::vector<std::string> objects;  // --objects head,brain,...: goal segment_objects([...]) instead
  std::string masks;                 // --masks DIR
  std::string label_table;           // --label-table FILE
  std::string report;
  std::string trace;
  Modality modality = Modality::t1;  // must be a supported_modality/1 of the knowledge base
  bool tissue = false;               // --tissue: grey/white matter labels (tissue_classification/0)
  int max_depth = 10000;
  double max_inferences = 1e7;
  double time_limit = 0;
  int threads = 0;  // --threads: 0 = all cores; the output is the same for any count
  bool quiet = false;
  bool verbose = false;  // -v: also the scene's notes of level info (e.g. already skull-stripped)
  bool progress = false;  // --progress: a bar of the find_<object> goals done so far
};

struct KbCheckArgs {
  std::vector<std::string> files;  // none: the built-in knowledge base
};

struct OpsArgs {
  bool json = false;
};

struct SynthArgs {
  std::string output;
  std::string truth;
  segbrain::PhantomOptions phantom;  // size, spacing, noise, bias, seed
};

// Objects of a label volume for eval: a name and the label values (closed ranges lo..hi)
// that make it up.
using LabelRanges = std::vector<std::pair<double, double>>;
using ObjectMap = std::vector<std::pair<std::string, LabelRanges>>;

struct EvalArgs {
  std::string ref;
  std::string seg;
  ObjectMap map;      // objects of the segmentation
  ObjectMap ref_map;  // the same objects in the reference
};

struct SlicesArgs {
  std::string input;
  std::string labels;
  std::string output;
  std::vector<std::string> kb;
  double scale = 2;
};

int run_segment(const RunArgs& a);
int run_kb_check(const KbCheckArgs& a);
int run_ops(const OpsArgs& a);
int run_synth(const SynthArgs& a);
int run_eval(const EvalArgs& a);
int run_slices(const SlicesArgs& a);

// Flag texts into the typed options above (main.cpp); usage errors name the flag.
// "nii.gz", "nrrd", ...: a volume format (--to).
formats::OutputFormat volume_output_format(const std::string& name);
// "NAME=VALUE" (--set).
FactSetting fact_setting(const std::string& text);
// "head,brain,ventricles" (--objects): the names, none empty; "" is no list.
std::vector<std::string> object_names(const std::string& list);
// "NX,NY,NZ" (--size): three whole numbers in [1, 2^31 - 1]; "SX,SY,SZ" (--spacing): three
// lengths in (0, 1e6] mm.
std::array<std::size_t, 3> positive_counts(const std::string& text, const char* flag);
std::array<double, 3> positive_lengths(const std::string& text, const char* flag);
// "brain=3,4,6-8;csf=2" (--map, --ref-map); "" is one object "object" of every nonzero value.
ObjectMap object_map(const std::string& text, const char* flag);

}  // namespace fest::segbrain_tool
