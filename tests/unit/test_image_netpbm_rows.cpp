// formats::NetpbmRowFile: bands of rows read from raw PGM/PPM/PAM and PFM files give the
// samples read_image gives for the whole file (8/16 bits, 1-4 channels, PFM bottom-up in
// both byte orders); files it cannot stream are left to read_image; bad headers refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/error.hpp"
#include "formats/image/image_io.hpp"
#include "formats/image/netpbm_rows.hpp"
#include "test_image_helpers.hpp"

using fest::formats::Format;
using fest::formats::NetpbmRowFile;

namespace {

class NetpbmRowsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    char pattern[] = "/tmp/fest-netpbm-rows-XXXXXX";
    ASSERT_NE(mkdtemp(pattern), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::system(("rm -rf '" + dir_ + "'").c_str()); }
  std::string write(const std::string& name, const std::string& bytes) {
    const std::string path = dir_ + "/" + name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }
  std::string dir_;
};

// Every band split [0, a), [a, b), [b, h) against the whole-file decode.
void expect_same_rows(const std::string& path, const cv::Mat& expected) {
  const auto f = NetpbmRowFile::open(path);
  ASSERT_NE(f, nullptr) << path;
  ASSERT_EQ(f->cv_type(), expected.type());
  ASSERT_EQ(f->header().width, expected.cols);
  ASSERT_EQ(f->header().height, expected.rows);
  const int h = expected.rows;
  for (int a : {1, h / 3})
    for (int b : {a + 1, h - 1}) {
      if (b <= a || b >= h) continue;
      for (auto [first, last] : {std::pair{0, a}, {a, b}, {b, h}}) {
        cv::Mat band(last - first, expected.cols, expected.type());
        f->read_rows(first, last, band.data);
        EXPECT_EQ(cv::norm(band, expected.rowRange(first, last), cv::NORM_INF), 0) << path << " rows " << first << "-" << last;
      }
    }
}

}  // namespace

TEST_F(NetpbmRowsTest, BandsMatchTheWholeFileDecode) {
  struct Case {
    const char* name;
    Format format;
    int depth, channels;
  };
  for (const Case& c : {Case{"g8.pgm", Format::pgm, CV_8U, 1}, Case{"rgb8.ppm", Format::ppm, CV_8U, 3},
                        Case{"rgb16.ppm", Format::ppm, CV_16U, 3}, Case{"ga16.pam", Format::pam, CV_16U, 2},
                        Case{"rgba8.pam", Format::pam, CV_8U, 4}, Case{"g.pfm", Format::pfm, CV_32F, 1},
                        Case{"rgb.pfm", Format::pfm, CV_32F, 3}}) {
    fest::Image img;
    img.pixels = fest::test::random_image(37, 23, c.depth, c.channels);
    const std::string path = write(c.name, fest::formats::write_image(img, c.format));
    expect_same_rows(path, fest::formats::read_image(fest::formats::write_image(img, c.format), c.format).pixels);
    EXPECT_EQ(NetpbmRowFile::open(path)->color_space(),
              c.format == Format::pfm ? fest::ColorSpace::linear : fest::ColorSpace::srgb);
  }
}

TEST_F(NetpbmRowsTest, BigEndianPfm) {
  // "PF" with a positive scale: big-endian samples, bottom row first.
  std::string bytes = "Pf\n2 3\n1.0\n";
  const float values[6] = {1.5f, -2.0f, 3.25f, 4.0f, 0.125f, 1e30f};  // file order: bottom row first
  for (float v : values) {
    unsigned char b[4];
    std::memcpy(b, &v, 4);
    bytes += std::string{char(b[3]), char(b[2]), char(b[1]), char(b[0])};
  }
  const std::string path = write("be.pfm", bytes);
  cv::Mat expected(3, 2, CV_32FC1);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 2; ++x) expected.at<float>(2 - y, x) = values[y * 2 + x];
  expect_same_rows(path, expected);
  EXPECT_EQ(cv::norm(fest::formats::read_image(bytes, Format::pfm).pixels, expected, cv::NORM_INF), 0);
}

TEST_F(NetpbmRowsTest, LeavesOtherFilesToTheWholeFileReader) {
  fest::Image img;
  img.pixels = fest::test::random_image(5, 4, CV_8U, 1);
  fest::formats::ImageWriteOptions ascii;
  ascii.ascii = true;
  EXPECT_EQ(NetpbmRowFile::open(write("a.pgm", fest::formats::write_image(img, Format::pgm, ascii))), nullptr);
  EXPECT_EQ(NetpbmRowFile::open(write("m.pgm", "P5\n2 1\n1000\n\x01\x02\x03\x04")), nullptr);  // maxval 1000
  EXPECT_EQ(NetpbmRowFile::open(write("x.png", fest::formats::write_image(img, Format::png))), nullptr);
  EXPECT_EQ(NetpbmRowFile::open(dir_ + "/missing.pgm"), nullptr);
  EXPECT_EQ(NetpbmRowFile::open("-"), nullptr);
  EXPECT_EQ(NetpbmRowFile::open(dir_), nullptr);  // a folder
}

TEST_F(NetpbmRowsTest, RefusesWhatReadImageRefuses) {
  for (const std::string& bytes : {std::string("P5\n4 4\n255\n0123"), std::string("Pf\n0 10\n-1.0\n"),
                                  std::string("Pf\n65536 65536\n-1.0\n") + std::string(4096, '\0')}) {
    const std::string path = write("bad.pgm", bytes);
    try {
      NetpbmRowFile::open(path);
      ADD_FAILURE() << "accepted " << bytes.substr(0, 20);
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input);
      EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
  }
}
