// decode() of clers.hpp: the general reverse decoder (reverse_decoder.hpp) restricted to
// the chapter's setting, one closed genus-0 surface.
#include <string>

#include "core/error.hpp"
#include "edgebreaker/clers.hpp"
#include "edgebreaker/corner_table.hpp"
#include "edgebreaker/reverse_decoder.hpp"
#include "edgebreaker/reverse_decoder_steps.hpp"

namespace fest::edgebreaker {

std::vector<Triangle> decode(const Clers& clers) {
  if (clers.empty()) throw bad_input("invalid CLERS string: empty (a closed mesh has at least one E)");
  DecodedConnectivity out;
  try {
    ReverseDecoder decoder(clers.size(), {}, true);
    for (std::size_t i = clers.size(); i-- > 0;) decoder.step(clers[i]);
    out = decoder.finish(true);
    // The chapter's triangulations are simple: no multi-edges, which the general decoder
    // accepts (they arise from cut non-manifold input).
    if (out.components == 1) build_corner_table(out.triangles, out.vertex_count);
  } catch (const Error& e) {
    // Same reasons, in the words of this string-level interface.
    std::string why = e.what();
    const std::string general = "invalid connectivity: ";
    if (why.rfind(general, 0) == 0) why = why.substr(general.size());
    throw bad_input("invalid CLERS string: {}", why);
  }
  if (out.components != 1)
    throw bad_input("invalid CLERS string: #E - #S is {}, a closed genus-0 mesh needs 1", out.components);
  return std::move(out.triangles);
}

}  // namespace fest::edgebreaker
