// libFuzzer target: raw bytes into read_json (then write_json) and into the CSV and TSV
// table readers (then write_table and describe_table).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "core/error.hpp"
#include "formats/table/table_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)fest::formats::write_json(fest::formats::read_json(bytes));
  } catch (const fest::Error&) {
  }
  using fest::formats::Format;
  for (Format f : {Format::csv, Format::tsv}) {
    try {
      const fest::Table t = fest::formats::read_table(bytes, f);
      (void)fest::formats::describe_table(t);
      (void)fest::formats::read_table(fest::formats::write_table(t, f), f);
    } catch (const fest::Error&) {
    }
  }
  return 0;
}
