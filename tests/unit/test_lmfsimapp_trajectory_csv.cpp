// lmfsim's trajectory CSV (tools/lmfsim/trajectory_csv): rows written by append_row read
// back exactly at the printed precision, and malformed rows are refused with the line.

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"
#include "trajectory_csv.hpp"

using namespace fest::lmfsim_tool;

TEST(LmfsimTrajectoryCsv, WrittenRowsReadBack) {
  TrajectoryRow r;
  r.frame = 12;
  r.t = 0.25;
  r.body = "arm";
  r.p = {1, -2, 0.5};
  r.q = fest::lmfsim::Quat(1, 0, 0, 0);
  r.v = {0, 0, -9.81};
  r.w = {0.125, 0, 0};
  std::string csv = trajectory_header();
  append_row(csv, r);
  const auto rows = parse_trajectory(csv, "t.csv");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].frame, 12);
  EXPECT_EQ(rows[0].body, "arm");
  EXPECT_EQ(rows[0].v.z(), -9.81);  // 9 significant digits print -9.81 exactly as typed
  EXPECT_EQ(rows[0].w.x(), 0.125);
}

TEST(LmfsimTrajectoryCsv, RefusesMalformedRows) {
  const std::string h = trajectory_header();
  auto message = [](const std::string& text) {
    try {
      parse_trajectory(text, "t.csv");
    } catch (const fest::Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(h + "0,0,b,1,2,3,1,0,0,0,0,0,0,0,0\n").find("expected 16 fields, got 15 (t.csv:2)"), std::string::npos);
  EXPECT_NE(message(h + "0,0,b,1,x,3,1,0,0,0,0,0,0,0,0,0\n").find("field 5"), std::string::npos);
  EXPECT_NE(message(h + "1.5,0,b,1,2,3,1,0,0,0,0,0,0,0,0,0\n").find("whole number"), std::string::npos);
  // A NUL byte inside a number used to end the field silently ("1\0junk" read as 1).
  std::string nul = h + "0,0,b,1,2,3,1,0,0,0,0,0,0,0,0,0\n";
  nul.insert(nul.size() - 2, std::string("\0junk", 5));
  EXPECT_NE(message(nul).find("field 16"), std::string::npos);
  EXPECT_NE(message("frame,t\n").find("not an lmfsim trajectory"), std::string::npos);
}
