// fcompare: the comparison of a kind chosen by the files' kind, and the main check.

#include "measure.hpp"

namespace fest::fcompare_tool {

using namespace fest::formats;
using fest::compare::Metrics;

void require_main(Metrics& m, const std::string& metric, const CompareOptions& opt) {
  if (opt.tol_given)
    m.require(compare::Check{metric, true, opt.tol});
  else
    m.require(metric, "<=", opt.tol);
}

void measure(const Input& a, const Input& b, const CompareOptions& opt, Metrics& m) {
  switch (kind_of(a.format)) {
    case Kind::mesh: compare_meshes(a, b, opt, m); break;
    case Kind::image: compare_images(a, b, opt, m); break;
    case Kind::volume: compare_volumes(a, b, opt, m); break;
    case Kind::table: compare_tables(a, b, opt, m); break;
    case Kind::dataset: compare_datasets(a, b, opt, m); break;
    case Kind::json: compare_json(a, b, opt, m); break;
  }
}

}  // namespace fest::fcompare_tool
