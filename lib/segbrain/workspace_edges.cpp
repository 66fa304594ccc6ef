// Foreign predicates of the second-order edge operators: the chapter's Marr-Hildreth
// operator and the Laplacian of Gaussian behind it.
#include <cmath>

#include "segbrain/edges.hpp"
#include "segbrain/operator_args.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain {

void Workspace::register_edge_operators(Engine& engine) {
  using namespace args;
  engine.register_foreign("laplacian_of_gaussian", 4, "+Img, +SigmaMM, +Scope, -Out",
      "sum of second Gaussian derivatives (per mm2), in-plane for slice(axial)",
      [this](Engine& e, const std::vector<Term>& a) {
        const double sigma = e.eval(a[1]);
        if (!(sigma > 0)) throw bad_input("laplacian_of_gaussian: sigma must be > 0, got {}", sigma);
        return create(e, a[3], image_object(laplacian_of_gaussian(grid_, image(name_of(a[0])), sigma, in_plane_scope(a[2]))));
      });
  engine.register_foreign("marr_hildreth", 5, "+Img, +SigmaMM, +Slope, +Scope, -Edges",
      "zero crossings of the LoG whose jump is >= Slope x max|LoG|; 4-neighbours in slice(axial), 6 in volume",
      [this](Engine& e, const std::vector<Term>& a) {
        const double sigma = e.eval(a[1]), slope = e.eval(a[2]);
        if (!(sigma > 0)) throw bad_input("marr_hildreth: sigma must be > 0, got {}", sigma);
        if (!(slope >= 0 && slope < 1)) throw bad_input("marr_hildreth: slope must lie in [0, 1), got {}", slope);
        Mask m = marr_hildreth(grid_, image(name_of(a[0])), sigma, slope, in_plane_scope(a[3]));
        std::size_t n = 0;
        for (auto v : m) n += v;
        e.measure() = {{"edge_fraction", m.empty() ? 0.0 : double(n) / double(m.size())}};
        return create(e, a[4], mask_object(std::move(m)));
      });
}

}  // namespace fest::segbrain
