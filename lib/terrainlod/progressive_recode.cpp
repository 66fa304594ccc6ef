#include "terrainlod/progressive_recode.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "core/error.hpp"

namespace fest::terrainlod {
namespace {

// Runs job(i) for i in [0, count) on up to `threads` threads; the first failure is rethrown.
template <typename Job>
void parallel_for(std::size_t count, int threads, const Job& job) {
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < count;) {
      try {
        job(i);
      } catch (...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::min<int>(threads, static_cast<int>(count)); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

std::vector<std::string> recode_progressive(const std::vector<CodedTile>& children, const std::vector<CodedTile>& parents,
                                            int threads, std::vector<TileSizes>* sizes) {
  std::vector<Tile> decoded(parents.size());
  parallel_for(parents.size(), threads, [&](std::size_t i) {
    if (tile_coding(parents[i].bytes) != TileCoding::standalone)
      throw runtime_failure("progressive recoding: parent {}/{}/{} is not standalone", parents[i].id.level, parents[i].id.x,
                            parents[i].id.y);
    decoded[i] = decode_tile(parents[i].bytes);
  });
  std::vector<std::size_t> order(parents.size());  // parents by id, for the lookup
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return parents[a].id < parents[b].id; });
  auto parent_of = [&](const TileId& child) -> const Tile* {
    const TileId want{child.level - 1, child.x / 2, child.y / 2};
    const auto it = std::lower_bound(order.begin(), order.end(), want,
                                     [&](std::size_t a, const TileId& id) { return parents[a].id < id; });
    if (it == order.end() || !(parents[*it].id == want))
      throw runtime_failure("progressive recoding: the parent of tile {}/{}/{} is missing", child.level, child.x, child.y);
    return &decoded[*it];
  };
  std::vector<std::string> out(children.size());
  if (sizes) sizes->assign(children.size(), TileSizes{});
  parallel_for(children.size(), threads, [&](std::size_t i) {
    const Tile* parent = children[i].id.level > 0 ? parent_of(children[i].id) : nullptr;
    out[i] = recode_tile(children[i].bytes, TileCoding::progressive, parent, sizes ? &(*sizes)[i] : nullptr);
  });
  return out;
}

}  // namespace fest::terrainlod
