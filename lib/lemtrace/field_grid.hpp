#pragma once
// The traced grid: mesh, per-cell records and the seed locator (docs/lemtrace.md §4).
//
// Precompute modes (§9.4.4): all (the paper's "exact with memory": every record before
// tracing), none ("on the fly": computed on each visit), lazy (computed on the first
// visit and kept; the table is allocated but not initialised, so memory pages are only
// touched for visited cells). Records are identical in all three modes.

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>

#include "lemtrace/cell_field.hpp"
#include "lemtrace/locator.hpp"

namespace fest::lemtrace {

enum class Precompute { all, lazy, none };

class FieldGrid {
 public:
  FieldGrid(TetMesh mesh, const ClassifyParams& params, Precompute mode, int threads);
  const TetMesh& mesh() const noexcept { return mesh_; }
  const ClassifyParams& params() const noexcept { return params_; }
  Precompute mode() const noexcept { return mode_; }
  // The record of a cell; `scratch` holds it when it is not (yet) in the table. Normal
  // cells come in the barycentric frame (to_barycentric_frame), the others as classify()
  // gives them; classify() itself gives the world-frame form of any cell.
  const CellRecord& record(int32_t cell, CellRecord& scratch) const {
    // Precomputed: a plain table read (the per-crossing cost of Table 9.4's "with memory").
    if (mode_ == Precompute::all) return table_[static_cast<std::size_t>(cell)];
    return record_slow(cell, scratch);
  }
  const CellLocator& locator() const;  // built on first use
  double max_speed() const noexcept { return max_speed_; }
  // Memory of the mesh, neighbour table, records and locator, in bytes (records: all
  // of the table for --precompute all, the visited ones for lazy).
  std::size_t bytes() const;
  std::size_t records_computed() const noexcept { return computed_.load(); }

 private:
  const CellRecord& record_slow(int32_t cell, CellRecord& scratch) const;

  TetMesh mesh_;
  ClassifyParams params_;
  Precompute mode_;
  double max_speed_ = 0;
  std::unique_ptr<CellRecord[]> table_;
  std::unique_ptr<std::atomic<uint8_t>[]> state_;  // 0 empty, 1 being written, 2 ready
  mutable std::atomic<std::size_t> computed_{0};
  mutable std::once_flag locator_once_;
  mutable std::unique_ptr<CellLocator> locator_;
};

}  // namespace fest::lemtrace
