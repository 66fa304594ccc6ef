#include <gtest/gtest.h>

#include "core/error.hpp"

using fest::Status;

TEST(Error, ExitCodesAreTheDesignTable) {
  // README "Conventions" (exit status): these numbers are the interface of every tool.
  EXPECT_EQ(fest::Error(Status::ok, "").exit_code(), 0);
  EXPECT_EQ(fest::Error(Status::failure, "").exit_code(), 1);
  EXPECT_EQ(fest::usage_error("x").exit_code(), 2);
  EXPECT_EQ(fest::bad_input("x").exit_code(), 3);
  EXPECT_EQ(fest::io_error("x").exit_code(), 4);
  EXPECT_EQ(fest::Error(Status::device_not_found, "").exit_code(), 5);
  EXPECT_EQ(fest::Error(Status::device_error, "").exit_code(), 6);
  EXPECT_EQ(fest::Error(Status::timeout, "").exit_code(), 7);
  EXPECT_EQ(fest::Error(Status::permission, "").exit_code(), 8);
}

TEST(Error, MessagesAreFormatted) {
  fest::Error e = fest::bad_input("{} vertices in {} bytes", 12, 300);
  EXPECT_STREQ(e.what(), "12 vertices in 300 bytes");
  EXPECT_EQ(e.status(), Status::bad_input);
  EXPECT_STREQ(fest::status_name(Status::io), "io");
}

TEST(Error, LocationNamesStandardInput) {
  EXPECT_EQ(fest::with_location("truncated", "a.ply"), "truncated (a.ply)");
  EXPECT_EQ(fest::with_location("truncated", "-"), "truncated (standard input)");
}
