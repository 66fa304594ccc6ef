#pragma once
// The form factors a shot needs (docs/radiosity.md §3), by one of three engines:
//
//  * hemicube (Cohen & Greenberg 1985): a hemicube at the shooter's centroid sees every
//    element; F_{i->e} is read off, the receiving value by reciprocity
//    F_{e->i} = F_{i->e} A_i / A_e (clamped to 1);
//  * raycast (Wallace, Elmquist & Haines 1989): at each element corner y,
//    F_{dy->i} ~ sum_s V_s cos(theta_y) cos(theta_s) (A_i/S) / (pi r_s^2 + A_i/S) over S
//    stratified points of the shooter, V_s by a shadow ray; an element takes the mean of
//    its corners;
//  * analytic: the exact contour integral of polygon_ff.hpp at each corner, times the
//    fraction of the S shadow rays that are unblocked;
//  * hybrid (Baum, Rushmeier & Winget 1989): the hemicube for visibility only, the
//    exact contour integral from each element's centroid for the value,
//    F_{e->i} = v_e F_{de->i}, v_e = (dF of the pixels showing e) / (dF of all pixels
//    e covers); elements too small to cover a pixel take one shadow ray.
//
// Both ray engines give the shooter's row by reciprocity, F_{i->k} = (1/A_i) sum_{e in k}
// A_e F_{e->i}. Results depend only on the model, never on the thread count.

#include <cstdint>
#include <memory>
#include <vector>

#include "radiosity/bvh.hpp"
#include "radiosity/hemicube.hpp"
#include "radiosity/model.hpp"

namespace fest::radiosity {

enum class Engine { hemicube, raycast, analytic, hybrid };
const char* engine_name(Engine e);

struct FormFactorOptions {
  Engine engine = Engine::hybrid;
  int hemicube_res = 256;
  int samples = 16;
  int threads = 1;
};

class FormFactors {
 public:
  FormFactors(const Model& model, const FormFactorOptions& options);

  // The set of active elements changed (adaptive subdivision): rebuild the item lists.
  void refresh();

  // For shooter patch i: recv[e] = F_{e->i} for every element index (0 for inactive ones
  // and those of the shooter), row[k] = F_{i->k} for every patch k.
  void shoot(int i, std::vector<double>& recv, std::vector<double>& row);

  // F from a point with a normal to patch k, unoccluded contour integral times the
  // visible fraction of `samples` shadow rays (adaptive gathering, §5).
  double point_to_patch(const Eigen::Vector3d& y, const Eigen::Vector3d& n, int k) const;

  const Hemicube* hemicube() const { return hemicube_.get(); }

 private:
  double ray_ff(const Eigen::Vector3d& y, const Eigen::Vector3d& n, int i, const std::vector<Eigen::Vector3d>& pts,
                bool analytic) const;
  std::vector<Eigen::Vector3d> shooter_samples(int i) const;

  const Model& model_;
  FormFactorOptions options_;
  std::unique_ptr<Hemicube> hemicube_;
  Bvh bvh_;
  double offset_;
  std::vector<int> active_;
  std::vector<const Polygon*> items_;
  std::vector<std::uint8_t> draw_;
  std::vector<double> ff_, cover_, vis_;
};

// F_{A->B} between two polygons (the formfactor subcommand and tests): analytic by
// quadrature; hemicube from the centroids of A cut into `cells` x `cells` parts, B cut
// likewise; raycast from the corners of those parts with the engine's formula. No
// occluders.
double polygon_form_factor(const Polygon& a, const Polygon& b, const FormFactorOptions& options, int cells = 16);

}  // namespace fest::radiosity
