#include "formats/dataset/vtk_reasons.hpp"

#include <cstdio>
#include <string_view>

#include <fmt/format.h>

#include "core/quote.hpp"

namespace fest::formats::detail {

namespace {

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// The number after "in piece " (VTK counts pieces from 0), or -1.
long piece_of(std::string_view text) {
  const std::size_t at = text.find("in piece ");
  if (at == std::string_view::npos) return -1;
  long piece = -1;
  if (std::sscanf(std::string(text.substr(at + 9, 20)).c_str(), "%ld", &piece) != 1) return -1;
  return piece;
}

// The text between the first pair of double quotes after `from`, escaped and cut short
// (it is an array name from the input), or empty.
std::string quoted_after(std::string_view text, std::size_t from = 0) {
  const std::size_t open = text.find('"', from);
  if (open == std::string_view::npos) return {};
  const std::size_t close = text.find('"', open + 1);
  if (close == std::string_view::npos) return {};
  return quoted_bytes(text.substr(open + 1, close - open - 1), 40);
}

std::string piece_words(long piece) { return piece >= 0 ? fmt::format("piece {}", piece) : std::string("a piece"); }

// "Cannot read cell <what> from Cells in piece N because the "<array>" array <why>":
// the cell arrays of an unstructured grid (or the polys, lines, strips, verts of a
// PolyData) do not describe cells.
std::string cell_array_words(std::string_view text) {
  const long piece = piece_of(text);
  const std::size_t because = text.find(" because the \"");
  if (because == std::string_view::npos)
    return fmt::format("the cell arrays of {} do not describe its cells", piece_words(piece));
  const std::string array = quoted_after(text, because);
  const std::string_view why = text.substr(because);
  if (why.find("not monotonically increasing") != std::string_view::npos)
    return fmt::format("the \"{}\" of the cells of {} do not start at 0 and increase from cell to cell", array,
                       piece_words(piece));
  if (why.find("not long enough") != std::string_view::npos)
    return fmt::format("the \"{}\" array of the cells of {} is shorter than its cell count needs", array,
                       piece_words(piece));
  if (why.find("could not be found") != std::string_view::npos)
    return fmt::format("the cells of {} have no \"{}\" array", piece_words(piece), array);
  if (why.find("could not be") != std::string_view::npos)
    return fmt::format("the \"{}\" array of the cells of {} is not of an integer type", array, piece_words(piece));
  return fmt::format("the \"{}\" array of the cells of {} does not describe its cells", array, piece_words(piece));
}

}  // namespace

std::string fest_words_for_vtk_reason(const std::string& vtk_text) {
  const std::string_view text = vtk_text;
  // Before the cell arrays: "Cannot read cell data array" also starts "Cannot read cell ".
  for (const char* kind : {"point", "cell", "row"}) {
    if (starts_with(text, fmt::format("Cannot read {} data array \"", kind)))
      return fmt::format("{} data array \"{}\" of {} holds fewer values than the piece has {}s", kind,
                         quoted_after(text), piece_words(piece_of(text)), kind);
  }
  if (starts_with(text, "Cannot read cell ") || starts_with(text, "Cannot read face"))
    return cell_array_words(text);
  if (starts_with(text, "Error reading cell offsets"))
    return "the cell offsets are not of an integer type";
  if (starts_with(text, "Cannot read points array"))
    return fmt::format("the points of {} hold fewer values than its NumberOfPoints needs", piece_words(piece_of(text)));
  if (starts_with(text, "Error reading uncompressed binary data header") ||
      starts_with(text, "Error reading compression header") ||
      starts_with(text, "Error reading beginning of compression header")) {
    unsigned long got = 0, want = 0;
    const std::size_t read_at = text.find("Read ");
    if (read_at != std::string_view::npos &&
        std::sscanf(std::string(text.substr(read_at)).c_str(), "Read %lu of %lu", &got, &want) == 2)
      return fmt::format("a binary block's header ends after {} of its {} bytes", got, want);
    return "a binary block's header cannot be read";
  }
  if (starts_with(text, "Cannot read ascii data") || starts_with(text, "Cannot read binary data") ||
      starts_with(text, "Cannot read appended data"))
    return "an array's values cannot be read as its markup declares them";
  if (starts_with(text, "Unsupported data type") || starts_with(text, "Invalid 'type' specified") ||
      starts_with(text, "Unsupported data type size"))
    return "an array has a data type VTK files do not define";
  return {};
}

}  // namespace fest::formats::detail
