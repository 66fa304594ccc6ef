// eos (cereal portable binary) shape model reader; layout in import.hpp.

#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.hpp"
#include "core/face_model_basis.hpp"
#include "formats/facemodel/import.hpp"

namespace fest::formats {

namespace {

class Cursor {
 public:
  Cursor(const std::string& bytes, const std::string& source) : b_(bytes), source_(source) {}
  template <typename T>
  T get(const char* what) {
    if (b_.size() - pos_ < sizeof(T)) throw bad_input("eos model: truncated while reading {} at byte {} ({})", what, pos_, source_);
    T v;
    std::memcpy(&v, b_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  // A cereal-serialised Eigen/cv matrix of float: rows, cols, data column-major.
  std::vector<double> matrix(const char* what, std::int32_t& rows, std::int32_t& cols) {
    rows = get<std::int32_t>(what);
    cols = get<std::int32_t>(what);
    if (rows < 0 || cols < 0) throw bad_input("eos model: {} has negative size ({})", what, source_);
    const std::uint64_t count = static_cast<std::uint64_t>(rows) * static_cast<std::uint64_t>(cols);
    if (count * 4 > b_.size() - pos_) throw bad_input("eos model: {} ({}×{}) runs past the end of the file ({})", what, rows, cols, source_);
    std::vector<double> out(count);
    for (std::uint64_t i = 0; i < count; ++i) out[i] = get<float>(what);
    return out;
  }
  std::size_t remaining() const { return b_.size() - pos_; }

 private:
  const std::string& b_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

}  // namespace

face::Model read_eos_model(const std::string& bytes, const std::string& source) {
  Cursor c(bytes, source);
  const auto version = c.get<std::uint32_t>("class version");
  if (version < 1 || version > 4) throw bad_input("eos model: class version {} unknown (1..4): not an eos .bin? ({})", version, source);
  std::int32_t mr, mc, br, bc, er, ec;
  const auto mean = c.matrix("mean", mr, mc);
  const auto basis = c.matrix("orthonormal_pca_basis", br, bc);
  const auto eig = c.matrix("eigenvalues", er, ec);
  if (mc != 1 || mr % 3 != 0 || mr == 0) throw bad_input("eos model: mean is {}×{}, expected 3p×1 ({})", mr, mc, source);
  if (br != mr) throw bad_input("eos model: basis has {} rows, mean {} ({})", br, mr, source);
  if (static_cast<std::int64_t>(er) * ec != bc) throw bad_input("eos model: {} eigenvalues for {} basis columns ({})", er * ec, bc, source);
  const auto tri_count = c.get<std::uint64_t>("triangle count");
  if (tri_count > c.remaining() / 12) throw bad_input("eos model: {} triangles run past the end of the file ({})", tri_count, source);
  face::Model m;
  m.dims = 3;
  m.points = static_cast<std::size_t>(mr / 3);
  m.components = static_cast<std::size_t>(bc);
  m.mean = mean;
  m.sigma.resize(m.components);
  for (std::size_t i = 0; i < m.components; ++i) {
    if (!(eig[i] > 0)) throw bad_input("eos model: eigenvalue {} is {} (variances must be positive) ({})", i, eig[i], source);
    m.sigma[i] = std::sqrt(eig[i]);  // eos stores variances
  }
  for (std::uint64_t t = 0; t < tri_count; ++t) {
    std::array<std::uint32_t, 3> tri{};
    for (auto& v : tri) {
      const auto i = c.get<std::int32_t>("triangle");
      if (i < 0 || static_cast<std::size_t>(i) >= m.points) throw bad_input("eos model: triangle vertex {} out of range ({})", i, source);
      v = static_cast<std::uint32_t>(i);
    }
    m.triangles.push_back(tri);
  }
  Eigen::MatrixXd B = Eigen::Map<const Eigen::MatrixXd>(basis.data(), br, bc);
  face::set_owned_basis_f32(m, B);
  m.source = "eos model (" + source + ")";
  m.units = "mm";
  return m;
}

}  // namespace fest::formats
