// Foreign predicates of the tissue classification (--tissue): class means by k-means and
// the nearest-mean class masks.
#include <cmath>

#include <fmt/format.h>

#include "segbrain/classify.hpp"
#include "segbrain/operator_args.hpp"
#include "segbrain/workspace.hpp"

namespace fest::segbrain {

void Workspace::register_tissue_operators(Engine& engine) {
  using namespace args;
  engine.register_foreign("tissue_classes", 4, "+Img, +Mask, +K, -Means",
      "1-D k-means of the intensities inside Mask (K = 2..8, started at percentiles 10..90), means increasing",
      [this](Engine& e, const std::vector<Term>& a) {
        const double kk = e.eval(a[2]);
        if (!(kk >= 2 && kk <= 8) || kk != std::floor(kk)) throw bad_input("tissue_classes: K must be an integer 2..8, got {}", kk);
        auto means = kmeans_1d(image(name_of(a[0])), mask(name_of(a[1])), int(kk));
        if (means.empty()) return false;
        for (std::size_t c = 0; c < means.size(); ++c) e.measure().push_back({fmt::format("mean{}", c), means[c]});
        return e.unify(a[3], number_list(means));
      });
  engine.register_foreign("classify", 5, "+Img, +Mask, +Means, +Index, -Out", "voxels of Mask whose nearest class mean is the Index-th (0-based)",
      [this](Engine& e, const std::vector<Term>& a) {
        std::vector<Term> items;
        if (!list_items(deref(a[2]), items) || items.empty()) throw bad_input("classify: Means must be a list of numbers");
        std::vector<double> means;
        for (const auto& t : items) means.push_back(e.eval(t));
        const double idx = e.eval(a[3]);
        if (!(idx >= 0 && idx < double(means.size()))) throw bad_input("classify: index {} outside the {} means", idx, means.size());
        return create(e, a[4], mask_object(nearest_class(image(name_of(a[0])), mask(name_of(a[1])), means, std::size_t(idx))));
      });
}

}  // namespace fest::segbrain
