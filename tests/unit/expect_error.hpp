#pragma once
// expect_bad_input(f, needle): f must throw fest::Error with Status::bad_input, and the
// message must contain `needle` (a readable message is part of the contract).
// usage_message(f): the message of the usage error f must throw ("" and a failure if none).

#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace fest::test {

inline void expect_bad_input(const std::function<void()>& f, const std::string& needle = "") {
  try {
    f();
    ADD_FAILURE() << "no error thrown (expected one mentioning '" << needle << "')";
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::bad_input) << e.what();
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << "message: " << e.what();
  }
}

inline std::string usage_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const fest::Error& e) {
    EXPECT_EQ(e.status(), fest::Status::usage) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error thrown (expected a usage error)";
  return {};
}

}  // namespace fest::test
