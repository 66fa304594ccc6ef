#include "marker_art.hpp"

#include <fmt/format.h>

#include "core/error.hpp"
#include "markers/dictionary.hpp"

namespace fest::markerpose_tool {

markers::MarkerArt art_from_flags(const std::string& dict, int id) {
  try {
    return markers::binary_art(markers::dictionary(dict), id);
  } catch (const Error& e) {
    throw Error(Status::usage, fmt::format("--dict {} --id {}: {}", dict, id, e.what()));
  }
}

}  // namespace fest::markerpose_tool
