// The CLERS string form: one upper-case letter per symbol, as the literature prints it.
#include "edgebreaker/clers.hpp"

#include "core/error.hpp"

namespace fest::edgebreaker {

char to_char(Symbol s) noexcept {
  switch (s) {
    case Symbol::C: return 'C';
    case Symbol::L: return 'L';
    case Symbol::E: return 'E';
    case Symbol::R: return 'R';
    case Symbol::S: return 'S';
  }
  return '?';  // unreachable for valid enumerators; keeps -Wreturn-type quiet
}

std::string to_string(const Clers& clers) {
  std::string out;
  out.reserve(clers.size());
  for (Symbol s : clers) out.push_back(to_char(s));
  return out;
}

Clers parse_clers(std::string_view text) {
  Clers out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    switch (text[i]) {
      case 'C': out.push_back(Symbol::C); break;
      case 'L': out.push_back(Symbol::L); break;
      case 'E': out.push_back(Symbol::E); break;
      case 'R': out.push_back(Symbol::R); break;
      case 'S': out.push_back(Symbol::S); break;
      default: {
        // Show printable characters as themselves and anything else as a byte value, so
        // the one-line message stays one line whatever the input holds.
        const auto byte = static_cast<unsigned char>(text[i]);
        const std::string shown = byte > 0x20 && byte < 0x7f ? fmt::format("'{}'", text[i])
                                                             : fmt::format("byte 0x{:02x}", byte);
        throw bad_input("invalid CLERS string: {} at position {} is not one of C, L, E, R, S", shown, i);
      }
    }
  }
  return out;
}

}  // namespace fest::edgebreaker
