// fest_resample_app called with typed options: resizing a constant image gives the same
// constant, because every kernel's weights sum to one (docs/resample.md) and the sRGB
// decode/encode of one code value round-trips.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>

#include "commands.hpp"

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream f(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

TEST(ResampleApp, ConstantImageStaysConstant) {
  const auto dir = std::filesystem::temp_directory_path() / ("fest_resampleapp_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const int w = 12, h = 9;
  const unsigned char value = 100;
  {
    std::ofstream f(dir / "in.pgm", std::ios::binary);
    f << "P5\n" << w << " " << h << "\n255\n" << std::string(static_cast<std::size_t>(w * h), static_cast<char>(value));
  }
  for (const char* filter : {"mitchell", "lanczos3", "box", "gaussian"}) {
    fest::resample_tool::ResizeArgs a;
    a.input = (dir / "in.pgm").string();
    a.out.output = (dir / "out.pgm").string();
    a.width = 5;  // height keeps the aspect ratio: round(9 * 5 / 12) = 4
    a.filter = fest::sampling::make_kernel(filter);
    a.threads = 1;
    ASSERT_EQ(fest::resample_tool::run_resize(a), 0) << filter;
    const std::string out = slurp(dir / "out.pgm");
    const std::size_t n = 5 * 4;
    ASSERT_GE(out.size(), n) << filter;
    EXPECT_EQ(out.substr(0, 2), "P5");
    EXPECT_EQ(out.substr(out.size() - n), std::string(n, static_cast<char>(value))) << filter;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
