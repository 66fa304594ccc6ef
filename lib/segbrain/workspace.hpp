#pragma once
// The blackboard of named objects (docs/segbrain.md) and the methods pool registered into the
// engine as foreign predicates. Objects created by an operator are released when the
// engine backtracks over the creation, so a retry can reuse the name.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "segbrain/engine.hpp"
#include "segbrain/grid.hpp"

namespace fest::segbrain {

struct Regions;

struct Object {
  bool is_mask = false;
  Image image;  // when !is_mask
  Mask mask;    // when is_mask
  std::vector<std::size_t> path;  // a tracked line (its mask marks the same voxels), in order
  std::shared_ptr<const Regions> regions;  // a region division (its mask: the regions' voxels)
};

struct Emitted {
  std::string object;
  int label = 0;
};

class Workspace {
 public:
  explicit Workspace(Grid grid) : grid_(grid) {}

  const Grid& grid() const { return grid_; }
  bool has(const std::string& name) const { return objects_.count(name) != 0; }
  const Object& get(const std::string& name) const;
  const Image& image(const std::string& name) const;
  const Mask& mask(const std::string& name) const;
  // Adds an object that lives for the whole run (the input volume).
  void put_root(const std::string& name, Object obj);
  std::size_t size() const { return objects_.size(); }
  const std::vector<Emitted>& emitted() const { return emitted_; }
  std::size_t memo_hits() const { return memo_hits_; }

  // Registers the operators of docs/segbrain.md §3 that this version provides.
  void register_operators(Engine& engine);
  // The second-order edge operators (workspace_edges.cpp) and line tracking
  // (workspace_tracking.cpp); register_operators calls them.
  void register_edge_operators(Engine& engine);
  void register_tracking_operators(Engine& engine);
  // Region division and aggregation of the edge-based find_brain (workspace_regions.cpp).
  void register_region_operators(Engine& engine);
  // Tissue classes for --tissue (workspace_tissue.cpp).
  void register_tissue_operators(Engine& engine);

 private:
  // Creates `out` (an unbound variable gets a fresh atom; a bound atom names it) and
  // trails its removal.
  bool create(Engine& e, const Term& out, Object obj);
  std::string name_of(const Term& t) const;

  // Depth maps of masks, kept while the mask object lives (several checks of one run
  // measure against the same head outline).
  const std::vector<double>& depth_of(const std::string& name);

  // deep_intensity results by (image, mask, fraction), kept while both objects live:
  // the white-matter reference is asked for by several rules of one run.
  struct DeepMemo {
    std::weak_ptr<const Object> image, mask;
    double frac, value;
  };
  std::vector<DeepMemo> deep_memo_;
  std::size_t memo_hits_ = 0;

  Grid grid_;
  std::map<std::string, std::pair<std::weak_ptr<const Object>, std::shared_ptr<const std::vector<double>>>> depth_cache_;
  std::map<std::string, std::shared_ptr<const Object>> objects_;
  std::vector<Emitted> emitted_;
  int fresh_ = 0;
};

// Label volume from the emitted objects, in emit order (later objects overwrite earlier
// ones, so the knowledge base emits from the outside in: deepest object wins).
std::vector<std::uint16_t> assemble_labels(const Workspace& ws);

}  // namespace fest::segbrain
