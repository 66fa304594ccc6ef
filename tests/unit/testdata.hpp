#pragma once
// Paths to test data for unit tests.
//  * fixture("x.ply")        -> tests/data/x.ply (small files committed with the source)
//  * FEST_REQUIRE_TESTDATA(p, "meshes/bunny00.off") sets std::string p to the fetched
//    real-data file (scripts/fetch-test-data.sh), or skips the test with a message.

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

namespace fest::test {

inline std::string fixture(const std::string& name) { return std::string(FEST_TEST_DATA_DIR) + "/" + name; }

inline std::string testdata_dir() {
  const char* env = std::getenv("FEST_TESTDATA");
  return env ? std::string(env) : std::string();
}

inline bool testdata_available() {
  std::string dir = testdata_dir();
  return !dir.empty() && std::ifstream(dir + "/MANIFEST").good();
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace fest::test

#define FEST_REQUIRE_TESTDATA(var, relpath)                                                   \
  if (!::fest::test::testdata_available())                                                    \
    GTEST_SKIP() << "real test data not fetched (run scripts/fetch-test-data.sh); needs "     \
                 << (relpath);                                                                \
  const std::string var = ::fest::test::testdata_dir() + "/" + (relpath)
