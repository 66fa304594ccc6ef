// volwave info: a .vw file described as JSON (geometry, bound, chunks and their errors).

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/file_io.hpp"
#include "core/volume.hpp"
#include "input_location.hpp"
#include "wavelet/vw_codec.hpp"

namespace fest::volwave_tool {

int info_command(const InfoOptions& o) {
  const std::string bytes = read_input(o.input);
  const wavelet::VwHeader h = named(o.input, [&] { return wavelet::read_vw_header(bytes); });
  nlohmann::json chunks = nlohmann::json::array();
  std::uint64_t at = h.header_bytes;
  int complete = 0;
  for (std::size_t k = 0; k < h.chunks.size(); ++k) {
    const auto& c = h.chunks[k];
    at += c.bytes;
    const bool present = at <= bytes.size();
    if (present && complete == static_cast<int>(k)) ++complete;
    std::string what = k == 0 ? "approximation" : (k + 1 == h.chunks.size() ? "outliers" : fmt::format("details of level {}", h.levels - static_cast<int>(k)));
    chunks.push_back({{"chunk", k}, {"holds", what}, {"bytes", c.bytes}, {"file_bytes_through", at}, {"max_error", c.max_error},
                      {"rmse", c.rmse}, {"present", present}});
  }
  const std::size_t voxels = h.dims[0] * h.dims[1] * h.dims[2];
  const double raw = static_cast<double>(voxels * scalar_type_size(h.type));
  nlohmann::json r = {{"format", "vw"},
                      {"version", h.version},
                      {"dimensions", h.dims},
                      {"spacing", h.spacing},
                      {"origin", h.origin},
                      {"direction", h.direction},
                      {"value_type", scalar_type_name(h.type)},
                      {"mode", wavelet::mode_name(h.mode)},
                      {"wavelet", wavelet::wavelet_name(h.wavelet)},
                      {"levels", h.levels},
                      {"bound", h.bound},
                      {"step", h.quantiser.step},
                      {"keys", h.quantiser.kind == wavelet::KeyKind::float32_bits ? "float32-bits" : "scaled"},
                      {"bytes", h.total_bytes()},
                      {"file_bytes", bytes.size()},
                      {"ratio", raw / static_cast<double>(h.total_bytes())},
                      {"truncated", bytes.size() < h.total_bytes()},
                      {"chunks_complete", complete},
                      {"max_error", h.chunks.back().max_error},
                      {"rmse", h.chunks.back().rmse},
                      {"chunks", chunks}};
  if (h.roi_step > 0) r["roi_bound"] = h.roi_bound;
  // How the slabs of the complete chunks are coded (fest-vw(5) slab modes).
  const wavelet::SlabCensus census = wavelet::slab_census(bytes);
  const char* names[3] = {"adaptive", "static", "packed"};
  for (int m = 0; m < 3; ++m)
    r["slabs"][names[m]] = {{"slabs", census.slabs[static_cast<std::size_t>(m)]},
                            {"bytes", census.bytes[static_cast<std::size_t>(m)]},
                            {"coefficients", census.coefficients[static_cast<std::size_t>(m)]}};
  // Packed slabs per rANS table precision, "11" the full one (version 5 chooses lower
  // ones for slabs with few symbols; docs/volwave.md §4).
  for (std::size_t i = 0; i < census.packed_by_precision.size(); ++i)
    if (census.packed_by_precision[i] > 0) r["slabs"]["packed"]["table_bits"][std::to_string(i + 5)] = census.packed_by_precision[i];
  write_output("-", r.dump(2) + "\n");
  return 0;
}

}  // namespace fest::volwave_tool
