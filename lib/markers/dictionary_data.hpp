#pragma once
// The embedded bit tables (dictionary_data.cpp, generated once by
// scripts/gen-marker-dictionaries.cpp from OpenCV's published dictionaries).

#include <cstdint>

namespace fest::markers::data {

struct Table {
  const char* name;  // "4x4", "apriltag_36h11", ...
  int bits;          // n: the marker has n x n data cells inside a one-cell black border
  int count;
  const std::uint64_t* codes;  // row-major, first cell = most significant bit, 1 = white
};

extern const Table k_tables[];
extern const int k_table_count;

}  // namespace fest::markers::data
