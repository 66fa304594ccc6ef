// The three connectivity coders of docs/ebcode.md §4 over one range coder.
#include "edgebreaker/conn_coder.hpp"

#include <algorithm>
#include <array>

#include "core/error.hpp"
#include "edgebreaker/range_coder.hpp"
#include "edgebreaker/reverse_decoder_steps.hpp"
#include "edgebreaker/state_machine.hpp"

namespace fest::edgebreaker {
namespace {

constexpr int symbol_count = 5;

// Rossignac's code, MSB first: C = 0, S = 100, R = 101, L = 110, E = 111.
void put_raw(RangeEncoder& enc, Symbol s) {
  switch (s) {
    case Symbol::C: enc.bypass(0); return;
    case Symbol::S: enc.bypass(1), enc.bypass_bits(0b00, 2); return;
    case Symbol::R: enc.bypass(1), enc.bypass_bits(0b01, 2); return;
    case Symbol::L: enc.bypass(1), enc.bypass_bits(0b10, 2); return;
    case Symbol::E: enc.bypass(1), enc.bypass_bits(0b11, 2); return;
  }
}
Symbol get_raw(RangeDecoder& dec) {
  if (dec.bypass() == 0) return Symbol::C;
  switch (dec.bypass_bits(2)) {
    case 0: return Symbol::S;
    case 1: return Symbol::R;
    case 2: return Symbol::L;
    default: return Symbol::E;
  }
}

// Adaptive frequencies per context (valence class x previous symbol x C possible):
// 16 per symbol at the start, +32 per occurrence, halved (rounding up) past 2^16 - 32.
class AdaptiveModel {
 public:
  AdaptiveModel() {
    for (auto& c : counts_) c.fill(16);
    totals_.fill(16 * symbol_count);
  }
  static int context(const ReverseDecoder& d, bool exclusion) {
    return (d.valence_class() * 6 + d.previous()) * 2 + (exclusion && !d.c_possible() ? 1 : 0);
  }
  // Frequencies in Symbol order with C zeroed when excluded; returns the total.
  // (The context's total is kept alongside its counts rather than summed per symbol.)
  std::uint32_t table(int ctx, std::array<std::uint32_t, symbol_count>& f) const {
    const auto& c = counts_[static_cast<std::size_t>(ctx)];
    for (std::size_t s = 0; s < symbol_count; ++s) f[s] = c[s];
    std::uint32_t total = totals_[static_cast<std::size_t>(ctx)];
    if (ctx & 1) {
      total -= f[0];
      f[0] = 0;
    }
    return total;
  }
  // Decoder side: the symbol whose interval holds the range decoder's target, read from
  // the context's counts in place (table() copies them for the encoder). With C
  // excluded its frequency is 0, so the search starts at L; otherwise the same search.
  Symbol decode(int ctx, RangeDecoder& dec) const {
    const auto& c = counts_[static_cast<std::size_t>(ctx)];
    const bool excluded = (ctx & 1) != 0;
    const std::uint32_t total = totals_[static_cast<std::size_t>(ctx)] - (excluded ? c[0] : 0u);
    const std::uint32_t v = dec.target(total);
    std::uint32_t cum = 0;
    int k = excluded ? 1 : 0;
    while (k < symbol_count - 1 && cum + c[static_cast<std::size_t>(k)] <= v) cum += c[static_cast<std::size_t>(k++)];
    dec.consume(cum, c[static_cast<std::size_t>(k)]);
    return static_cast<Symbol>(k);
  }
  void update(int ctx, Symbol s) {
    auto& c = counts_[static_cast<std::size_t>(ctx)];
    auto& total = totals_[static_cast<std::size_t>(ctx)];
    c[static_cast<std::size_t>(s)] += 32;
    total += 32;
    if (total > 65536 - 32) {
      total = 0;
      for (auto& v : c) {
        v = static_cast<std::uint16_t>((v + 1) / 2);
        total += v;
      }
    }
  }

 private:
  std::array<std::array<std::uint16_t, symbol_count>, 72> counts_{};
  std::array<std::uint32_t, 72> totals_{};
};

struct Violation {};

}  // namespace

ConnEncoded encode_connectivity(const Connectivity& code, ConnMode mode, int model, bool verify, bool decode,
                                bool opposite) {
  // The adaptive coder's contexts come from the decoder's state, so it always runs it.
  const bool run_decoder = decode || mode == ConnMode::adaptive;
  for (bool exclusion : {true, false}) {
    if (!exclusion && mode == ConnMode::static_model)
      throw runtime_failure("the static model cannot code this mesh (a symbol it excludes occurs)");
    try {
      RangeEncoder enc;
      ReverseDecoder decoder(code.clers.size(), code.events);
      AdaptiveModel adaptive;
      StaticCoderState machine(mode == ConnMode::static_model ? model : 0);
      std::array<std::uint32_t, symbol_count> f{};
      for (std::size_t i = code.clers.size(); i-- > 0;) {
        const Symbol s = code.clers[i];
        if (i + 1 == code.clers.size()) {
          if (s != Symbol::E) throw runtime_failure("internal: the last symbol is not E");
          // Not coded: the first decoded symbol is always E.
        } else if (mode == ConnMode::raw) {
          put_raw(enc, s);
        } else if (mode == ConnMode::adaptive) {
          const int ctx = AdaptiveModel::context(decoder, exclusion);
          const std::uint32_t total = adaptive.table(ctx, f);
          if (f[static_cast<std::size_t>(s)] == 0) throw Violation{};
          std::uint32_t cum = 0;
          for (int k = 0; k < static_cast<int>(s); ++k) cum += f[static_cast<std::size_t>(k)];
          enc.encode(cum, f[static_cast<std::size_t>(s)], total);
          adaptive.update(ctx, s);
        } else {
          const StaticFrequencies& sf = machine.frequencies();
          if (sf.f[static_cast<std::size_t>(s)] == 0) throw Violation{};
          enc.encode(sf.cum[static_cast<std::size_t>(s)], sf.f[static_cast<std::size_t>(s)], static_total);
        }
        if (mode == ConnMode::static_model) machine.advance(s);
        if (run_decoder) decoder.step(s);
      }
      ConnEncoded out;
      out.bytes = enc.finish();
      out.exclusion = exclusion;
      if (decode) out.decoded = decoder.finish(verify, opposite);
      return out;
    } catch (const Violation&) {
    }
  }
  throw runtime_failure("internal: connectivity coding failed without exclusion");
}

DecodedConnectivity decode_connectivity(std::string_view bytes, std::size_t symbols, std::vector<HandleEvent> events,
                                        ConnMode mode, int model, bool exclusion, bool verify, bool opposite,
                                        bool valence) {
  RangeDecoder dec(bytes);
  ReverseDecoder decoder(symbols, std::move(events));
  decoder.keep_symbols(verify);
  // Storage at once for up to 32 symbols per byte (real meshes spend more than a quarter
  // bit per symbol); a count beyond that grows the arrays as decoding goes, so a lying
  // header costs memory in proportion to its bytes only.
  decoder.reserve(std::min<std::size_t>(symbols, (std::size_t{1} << 16) + 32 * bytes.size()));
  AdaptiveModel adaptive;
  if (mode == ConnMode::adaptive && symbols > 0) {
    // The loop below for the adaptive coder alone (the mode is not asked per symbol).
    decoder.step(Symbol::E);  // the first decoded symbol is E, not stored
    if (dec.overrun() > 12) throw bad_input("connectivity section is truncated");
    for (std::size_t i = symbols - 1; i-- > 0;) {
      const int ctx = AdaptiveModel::context(decoder, exclusion);
      const Symbol s = adaptive.decode(ctx, dec);
      adaptive.update(ctx, s);
      decoder.step(s);
      if (dec.overrun() > 12) throw bad_input("connectivity section is truncated");
    }
    if (dec.truncated()) throw bad_input("connectivity section is truncated");
    return decoder.finish(verify, opposite, valence);
  }
  StaticCoderState machine(mode == ConnMode::static_model ? model : 0);
  for (std::size_t i = symbols; i-- > 0;) {
    Symbol s = Symbol::E;
    if (i + 1 == symbols) {
      // the first decoded symbol is E, not stored
    } else if (mode == ConnMode::raw) {
      s = get_raw(dec);
    } else if (mode == ConnMode::adaptive) {
      const int ctx = AdaptiveModel::context(decoder, exclusion);
      s = adaptive.decode(ctx, dec);
      adaptive.update(ctx, s);
    } else {
      const StaticFrequencies& sf = machine.frequencies();
      const std::uint32_t v = dec.target(static_total);
      int k = 0;
      while (k < symbol_count - 1 && sf.cum[static_cast<std::size_t>(k)] + sf.f[static_cast<std::size_t>(k)] <= v) ++k;
      s = static_cast<Symbol>(k);
      dec.consume(sf.cum[static_cast<std::size_t>(k)], sf.f[static_cast<std::size_t>(k)]);
    }
    if (mode == ConnMode::static_model) machine.advance(s);
    decoder.step(s);
    if (dec.overrun() > 12) throw bad_input("connectivity section is truncated");
  }
  if (dec.truncated()) throw bad_input("connectivity section is truncated");
  return decoder.finish(verify, opposite, valence);
}

}  // namespace fest::edgebreaker
