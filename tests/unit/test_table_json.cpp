// JSON documents: parsing, the 2-space writer, errors with byte positions, and the
// nesting guard that keeps "[[[[..." from exhausting the stack.
#include <filesystem>
#include <functional>

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "formats/table/table_io.hpp"
#include "expect_error.hpp"
#include "testdata.hpp"

using fest::formats::read_json;
using fest::formats::write_json;

namespace {

using fest::test::expect_bad_input;

}  // namespace

TEST(TableJson, ParsesAndWritesWithTwoSpaceIndent) {
  const nlohmann::json doc = read_json(R"({"b": [1, 2.5, "x]["], "a": {"t": true, "n": null}})");
  EXPECT_EQ(doc["b"][1], 2.5);
  EXPECT_EQ(doc["b"][2], "x][");
  EXPECT_EQ(write_json(nlohmann::json{{"k", {1, 2}}}), "{\n  \"k\": [\n    1,\n    2\n  ]\n}\n");
}

TEST(TableJson, RoundTrip) {
  const nlohmann::json doc = {{"name", "t1"}, {"dims", {128, 128, 62}}, {"nested", {{"pi", 3.141592653589793}}}};
  EXPECT_EQ(read_json(write_json(doc)), doc);
}

TEST(TableJson, NestingUpTo512IsAccepted) {
  const std::string deep = std::string(512, '[') + std::string(512, ']');
  const nlohmann::json doc = read_json(deep);
  EXPECT_TRUE(doc.is_array());
  EXPECT_FALSE(write_json(doc).empty());
}

TEST(TableJsonMalformed, DeepNestingBombIsRefused) {
  expect_bad_input([] { read_json(std::string(513, '[') + std::string(513, ']')); }, "deeper than 512");
  expect_bad_input([] { read_json(std::string(1000000, '[')); }, "at byte 513");
  expect_bad_input([] { read_json(std::string(100000, '{')); }, "deeper");
  // Brackets inside strings do not count as nesting.
  EXPECT_NO_THROW(read_json("\"" + std::string(2000, '[') + "\""));
  EXPECT_NO_THROW(read_json("[\"\\\"[[[[\"]"));
}

TEST(TableJsonMalformed, SyntaxErrorsGiveBytePosition) {
  expect_bad_input([] { read_json(""); }, "byte");
  expect_bad_input([] { read_json("{\"a\": 1,}"); }, "byte 9");
  expect_bad_input([] { read_json("[1, 2"); }, "byte");
  expect_bad_input([] { read_json("{\"a\": tru}"); }, "byte");
  expect_bad_input([] { read_json("[1] [2]"); }, "byte");
  expect_bad_input([] { read_json("\"\xff\xfe\""); }, "byte");
  expect_bad_input([] { read_json("[1e999]"); }, "");
}

TEST(TableJsonMalformed, WriterRefusesInvalidUtf8) {
  expect_bad_input([] { write_json(nlohmann::json(std::string("\xff\xfe"))); }, "UTF-8");
}

// Every input the fuzzer once crashed on (tests/data/regress/json/) must now give a clean
// result or a bad_input error, as JSON and as a CSV/TSV table.
TEST(TableJson, FuzzRegressionInputs) {
  const std::filesystem::path dir = fest::test::fixture("regress/json");
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "no regression inputs";
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string bytes = fest::test::slurp(entry.path().string());
    try {
      (void)write_json(read_json(bytes));
    } catch (const fest::Error& e) {
      EXPECT_EQ(e.status(), fest::Status::bad_input) << entry.path() << ": " << e.what();
    }
    for (auto f : {fest::formats::Format::csv, fest::formats::Format::tsv}) {
      try {
        (void)fest::formats::read_table(bytes, f);
      } catch (const fest::Error& e) {
        EXPECT_EQ(e.status(), fest::Status::bad_input) << entry.path() << ": " << e.what();
      }
    }
  }
}
