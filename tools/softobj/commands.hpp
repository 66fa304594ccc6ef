#pragma once
// softobj's subcommands (docs/softobj.md §7), each taking its parsed options.

#include <string>
#include <vector>

namespace fest::softobj_tool {

enum class PolygonizeMethod { shrinkwrap, mc };
enum class SkeletonFormat { json, mesh };          // mesh: its triangles are the skeleton
enum class TongueLayoutChoice { default10, paper9 };
struct KernelChoice {                              // --kernel coulomb | wyvill:R
  bool wyvill = false;
  double radius = 0;
};

struct PolygonizeArgs {
  std::string input = "-";
  std::string output = "-";
  std::string to;
  double iso = 0, radius = 0;  // at most one; neither: the file's "iso", else radius 1
  double alpha_deg = 15;
  double lmax = 0;             // 0 = rho
  double max_deviation = 0;    // deviation-driven refinement tolerance; 0 = off
  int steps = 16;
  int start_level = 1;
  double relax = 0.5;
  bool no_coarsen = false;
  long long max_verts = 500000;
  PolygonizeMethod method = PolygonizeMethod::shrinkwrap;
  double grid = 0;             // mc spacing; 0 = lmax / 2
  SkeletonFormat skeleton_format = SkeletonFormat::json;
  KernelChoice kernel;
  std::string report;
};

struct TongueArgs {
  std::string input = "-";
  std::string output = "-";
  bool neutral = false;              // start from the neutral shape, read no input
  int frame = 0;
  TongueLayoutChoice layout = TongueLayoutChoice::default10;
  std::vector<std::string> set;      // name=value
  double radius = 6;
  std::string palate;                // pass 1 of the penetration avoidance
  // --polygonize: every row -> pass 1 -> shrink-wrap -> pass 2 -> output % frame number
  bool polygonize = false;
  double alpha_deg = 15, lmax = 0;
  double max_deviation = 0;          // deviation-driven refinement tolerance; 0 = off
  int steps = 16;
  int threads = 0;
  bool progress = false;  // --progress: frames polygonised
};

struct PalateArgs {
  std::string input = "-";   // mesh
  std::string palate;
  std::string output = "-";
  std::string to;
};

int run_palate(const PalateArgs& a);

struct FieldArgs {
  std::string input = "-";
  std::string at;
  std::string output = "-";
};

struct AnimateArgs {
  std::string input = "-";   // timeline
  std::string table;
  double fps = 30;
  std::string output = "-";
};

int run_animate(const AnimateArgs& a);
int run_polygonize(const PolygonizeArgs& a);
int run_tongue(const TongueArgs& a);
int run_field(const FieldArgs& a);

}  // namespace fest::softobj_tool
