// read_json / write_json (declared in table_io.hpp).
#include <string>

#include "core/error.hpp"
#include "core/quote.hpp"
#include "formats/table/table_io.hpp"

namespace fest::formats {

namespace {

constexpr std::size_t kMaxJsonDepth = 512;

// Refuses nesting deeper than kMaxJsonDepth before nlohmann builds (and later dumps or
// compares, recursively) a structure that deep. Brackets inside strings do not count.
void check_depth(std::string_view bytes) {
  std::size_t depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const char c = bytes[i];
    if (in_string) {
      if (c == '\\') ++i;  // skip the escaped character
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw bad_input("JSON nests deeper than {} levels at byte {}", kMaxJsonDepth, i + 1);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

}  // namespace

nlohmann::json read_json(std::string_view bytes) {
  check_depth(bytes);
  try {
    return nlohmann::json::parse(bytes.begin(), bytes.end());
  } catch (const nlohmann::json::parse_error& e) {
    throw bad_input("{}", json_failure_words(e.what(), e.byte, bytes));
  } catch (const nlohmann::json::exception& e) {
    throw bad_input("JSON: {}", json_failure_words(e.what(), 0, bytes));
  }
}

std::string write_json(const nlohmann::json& doc) {
  try {
    return doc.dump(2) + "\n";
  } catch (const nlohmann::json::exception& e) {
    // Only invalid UTF-8 in a string can fail here (type_error 316).
    throw bad_input("JSON: cannot write a text that is not UTF-8 ({})", json_failure_words(e.what(), 0, {}));
  }
}

}  // namespace fest::formats
