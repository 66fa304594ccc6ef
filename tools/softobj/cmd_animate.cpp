// softobj animate: phoneme timeline -> tongue parameters per frame (docs/softobj.md §5).
#include <cmath>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/table.hpp"
#include "formats/input.hpp"
#include "formats/table/table_io.hpp"
#include "softobj/coarticulation.hpp"

namespace fest::softobj_tool {

int run_animate(const AnimateArgs& a) {
  if (a.table == "-" && a.input == "-") throw usage_error("the table and the timeline cannot both be standard input");
  const std::string table_text = read_input(a.table);
  softobj::PhonemeTable table;
  try {
    table = softobj::decode_phoneme_table(table_text);
  } catch (const Error& e) {
    throw Error(e.status(), with_location(e.what(), a.table));
  }
  std::vector<softobj::TimedPhoneme> timeline;
  try {
    timeline = softobj::decode_timeline(read_input(a.input), table);
  } catch (const Error& e) {
    if (e.status() != Status::bad_input) throw;
    throw Error(e.status(), with_location(e.what(), a.input));
  }
  const auto keys = softobj::key_frames(timeline, table);
  const double end = timeline.back().end;
  const auto frames = static_cast<std::size_t>(std::floor(end * a.fps + 1e-9)) + 1;
  if (frames > 10000000) throw usage_error("{} frames are too many", frames);
  Table out;
  std::vector<std::vector<double>> cols(softobj::TongueParams::count + 1, std::vector<double>(frames));
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / a.fps;
    const softobj::TongueParams p = softobj::params_at(keys, table, t);
    cols[0][f] = t;
    for (int k = 0; k < softobj::TongueParams::count; ++k) cols[static_cast<std::size_t>(k) + 1][f] = p[k];
  }
  out.add_column("time", cols[0]);
  for (int k = 0; k < softobj::TongueParams::count; ++k)
    out.add_column(softobj::TongueParams::names()[static_cast<std::size_t>(k)], cols[static_cast<std::size_t>(k) + 1]);
  formats::store_output(a.output, formats::write_table(out, formats::Format::tsv), false);
  return 0;
}

}  // namespace fest::softobj_tool
