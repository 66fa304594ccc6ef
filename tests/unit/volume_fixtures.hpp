#pragma once
// The contract of the int16 fixtures in tests/data/volume/ (be_int16.nii, lps_ascii.nrrd,
// msb_short.mha; made by make_fixtures.py): a 4x3x2 grid holding v = x + 10y + 100z - 50.

#include <array>
#include <cstddef>

#include <gtest/gtest.h>

#include "core/volume.hpp"

namespace fest::test {

inline void expect_formula_int16_fixture(const fest::Volume& v) {
  ASSERT_EQ(v.dims, (std::array<std::size_t, 3>{4, 3, 2}));
  EXPECT_EQ(v.type, fest::ScalarType::i16);
  for (std::size_t z = 0; z < 2; ++z)
    for (std::size_t y = 0; y < 3; ++y)
      for (std::size_t x = 0; x < 4; ++x) EXPECT_EQ(v.at(x, y, z), double(x) + 10.0 * y + 100.0 * z - 50.0);
}

}  // namespace fest::test
