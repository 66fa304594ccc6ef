#include "brdffit/fit_sample.hpp"

#include "brdffit/parallel_chunks.hpp"
#include "reflectance/lafortune.hpp"

namespace fest::brdffit {

FitSample make_fit_sample(const Eigen::Vector3d& u, const Eigen::Vector3d& v, const Eigen::Vector3d& r, double weight) {
  FitSample s;
  s.xy = static_cast<float>(u.x() * v.x() + u.y() * v.y());
  s.z = static_cast<float>(u.z() * v.z());
  s.uz = static_cast<float>(u.z());
  for (int c = 0; c < 3; ++c) s.r[c] = static_cast<float>(r[c]);
  s.w = static_cast<float>(weight);
  return s;
}

namespace {

void append_local(const LumitexelSet& set, const Lumitexel& l, const Eigen::Matrix3d& frame, FitSample* out) {
  for (std::uint16_t k = 0; k < l.count; ++k) {
    const Sample& s = set.samples[l.first_sample + k];
    const Eigen::Vector3d u = frame.transpose() * s.u_world.cast<double>().normalized();
    const Eigen::Vector3d v = frame.transpose() * s.v_world.cast<double>().normalized();
    out[k] = make_fit_sample(u, v, s.r.cast<double>(), s.weight);
  }
}

}  // namespace

std::vector<FitSample> local_samples(const LumitexelSet& set, int threads) {
  std::vector<FitSample> out(set.samples.size());
  for_each_chunk(set.lumitexels.size(), 4096, threads, [&](std::size_t, std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      const Lumitexel& l = set.lumitexels[i];
      append_local(set, l, reflectance::local_frame(l.n.cast<double>().normalized()), out.data() + l.first_sample);
    }
  });
  return out;
}

void local_samples_of(const LumitexelSet& set, std::size_t i, const Eigen::Vector3d& n, std::vector<FitSample>& out) {
  const Lumitexel& l = set.lumitexels[i];
  out.resize(l.count);
  append_local(set, l, reflectance::local_frame(n), out.data());
}

}  // namespace fest::brdffit
