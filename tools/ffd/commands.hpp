#pragma once
// ffd's command library (fest_ffd_app): one function per subcommand; reads meshes with
// formats/, deforms with lib/ffd, writes with formats/. Typed options, no flags here.

#include <string>
#include <vector>

#include "ffd/lattice.hpp"

namespace fest::ffd_tool {

// --normals: vertex normals recomputed from the faces, or carried by J^-T (docs/ffd.md).
enum class NormalsMode { recompute, jacobian };
// --object NAME=MODE: deformed by the lattice, moved rigidly (docs/ffd.md), or left as is.
enum class ObjectMode { deform, rigid, ignore };
const char* object_mode_name(ObjectMode m);
struct NamedInput {   // --in NAME=FILE
  std::string name, path;
};
struct ObjectRole {   // --object NAME=MODE
  std::string name;
  ObjectMode mode = ObjectMode::deform;
};

// --to of convert: the lattice file written.
enum class LatticeFormat { json, pygem };

struct InitOptions {
  std::string input = "-", output = "-";
  std::vector<int> dims{4, 4, 4};
  ffd::Basis basis = ffd::Basis::bernstein;
  double pad = 0.05;
};

struct ApplyOptions {
  std::string lattice;                 // JSON or PyGeM .prm (recognised by content)
  std::string input = "-", output = "-";
  std::vector<NamedInput> inputs;      // --in: each an object
  std::vector<ObjectRole> objects;     // --object
  std::string joints, fixed_cp;
  ffd::Outside outside = ffd::Outside::none;
  NormalsMode normals = NormalsMode::recompute;
  std::string to;
  std::string report;
  bool strict = false, allow_large = false, ascii = false;
  int threads = 0;
};

struct JacobianOptions {
  std::string lattice, input = "-", output = "-";
  ffd::Outside outside = ffd::Outside::none;
  int threads = 0;
};

struct LatticeMeshOptions {
  std::string input = "-", output = "-";
};

struct ConvertOptions {
  std::string input = "-", output = "-";
  LatticeFormat to = LatticeFormat::json;
};

struct AnimateOptions {
  std::string keys;                    // TSV rows: time lattice_file
  std::string input = "-";
  std::string output;                  // pattern with %d (frame number)
  double fps = 30;
  std::string manifest = "-";
  ffd::Outside outside = ffd::Outside::none;
  int threads = 0;
  bool progress = false;  // --progress: frames written
};

int run_init(const InitOptions& o);
int run_apply(const ApplyOptions& o);
int run_jacobian(const JacobianOptions& o);
int run_lattice_mesh(const LatticeMeshOptions& o);
int run_convert(const ConvertOptions& o);
int run_animate(const AnimateOptions& o);

}  // namespace fest::ffd_tool
