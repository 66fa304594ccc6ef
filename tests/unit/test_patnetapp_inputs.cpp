// `patnet run`'s input files (tools/patnet/inputs): inputs that once escaped the events
// reader as a JSON library exception under fuzz_patnet_inputs (tests/data/regress/
// patnet_inputs/: a number beyond double's range is nlohmann's out_of_range, not its
// parse_error) must now be one bad_input error naming the line.
#include <filesystem>

#include <gtest/gtest.h>

#include "expect_error.hpp"
#include "inputs.hpp"
#include "testdata.hpp"

TEST(PatnetInputs, FuzzFindingsAreBadInput) {
  int replayed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(fest::test::fixture("regress/patnet_inputs"))) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = fest::test::slurp(entry.path().string());
    fest::patnet::Machine m;
    fest::test::expect_bad_input([&] { fest::patnet_tool::parse_events(bytes, "events.jsonl", m); }, "events.jsonl:1");
    ++replayed;
  }
  EXPECT_GE(replayed, 2);
}

TEST(PatnetInputs, EventsAndTableRead) {
  fest::patnet::Machine m;
  const auto ev = fest::patnet_tool::parse_events(fest::test::slurp(fest::test::fixture("patnet/inputs/events.jsonl")), "e", m);
  ASSERT_EQ(ev.size(), 5u);
  EXPECT_EQ(ev[1].name, "greeter");
  const auto t = fest::patnet_tool::parse_table(fest::test::slurp(fest::test::fixture("patnet/inputs/table.tsv")), "t", "sensor");
  EXPECT_EQ(t.rows.size(), 3u);
}
