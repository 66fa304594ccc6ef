#include "sampling/streamed_resize.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>

#include "core/parallel_for.hpp"
#include "sampling/grey_row_filter.hpp"
#include "sampling/separable_kernels.hpp"

namespace fest::sampling {

namespace {

using pass_detail::accumulate_rows;
using pass_detail::filter_four_rows_any;
using pass_detail::filter_row_any;

// Output rows summed together along y: their taps' input rows are read from the ring
// while they are in cache, one column strip at a time.
constexpr int group_rows = 8;
constexpr std::size_t strip = 1024;  // floats of a column strip (4 KiB)
constexpr std::size_t band_bytes = std::size_t{1} << 20;  // stored bytes read per band

// Rows [lo, hi) of the y pass's input that a group of outputs reads; empty when no tap
// survives (zero edges far outside the image).
struct Span {
  int lo = 0, hi = 0;
  bool empty() const { return hi <= lo; }
};

std::vector<Span> group_spans(const WeightTable& t) {
  const int groups = (t.n_out + group_rows - 1) / group_rows;
  std::vector<Span> spans(static_cast<std::size_t>(groups));
  for (int g = 0; g < groups; ++g) {
    const std::size_t first = t.offset[static_cast<std::size_t>(g) * group_rows];
    const std::size_t last = t.offset[static_cast<std::size_t>(std::min(t.n_out, (g + 1) * group_rows))];
    Span s{std::numeric_limits<int>::max(), -1};
    for (std::size_t j = first; j < last; ++j) {
      s.lo = std::min(s.lo, t.index[j]);
      s.hi = std::max(s.hi, t.index[j] + 1);
    }
    spans[static_cast<std::size_t>(g)] = first == last ? Span{} : s;
  }
  return spans;
}

// Rows of the first stage (decoded, and filtered along x when rows go first), row r in
// slot r mod capacity; [lo, hi) are present.
class Ring {
 public:
  // Left uninitialised: every row is written before it is read.
  Ring(int capacity, std::size_t row_len)
      : capacity_(capacity), row_len_(row_len), values_(new float[static_cast<std::size_t>(capacity) * row_len]) {}
  float* slot(int row) { return values_.get() + static_cast<std::size_t>(row % capacity_) * row_len_; }
  int capacity() const { return capacity_; }
  int lo = 0, hi = 0;

 private:
  int capacity_;
  std::size_t row_len_;
  std::unique_ptr<float[]> values_;
};

void widen_range(const float* v, std::size_t n, int c, ChannelRange& r) {
  for (std::size_t i = 0; i < n; ++i) {
    const auto ch = i % static_cast<std::size_t>(c);
    r.lo[ch] = std::min(r.lo[ch], v[i]);
    r.hi[ch] = std::max(r.hi[ch], v[i]);
  }
}

}  // namespace

std::optional<FloatImage> resize_streamed(const StoredRows& in, const Encoding& enc, const StreamedPasses& passes,
                                          int threads, ChannelRange* range) {
  const WeightTable& tx = *passes.x;
  const WeightTable& ty = *passes.y;
  const int c = CV_MAT_CN(in.type());
  const std::vector<Span> spans = group_spans(ty);
  // The ring drops the rows above a group's first row: that needs first rows that never
  // move back (true of clamp, zero and reflect edges; wrap edges move back at the end).
  int max_span = 1;
  for (std::size_t g = 0, last_lo = 0; g < spans.size(); ++g) {
    if (spans[g].empty()) continue;
    if (static_cast<std::size_t>(spans[g].lo) < last_lo) return std::nullopt;
    last_lo = static_cast<std::size_t>(spans[g].lo);
    max_span = std::max(max_span, spans[g].hi - spans[g].lo);
  }
  const std::size_t stored_row_bytes = static_cast<std::size_t>(in.width()) * CV_ELEM_SIZE(in.type());
  const int band = static_cast<int>(std::clamp<std::size_t>(band_bytes / std::max<std::size_t>(1, stored_row_bytes), 4, 256));
  const int capacity = max_span + band;
  const std::size_t in_len = static_cast<std::size_t>(in.width()) * static_cast<std::size_t>(c);
  const std::size_t stage_len = passes.columns_first ? in_len : static_cast<std::size_t>(tx.n_out) * static_cast<std::size_t>(c);

  // Float samples that decode to themselves (no sRGB, no alpha to premultiply) need no
  // decoding: when columns go first they are read into the ring as they are.
  const bool direct = passes.columns_first && CV_MAT_DEPTH(in.type()) == CV_32F && !enc.decode_srgb &&
                      !(enc.premultiply && alpha_channel(c) >= 0);
  FloatImage out(tx.n_out, ty.n_out, c);
  const GreyRowFilter grey(tx);  // one channel: eight outputs at a time
  auto filter_x = [&](const float* src, float* dst) {
    if (c == 1) return grey(src, dst);
    filter_row_any(src, dst, tx, c);
  };
  const int groups = static_cast<int>(spans.size());
  const int jobs = std::max(1, std::min(threads, groups));
  std::vector<ChannelRange> ranges(static_cast<std::size_t>(jobs));
  for (auto& r : ranges) {
    r.lo.assign(static_cast<std::size_t>(c), std::numeric_limits<float>::infinity());
    r.hi.assign(static_cast<std::size_t>(c), -std::numeric_limits<float>::infinity());
  }

  parallel_for(static_cast<std::size_t>(jobs), jobs, [&](std::size_t job) {
    const int g_begin = static_cast<int>(static_cast<long long>(groups) * static_cast<long long>(job) / jobs);
    const int g_end = static_cast<int>(static_cast<long long>(groups) * static_cast<long long>(job + 1) / jobs);
    int needed = 0;  // rows this job reads stop here
    for (int g = g_begin; g < g_end; ++g) needed = std::max(needed, spans[static_cast<std::size_t>(g)].hi);
    Ring ring(capacity, stage_len);
    std::vector<float> scratch;  // a band of stored rows (floats: aligned for any sample)
    std::vector<float> decoded(passes.columns_first ? 0 : in_len);
    std::vector<float> sums(passes.columns_first ? static_cast<std::size_t>(group_rows) * in_len : 0);
    std::vector<const float*> sources;
    std::vector<std::size_t> starts;
    ChannelRange& job_range = ranges[job];

    auto fill = [&](int first, int last) {
      if (direct) {  // stored floats read straight into the ring, split where it wraps
        for (int a = first, b; a < last; a = b) {
          b = std::min(last, a + ring.capacity() - a % ring.capacity());
          const cv::Mat stored = in.rows(a, b, ring.slot(a));
          for (int r = a; r < b; ++r) {
            if (stored.data != reinterpret_cast<const std::uint8_t*>(ring.slot(a))) decode_row(stored, r - a, enc, ring.slot(r));
            if (range) widen_range(ring.slot(r), in_len, c, job_range);
          }
        }
        return;
      }
      scratch.resize((static_cast<std::size_t>(last - first) * stored_row_bytes + sizeof(float) - 1) / sizeof(float));
      const cv::Mat stored = in.rows(first, last, scratch.data());
      for (int r = first; r < last; ++r) {
        float* dst = passes.columns_first ? ring.slot(r) : decoded.data();
        decode_row(stored, r - first, enc, dst);
        if (range) widen_range(dst, in_len, c, job_range);
        if (!passes.columns_first) filter_x(dst, ring.slot(r));
      }
    };

    for (int g = g_begin; g < g_end; ++g) {
      const Span s = spans[static_cast<std::size_t>(g)];
      if (!s.empty()) {
        ring.lo = std::max(ring.lo, s.lo);
        ring.hi = std::max(ring.hi, ring.lo);
        while (ring.hi < s.hi) {
          // hi - lo <= max_span, so the band always reaches s.hi within the capacity.
          const int end = std::min({ring.hi + band, ring.lo + ring.capacity(), needed});
          fill(ring.hi, end);
          ring.hi = end;
        }
      }
      const int o_begin = g * group_rows, o_end = std::min(ty.n_out, o_begin + group_rows);
      sources.clear();
      starts.clear();
      for (int o = o_begin; o < o_end; ++o) {
        starts.push_back(sources.size());
        for (std::size_t j = ty.offset[static_cast<std::size_t>(o)]; j < ty.offset[static_cast<std::size_t>(o) + 1]; ++j)
          sources.push_back(ring.slot(ty.index[j]));
      }
      auto sum_row = [&](int o) {
        return passes.columns_first ? sums.data() + static_cast<std::size_t>(o - o_begin) * in_len : out.row(o);
      };
      for (std::size_t i0 = 0; i0 < stage_len; i0 += strip)
        for (int o = o_begin; o < o_end; ++o) {
          const std::size_t first = ty.offset[static_cast<std::size_t>(o)];
          const std::size_t taps = ty.offset[static_cast<std::size_t>(o) + 1] - first;
          accumulate_rows(sum_row(o), sources.data() + starts[static_cast<std::size_t>(o - o_begin)], ty.weight.data() + first,
                          taps, i0, std::min(stage_len, i0 + strip));
        }
      if (!passes.columns_first) continue;
      int o = o_begin;
      if (c == 3 || c == 4)
        for (; o + 4 <= o_end; o += 4) {
          const float* src[4] = {sum_row(o), sum_row(o + 1), sum_row(o + 2), sum_row(o + 3)};
          float* dst[4] = {out.row(o), out.row(o + 1), out.row(o + 2), out.row(o + 3)};
          filter_four_rows_any(src, dst, tx, c);
        }
      for (; o < o_end; ++o) filter_x(sum_row(o), out.row(o));
    }
  });

  if (range) {
    *range = ranges[0];
    for (const auto& r : ranges)
      for (int ch = 0; ch < c; ++ch) {
        range->lo[static_cast<std::size_t>(ch)] = std::min(range->lo[static_cast<std::size_t>(ch)], r.lo[static_cast<std::size_t>(ch)]);
        range->hi[static_cast<std::size_t>(ch)] = std::max(range->hi[static_cast<std::size_t>(ch)], r.hi[static_cast<std::size_t>(ch)]);
      }
  }
  return out;
}

}  // namespace fest::sampling
