#pragma once
// Tables (CSV/TSV with one header line of column names, numeric cells) and JSON.

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "core/table.hpp"
#include "formats/detect.hpp"

namespace fest::formats {

Table read_table(std::string_view bytes, Format format);  // csv or tsv
std::string write_table(const Table& table, Format format);
nlohmann::json describe_table(const Table& table);

// Throws Status::bad_input with the parser's position for malformed JSON; nesting
// deeper than 512 levels is refused (a stack-exhaustion guard).
nlohmann::json read_json(std::string_view bytes);
std::string write_json(const nlohmann::json& doc);

// read_json in the (bytes, format) shape of the other readers, for formats::parse().
inline nlohmann::json read_json_document(std::string_view bytes, Format) { return read_json(bytes); }  // 2-space indent, trailing newline

}  // namespace fest::formats
