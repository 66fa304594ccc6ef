#pragma once
// ebdecode's command (docs/ebdecode.md), taking its typed options. main.cpp fills these from
// flags; everything else in this folder is the fest_ebdecode_app library.

#include <optional>
#include <string>

#include "formats/detect.hpp"

namespace fest::ebdecode_tool {

struct DecodeOptions {
  std::string input = "-";
  std::string output = "-";
  std::optional<formats::Format> format;  // none: from the output's name, PLY on standard output
  bool ascii = false;                     // ASCII PLY
  bool info = false;                      // print the header as JSON instead of decoding
  std::string report;                     // JSON report path; empty: none
  bool stitch = true;
  bool verify = true;
};

// .ebm (or Draco) -> mesh file, or the header as JSON with `info`.
int decode_command(const DecodeOptions& o);

// --to's value (ply, plya, obj, off) into o.format and o.ascii; usage error otherwise.
void parse_output_format(const std::string& name, DecodeOptions& o);

}  // namespace fest::ebdecode_tool
