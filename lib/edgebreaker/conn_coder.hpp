#pragma once
// Entropy coding of the CLERS string (docs/ebcode.md §4): the raw 1/3-bit code, the chapter's
// static state-machine coder (state_machine.hpp) and the adaptive valence-context coder.
// Symbols are coded in decoding order; the encoder runs the same ReverseDecoder as the
// decoder to know each symbol's context, so the two cannot drift apart.

#include <cstdint>
#include <string>
#include <string_view>

#include "edgebreaker/reverse_decoder.hpp"
#include "edgebreaker/traversal.hpp"

namespace fest::edgebreaker {

enum class ConnMode : std::uint8_t { raw = 0, static_model = 1, adaptive = 2 };

struct ConnEncoded {
  std::string bytes;
  bool exclusion = true;  // C was excluded where the decoder knows it impossible
  DecodedConnectivity decoded;  // what the decoder will rebuild (G ids); empty unless asked
};

// `model` names a static model (state_machine.hpp) for ConnMode::static_model. With
// exclusion, the adaptive coder gives C no probability where c_possible() is false; an
// input that violates this (only non-simple meshes can) is coded again without it, and
// the static mode then throws runtime_failure (the caller falls back to adaptive).
// With `decode`, the result carries what the decoder rebuilds (checked with `verify`);
// the decoded connectivity depends on the symbols only, not on the coder, so a caller
// that tries several coders asks for it once. Without it the static and raw coders do
// not run the decoder at all (their contexts do not need it): half of the work of
// trying both coders.
// `opposite` asks for DecodedConnectivity::opposite (the multi-way predictor's).
ConnEncoded encode_connectivity(const Connectivity& code, ConnMode mode, int model, bool verify, bool decode = true,
                                bool opposite = true);

// Inverse; throws bad_input for any stream that is not one encode_connectivity wrote.
// `valence` asks for DecodedConnectivity::valence.
DecodedConnectivity decode_connectivity(std::string_view bytes, std::size_t symbols, std::vector<HandleEvent> events,
                                        ConnMode mode, int model, bool exclusion, bool verify, bool opposite = true,
                                        bool valence = false);

}  // namespace fest::edgebreaker
