#pragma once
// SHA-256 of a byte string as 64 lower-case hex digits (FIPS 180-4, via OpenSSL).

#include <string>
#include <string_view>

namespace fest {

std::string sha256_hex(std::string_view bytes);

}  // namespace fest
