#include "lemtrace/field_grid.hpp"

#include <algorithm>
#include <vector>

#include "core/parallel_for.hpp"

namespace fest::lemtrace {

FieldGrid::FieldGrid(TetMesh mesh, const ClassifyParams& params, Precompute mode, int threads)
    : mesh_(std::move(mesh)), params_(params), mode_(mode) {
  for (const Vec3& v : mesh_.vectors) max_speed_ = std::max(max_speed_, v.norm());
  const std::size_t n = mesh_.tets.size();
  if (mode_ == Precompute::none) return;
  // new T[n] without () leaves trivially constructible records uninitialised.
  table_.reset(new CellRecord[n]);
  state_.reset(new std::atomic<uint8_t>[n]);
  for (std::size_t i = 0; i < n; ++i) state_[i].store(mode_ == Precompute::all ? 2 : 0, std::memory_order_relaxed);
  if (mode_ != Precompute::all) return;
  // Every record depends on its cell alone; chunks of cells keep the job count small.
  const std::size_t chunk = 4096, chunks = (n + chunk - 1) / chunk;
  parallel_for(chunks, threads, [&](std::size_t k) {
    for (std::size_t c = k * chunk; c < std::min(n, (k + 1) * chunk); ++c) {
      const TetGeometry g = tet_geometry(mesh_, static_cast<int32_t>(c));
      table_[c] = to_barycentric_frame(g, classify(g, params_));
    }
  });
  computed_ = n;
}

const CellRecord& FieldGrid::record_slow(int32_t cell, CellRecord& scratch) const {
  const auto c = static_cast<std::size_t>(cell);
  if (mode_ != Precompute::none && state_[c].load(std::memory_order_acquire) == 2) return table_[c];
  const TetGeometry g = tet_geometry(mesh_, cell);
  scratch = to_barycentric_frame(g, classify(g, params_));
  if (mode_ == Precompute::lazy) {
    uint8_t expected = 0;
    if (state_[c].compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) {
      table_[c] = scratch;
      state_[c].store(2, std::memory_order_release);
      ++computed_;
    }
  }
  return scratch;
}

const CellLocator& FieldGrid::locator() const {
  std::call_once(locator_once_, [this] { locator_ = std::make_unique<CellLocator>(mesh_); });
  return *locator_;
}

std::size_t FieldGrid::bytes() const {
  std::size_t b = mesh_.points.size() * 2 * sizeof(Vec3) + mesh_.tets.size() * (2 * sizeof(Tet) + sizeof(int64_t));
  if (mode_ == Precompute::all) b += mesh_.tets.size() * (sizeof(CellRecord) + 1);
  if (mode_ == Precompute::lazy) b += computed_.load() * sizeof(CellRecord) + mesh_.tets.size();
  if (locator_) b += locator_->bytes();
  return b;
}

}  // namespace fest::lemtrace
