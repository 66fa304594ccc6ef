#include "capture/sim_lights.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

using fest::capture::SimLightBank;

TEST(SimLights, OnlyLeavesExactlyOneLightOnAndRecordsChanges) {
  SimLightBank bank({"L0", "L1", "BG"});
  bank.set("BG", true);
  bank.only("L1");
  int lit = 0;
  for (const auto& l : bank.list()) lit += l.on;
  EXPECT_EQ(lit, 1);
  EXPECT_TRUE(bank.list()[1].on);
  bank.only("L1");  // already the only one: no new events
  bank.all_off();
  ASSERT_EQ(bank.timeline().size(), 4u);  // BG on, BG off, L1 on, L1 off
  EXPECT_EQ(bank.timeline()[1].id, "BG");
  EXPECT_FALSE(bank.timeline()[1].on);
  EXPECT_EQ(bank.timeline()[3].id, "L1");
}

TEST(SimLights, UnknownAndDuplicateIdsAreUsageErrors) {
  EXPECT_THROW(SimLightBank({"L0", "L0"}), fest::Error);
  SimLightBank bank({"L0"});
  EXPECT_THROW(bank.set("L9", true), fest::Error);
}
