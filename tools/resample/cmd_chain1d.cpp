// resample chain1d: the 1-D prefilter -> sample -> display chain (Fig. 10.10) and the edge
// experiment (Fig. 10.2), printed as JSON.
#include <optional>

#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "core/error.hpp"
#include "core/file_io.hpp"
#include "core/reworded_error.hpp"
#include "sampling/chain1d.hpp"
#include "sampling/frequency_response.hpp"

namespace fest::resample_tool {

using namespace fest;
using namespace fest::sampling;

int run_chain1d(const ChainArgs& a) {
  if (!a.edge.empty()) {
    if (a.edge.size() > 2) throw usage_error("--edge takes x0 or x0,x1");
    const auto crossings = with_rewording({{"edge experiment:", "chain1d --edge:"}}, [&] {
      return edge_experiment(a.edge[0], a.edge.size() == 2 ? std::optional<double>(a.edge[1]) : std::nullopt);
    });
    nlohmann::json j{{"experiment", "fig10.2"}, {"prefilter", "box:width=2"}, {"recon", "tent:width=2"},
                     {"threshold", 0.5}, {"edges", a.edge}, {"recovered", crossings}};
    write_output("-", j.dump() + "\n");
    return 0;
  }
  const Kernel &p = a.prefilter, &r = a.recon;
  if (r.nearest) throw usage_error("chain1d: the display filter cannot be point sampling");
  nlohmann::json results = nlohmann::json::array();
  for (double f : a.freq) {
    const ChainResult c = analyse_chain(p, r, f, a.terms);
    nlohmann::json aliases = nlohmann::json::array();
    for (int k = -2; k <= 2; ++k)
      if (k != 0) aliases.push_back({{"k", k}, {"freq", f - k}, {"R", frequency_response(r, f - k)},
                                     {"amplitude", c.amplitude_at(k)}});
    results.push_back({{"f", f}, {"P", c.prefilter}, {"A0", c.survived}, {"alias_rms", c.alias_rms}, {"mse", c.mse},
                       {"aliases", aliases}});
  }
  nlohmann::json j{{"prefilter", p.name}, {"recon", r.name}, {"terms", a.terms}, {"results", results}};
  write_output("-", j.dump() + "\n");
  return 0;
}

}  // namespace fest::resample_tool
