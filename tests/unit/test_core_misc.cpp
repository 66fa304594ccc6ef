#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "core/progress.hpp"
#include "core/table.hpp"
#include "core/threads.hpp"
#include "core/volume.hpp"

TEST(Progress, RendersBarAndPercentage) {
  EXPECT_EQ(fest::Progress::render("x", 0, 4, 4), "x: [    ]   0%");
  EXPECT_EQ(fest::Progress::render("x", 2, 4, 4), "x: [##  ]  50%");
  EXPECT_EQ(fest::Progress::render("x", 9, 4, 4), "x: [####] 100%");
  EXPECT_EQ(fest::Progress::render("x", 7, 0, 4), "x: 7");
}

TEST(Progress, DisabledWritesNothing) {
  std::FILE* f = std::tmpfile();
  {
    fest::Progress p("work", 10, false, f);
    p.advance(5);
    p.finish();
  }
  EXPECT_EQ(std::ftell(f), 0);
  std::fclose(f);
}

TEST(Progress, EnabledEndsWithNewline) {
  std::FILE* f = std::tmpfile();
  {
    fest::Progress p("work", 10, true, f);
    p.advance(10);
    p.finish();
  }
  std::rewind(f);
  char buf[256] = {};
  std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  ASSERT_GT(n, 0u);
  EXPECT_EQ(buf[n - 1], '\n');
  EXPECT_NE(std::string(buf).find("100%"), std::string::npos);
}

TEST(Threads, ZeroMeansAllCoresNegativeIsUsageError) {
  EXPECT_EQ(fest::resolve_threads(0), fest::available_cores());
  EXPECT_EQ(fest::resolve_threads(3), 3);
  try {
    fest::resolve_threads(-1);
    FAIL();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage);
  }
}

TEST(Volume, IndexIsXFastest) {
  fest::Volume v;
  v.resize(3, 4, 5);
  EXPECT_EQ(v.size(), 60u);
  EXPECT_EQ(v.index(1, 0, 0), 1u);
  EXPECT_EQ(v.index(0, 1, 0), 3u);
  EXPECT_EQ(v.index(0, 0, 1), 12u);
}

TEST(Volume, WorldAppliesSpacingDirectionOrigin) {
  fest::Volume v;
  v.spacing = {2, 3, 4};
  v.origin = {10, 20, 30};
  // A 90-degree rotation about z: voxel x runs along world y, voxel y along world -x.
  v.direction = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  auto w = v.world(1, 1, 1);
  EXPECT_DOUBLE_EQ(w[0], 10 - 3);
  EXPECT_DOUBLE_EQ(w[1], 20 + 2);
  EXPECT_DOUBLE_EQ(w[2], 30 + 4);
}

TEST(Volume, AbsurdSizesAreBadInput) {
  fest::Volume v;
  EXPECT_THROW(v.resize(0, 1, 1), fest::Error);
  EXPECT_THROW(v.resize(1u << 20, 1u << 20, 1u << 20), fest::Error);
  EXPECT_THROW(v.resize(SIZE_MAX, SIZE_MAX, 2), fest::Error);
}

TEST(ScalarType, NamesRoundTrip) {
  for (auto t : {fest::ScalarType::u8, fest::ScalarType::i16, fest::ScalarType::f64}) {
    fest::ScalarType back;
    ASSERT_TRUE(fest::parse_scalar_type(fest::scalar_type_name(t), back));
    EXPECT_EQ(back, t);
  }
  fest::ScalarType unused;
  EXPECT_FALSE(fest::parse_scalar_type("complex", unused));
  EXPECT_EQ(fest::scalar_type_size(fest::ScalarType::i16), 2u);
}

TEST(Table, ColumnsMustAgree) {
  fest::Table t;
  t.add_column("x", {1, 2, 3});
  t.add_column("y", {4, 5, 6});
  EXPECT_EQ(t.rows(), 3u);
  EXPECT_EQ(t.find("y"), 1u);
  EXPECT_EQ(t.find("z"), fest::Table::npos);
  EXPECT_THROW(t.add_column("z", {1}), fest::Error);
  EXPECT_THROW(t.add_column("x", {1, 2, 3}), fest::Error);
}

// lib/core/stopwatch.hpp: readings grow and agree in their units.
#include "core/stopwatch.hpp"

TEST(CoreStopwatch, MsAndSecondsAgree) {
  fest::Stopwatch w;
  const double s = w.seconds();
  const double ms = w.ms();
  EXPECT_GE(s, 0.0);
  EXPECT_GE(ms, s * 1000.0);
  w.restart();
  EXPECT_LE(w.ms(), ms + 1000.0);
}
