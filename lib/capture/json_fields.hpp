#pragma once
// Checked reading of the capture JSON documents (station, plan, sim scene, manifest):
// every error names the file and the JSON path ("station.json: lights[1].position_mm:
// must be an array of 3 numbers"), unknown keys are refused with a "did you mean" hint.

#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fest::capture {

class JsonFields {
 public:
  explicit JsonFields(std::string where) : where_(std::move(where)) {}
  const std::string& where() const { return where_; }

  // bad_input "what (where: path)".
  [[noreturn]] void fail(const std::string& what, const std::string& path) const;
  // The value must be an object whose keys are all in `allowed`.
  void keys(const nlohmann::json& object, const std::string& path, const std::vector<std::string>& allowed) const;

  double number(const nlohmann::json& v, const std::string& path, double lo, double hi) const;
  double positive(const nlohmann::json& v, const std::string& path) const;  // > 0, finite
  int integer(const nlohmann::json& v, const std::string& path, int lo, int hi) const;
  bool boolean(const nlohmann::json& v, const std::string& path) const;
  std::string string(const nlohmann::json& v, const std::string& path) const;  // non-empty
  std::vector<std::string> strings(const nlohmann::json& v, const std::string& path) const;
  // Exactly n finite numbers (n = 0: any count >= 1).
  std::vector<double> numbers(const nlohmann::json& v, const std::string& path, std::size_t n) const;
  std::array<double, 3> vec3(const nlohmann::json& v, const std::string& path) const;
  // 9 numbers, flat row-major or as 3 rows of 3.
  std::array<double, 9> mat3(const nlohmann::json& v, const std::string& path) const;

 private:
  std::string where_;
};

// "path.key" (or "key" at the top level).
std::string json_path(const std::string& parent, const std::string& key);

}  // namespace fest::capture
