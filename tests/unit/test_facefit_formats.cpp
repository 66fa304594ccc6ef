// Model and landmark files (test plan item 11 and the bad-input list): .mmb round trip
// and rejection of malformed files, the eos reader on files this test writes, the .npz
// reader on fixtures written by an independent Python writer, landmark TSV/.pts/maps.

#include <cstdio>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "formats/facemodel/import.hpp"
#include "formats/facemodel/landmarks_io.hpp"
#include "formats/facemodel/mmb.hpp"
#include "facefit_fixtures.hpp"

using namespace facefit_test;
using namespace fest::formats;

namespace {

fest::Status status_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    return e.status();
  }
  return fest::Status::ok;
}

Model small_model() {
  Model m = g1_model(false, 5);
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  m.landmarks = {{"nose", 7}, {"chin", 11}};
  m.eval_mask = {1, 2, 3};
  m.training_examples = 6;
  return m;
}

std::string eos_bytes(std::uint32_t version, const Model& m) {
  std::string b;
  auto put = [&](const auto& v) { b.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(version);
  auto matrix = [&](std::int32_t rows, std::int32_t cols, const std::function<float(int, int)>& at) {
    put(rows);
    put(cols);
    for (int c = 0; c < cols; ++c)
      for (int r = 0; r < rows; ++r) put(at(r, c));
  };
  const auto n = static_cast<std::int32_t>(m.n()), k = static_cast<std::int32_t>(m.components);
  matrix(n, 1, [&](int r, int) { return static_cast<float>(m.mean[static_cast<std::size_t>(r)]); });
  matrix(n, k, [&](int r, int c) { return static_cast<float>(m.basis_at(static_cast<std::size_t>(r), static_cast<std::size_t>(c))); });
  matrix(k, 1, [&](int r, int) { return static_cast<float>(m.sigma[static_cast<std::size_t>(r)] * m.sigma[static_cast<std::size_t>(r)]); });
  put(static_cast<std::uint64_t>(m.triangles.size()));
  for (const auto& t : m.triangles)
    for (auto v : t) put(static_cast<std::int32_t>(v));
  b += "colour model and more that the reader ignores";
  return b;
}

}  // namespace

TEST(FacefitFormats, MmbRoundTripIsBitExact) {
  const Model m = small_model();
  const std::string bytes = write_mmb(m);
  EXPECT_EQ(bytes.substr(0, 8), "MORPHMB1");
  std::uint64_t H;
  std::memcpy(&H, bytes.data() + 8, 8);
  EXPECT_EQ((16 + H) % 64, 0u);  // arrays start 64-byte aligned
  const Model back = parse_mmb(bytes, {});
  EXPECT_EQ(write_mmb(back), bytes);
  EXPECT_EQ(back.points, m.points);
  EXPECT_EQ(back.components, 5u);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.landmarks, m.landmarks);
  EXPECT_EQ(back.eval_mask, m.eval_mask);
  EXPECT_EQ(back.mean, m.mean);
  for (std::size_t i = 0; i < m.n(); ++i) EXPECT_EQ(back.basis_at(i, 4), m.basis_at(i, 4));
}

TEST(FacefitFormats, MmbIsMemoryMappedFromAFile) {
  const Model m = small_model();
  const std::string path = ::testing::TempDir() + "facefit_model.mmb";
  std::ofstream(path, std::ios::binary) << write_mmb(m);
  const Model back = read_mmb(path, {});
  std::remove(path.c_str());  // the mapping stays valid after unlink
  EXPECT_EQ(back.basis_at(17, 3), m.basis_at(17, 3));
  EXPECT_EQ(status_of([] { read_mmb("/nonexistent/model.mmb", {}); }), fest::Status::io);
}

TEST(FacefitFormats, MalformedModelsAreBadInput) {
  const std::string good = write_mmb(small_model());
  std::string magic = good;
  magic[0] = 'X';
  EXPECT_EQ(status_of([&] { parse_mmb(magic, {}); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { parse_mmb(good.substr(0, good.size() - 100), {}); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { parse_mmb(good.substr(0, 12), {}); }), fest::Status::bad_input);
  std::string json = good;
  json[16] = '#';
  EXPECT_EQ(status_of([&] { parse_mmb(json, {}); }), fest::Status::bad_input);
  std::string huge = good;
  const std::uint64_t H = ~0ull;
  std::memcpy(huge.data() + 8, &H, 8);
  EXPECT_EQ(status_of([&] { parse_mmb(huge, {}); }), fest::Status::bad_input);
}

TEST(FacefitFormats, BasisAndSigmaAreChecked) {
  Model m = small_model();
  Eigen::MatrixXd S = basis_matrix(m);
  S.col(2) *= 1.5;
  set_owned_basis(m, S);
  const std::string bytes = write_mmb(m);
  EXPECT_EQ(status_of([&] { parse_mmb(bytes, {}); }), fest::Status::bad_input);
  MmbReadOptions fix;
  fix.fix_basis = true;
  const Model fixed = parse_mmb(bytes, fix);
  EXPECT_NEAR(basis_matrix(fixed).col(2).norm(), 1.0, 1e-12);

  Model swapped = small_model();
  std::swap(swapped.sigma[0], swapped.sigma[1]);
  std::string warnings;
  const Model reordered = parse_mmb(write_mmb(swapped), {}, &warnings);
  EXPECT_GT(reordered.sigma[0], reordered.sigma[1]);
  EXPECT_EQ(reordered.basis_at(3, 0), swapped.basis_at(3, 1));
  EXPECT_NE(warnings.find("reordered"), std::string::npos);

  Model nan = small_model();
  nan.mean[5] = std::nan("");
  EXPECT_EQ(status_of([&] { parse_mmb(write_mmb(nan), {}); }), fest::Status::bad_input);
}

TEST(FacefitFormats, EosBinaryLayout) {
  const Model m = small_model();
  for (std::uint32_t version : {1u, 3u}) {
    const Model e = read_eos_model(eos_bytes(version, m), "test.bin");
    EXPECT_EQ(e.points, m.points);
    ASSERT_EQ(e.components, m.components);
    EXPECT_NEAR(e.sigma[0], m.sigma[0], 1e-5 * m.sigma[0]);  // stored as variance, float
    EXPECT_EQ(e.triangles, m.triangles);
    EXPECT_NEAR(e.mean[7], m.mean[7], 1e-4);
  }
  const std::string bytes = eos_bytes(1, m);
  EXPECT_EQ(status_of([&] { read_eos_model(bytes.substr(0, 200), "t.bin"); }), fest::Status::bad_input);
  EXPECT_EQ(status_of([&] { read_eos_model(eos_bytes(9, m), "t.bin"); }), fest::Status::bad_input);
}

TEST(FacefitFormats, NpzFixturesFromAnIndependentWriter) {
  const std::string dir = FEST_TEST_DATA_DIR "/facefit/";
  for (const char* name : {"model_stored_f8.npz", "model_bfm_deflated_f4.npz"}) {
    std::string warnings;
    const Model m = read_npz_model(dir + name, &warnings);
    EXPECT_EQ(m.points, 4u) << name;
    ASSERT_EQ(m.components, 2u) << name;
    EXPECT_DOUBLE_EQ(m.sigma[0], 3.0);
    EXPECT_DOUBLE_EQ(m.sigma[1], 2.0);
    EXPECT_DOUBLE_EQ(m.mean[11], 11.0);
    EXPECT_EQ(m.basis_at(0, 0), 1.0f);
    EXPECT_EQ(m.basis_at(5, 1), 1.0f);
    EXPECT_EQ(m.basis_at(1, 0), 0.0f);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3})) << name;
  }
  EXPECT_EQ(status_of([&] { read_npz_model(dir + "make_npz.py", nullptr); }), fest::Status::bad_input);
}

TEST(FacefitFormats, LandmarkFiles) {
  const auto tsv = read_landmarks("# clicked\nid\tu\tv\nnose\t150.5\t120\nchin 151 200.25\n", "lm.tsv");
  ASSERT_EQ(tsv.size(), 2u);
  EXPECT_EQ(tsv[1].id, "chin");
  EXPECT_DOUBLE_EQ(tsv[1].v, 200.25);
  const auto byv = read_landmarks("vertex u v sigma\n12 1 2 0.5\n", "v.tsv");
  EXPECT_TRUE(byv[0].by_vertex);
  EXPECT_EQ(byv[0].vertex, 12u);
  EXPECT_DOUBLE_EQ(byv[0].sigma, 0.5);
  const auto pts = read_landmarks("version: 1\nn_points: 2\n{\n11 21\n31.5 41\n}\n", "a.pts");
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1].id, "2");
  EXPECT_DOUBLE_EQ(pts[1].u, 30.5);  // 1-based iBUG coordinates
  for (const char* bad : {"u v\n1 2\n", "id u v\nnose nan 3\n", "id u v\nnose 1\n", "id u v\nnose 1 2\nnose 3 4\n",
                          "version: 1\nn_points: 3\n{\n1 2\n}\n"})
    EXPECT_EQ(status_of([&] { read_landmarks(bad, "bad.tsv"); }), fest::Status::bad_input) << bad;
  const auto map = read_landmark_map("[landmark_mappings]\n9 = 33  # chin\n\"31\" = 114\n[other]\nx = 1\n", "ibug_to_x.txt");
  EXPECT_EQ(map.size(), 2u);
  EXPECT_EQ(map.at("9"), 33u);
  EXPECT_EQ(map.at("31"), 114u);
  const auto tsvmap = read_landmark_map("name\tvertex\nnose\t5\n", "map.tsv");
  EXPECT_EQ(tsvmap.at("nose"), 5u);
}
