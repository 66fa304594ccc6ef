// patnet markov: a transcript's state sequence -> transition matrix (CSV) or a net of
// def-probnodes (seed §23, docs/patnet.md "markov").


#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/input_name.hpp"
#include "core/tool_main.hpp"
#include "formats/detect.hpp"
#include "formats/table/table_io.hpp"
#include "patnet/markov.hpp"

namespace fest::patnet_tool {

int cmd_markov(const MarkovArgs& a) {
  const std::string name = input_name(a.input);
  const std::string bytes = read_input(a.input);
  if (bytes.empty()) throw bad_input("empty transcript ({})", name);
  // A transcript is TSV (the seed's tables) or CSV: recognised by the header line.
  const std::string header = bytes.substr(0, bytes.find('\n'));
  const formats::Format fmt_in = header.find('\t') != std::string::npos ? formats::Format::tsv : formats::Format::csv;
  Table t;
  try {
    t = formats::read_table(bytes, fmt_in);
  } catch (const Error& e) {
    throw Error(e.status(), fmt::format("{} ({})", e.what(), name));
  }
  const std::vector<std::string>& cols = a.cols;
  std::vector<std::size_t> idx;
  for (const auto& c : cols) {
    const std::size_t k = t.find(c);
    if (k == Table::npos) throw bad_input("the transcript has no column '{}' ({})", c, name);
    idx.push_back(k);
  }
  const int states = cols.size() == 3 ? 24 : a.states;
  std::vector<int> seq;
  seq.reserve(t.rows());
  for (std::size_t r = 0; r < t.rows(); ++r) {
    int s;
    if (cols.size() == 3) {
      s = patnet::gaze_state(t.columns[idx[0]][r], t.columns[idx[1]][r], t.columns[idx[2]][r]);
      if (s < 0)
        throw bad_input("row {}: turn state must be 0..5 and gazes 0 or 1 (got {}, {}, {}) ({})", r + 2,
                        t.columns[idx[0]][r], t.columns[idx[1]][r], t.columns[idx[2]][r], name);
    } else {
      const double v = t.columns[idx[0]][r];
      if (!(v >= 0 && v < states && v == static_cast<int>(v)))
        throw bad_input("row {}: state {} is not an integer in 0..{} ({})", r + 2, v, states - 1, name);
      s = static_cast<int>(v);
    }
    seq.push_back(s);
  }
  if (seq.size() < 2) throw bad_input("the transcript needs at least two rows ({})", name);
  const patnet::MarkovEstimate est = patnet::estimate_markov(seq, states, a.no_self);
  if (!est.unvisited.empty() && !a.quiet) {
    std::string list;
    for (int u : est.unvisited) list += (list.empty() ? "S" : ", S") + std::to_string(u);
    warn("patnet", fmt::format("{} of {} states have no observed transition and get uniform rows: {}", est.unvisited.size(),
                               states, list));
  }
  if (!a.net.empty()) {
    write_output(a.output, patnet::markov_net(est, a.net, seq.front(), cols.size() == 3));
    return 0;
  }
  Table out;
  std::vector<double> ids;
  for (int i = 0; i < states; ++i) ids.push_back(i);
  out.add_column("state", ids);
  for (int j = 0; j < states; ++j) {
    std::vector<double> col;
    for (int i = 0; i < states; ++i) col.push_back(est.p[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)]);
    out.add_column("S" + std::to_string(j), col);
  }
  write_output(a.output, formats::write_table(out, formats::Format::csv));
  return 0;
}

}  // namespace fest::patnet_tool
