#include "markers/dictionary.hpp"

#include <algorithm>
#include <bitset>
#include <map>
#include <mutex>

#include "core/error.hpp"
#include "markers/dictionary_data.hpp"

namespace fest::markers {

namespace {

int popcount(std::uint64_t x) { return static_cast<int>(std::bitset<64>(x).count()); }

int minimum_distance(const std::vector<std::uint64_t>& codes, int n) {
  int best = n * n;
  std::vector<std::uint64_t> rot(codes.size() * 4);
  for (std::size_t i = 0; i < codes.size(); ++i) {
    rot[4 * i] = codes[i];
    for (int k = 1; k < 4; ++k) rot[4 * i + k] = rotate_code_ccw(rot[4 * i + k - 1], n);
    for (int k = 1; k < 4; ++k) best = std::min(best, popcount(codes[i] ^ rot[4 * i + k]));
  }
  for (std::size_t i = 0; i < codes.size(); ++i)
    for (std::size_t j = i + 1; j < codes.size(); ++j)
      for (int k = 0; k < 4; ++k) best = std::min(best, popcount(codes[i] ^ rot[4 * j + k]));
  return best;
}

Dictionary build(const std::string& name) {
  std::string table = name;
  int count = -1;
  if (name.size() > 4 && name[1] == 'x' && name[3] == '_' && name[0] == name[2]) {
    table = name.substr(0, 3);
    const std::string tail = name.substr(4);
    if (tail == "50" || tail == "100" || tail == "250" || tail == "1000") count = std::stoi(tail);
    else table.clear();
  } else if (name.rfind("apriltag_", 0) != 0 && name != "aruco_original") {
    table.clear();
  }
  for (int i = 0; i < data::k_table_count; ++i) {
    const data::Table& t = data::k_tables[i];
    if (table != t.name) continue;
    Dictionary d;
    d.name = name;
    d.bits = t.bits;
    const int n = count < 0 ? t.count : std::min(count, t.count);
    d.codes.assign(t.codes, t.codes + n);
    d.min_distance = minimum_distance(d.codes, d.bits);
    d.max_correction = std::max(0, static_cast<int>(0.6 * (d.min_distance - 1) / 2.0));
    return d;
  }
  std::string known;
  for (const std::string& k : dictionary_names()) known += (known.empty() ? "" : ", ") + k;
  throw bad_input("unknown marker dictionary '{}' (known: {})", name, known);
}

}  // namespace

std::vector<std::string> dictionary_names() {
  std::vector<std::string> names;
  for (const char* n : {"4x4", "5x5", "6x6", "7x7"})
    for (const char* c : {"50", "100", "250", "1000"}) names.push_back(std::string(n) + "_" + c);
  for (const char* n : {"aruco_original", "apriltag_16h5", "apriltag_25h9", "apriltag_36h10", "apriltag_36h11"})
    names.emplace_back(n);
  return names;
}

const Dictionary& dictionary(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, Dictionary> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(name, build(name)).first;
  return it->second;
}

std::uint64_t rotate_code_ccw(std::uint64_t code, int n) {
  const int nn = n * n;
  std::uint64_t out = 0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const std::uint64_t bit = (code >> (nn - 1 - (c * n + (n - 1 - r)))) & 1u;
      out |= bit << (nn - 1 - (r * n + c));
    }
  return out;
}

Decoded decode(const Dictionary& dict, std::uint64_t sampled, std::uint64_t uncertain) {
  Decoded best;
  int best_errors = dict.bits * dict.bits + 1;
  std::uint64_t grid = sampled, mask = ~uncertain;
  for (int k = 0; k < 4; ++k) {
    for (std::size_t i = 0; i < dict.codes.size(); ++i) {
      const int e = popcount((grid ^ dict.codes[i]) & mask);
      if (e < best_errors) {
        best_errors = e;
        best.id = static_cast<int>(i);
        best.rotation = k;
      }
    }
    grid = rotate_code_ccw(grid, dict.bits);
    mask = rotate_code_ccw(mask & ((1ull << (dict.bits * dict.bits)) - 1), dict.bits) |
           ~((1ull << (dict.bits * dict.bits)) - 1);
  }
  best.bit_errors = best_errors;
  best.erasures = popcount(uncertain);
  if (best_errors > dict.max_correction || 2 * best_errors + best.erasures >= std::max(1, dict.min_distance))
    best.id = -1;
  return best;
}

}  // namespace fest::markers
