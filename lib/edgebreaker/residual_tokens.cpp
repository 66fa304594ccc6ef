// GEOM version 3's residual tokens (docs/ebcode.md §5; layout in ebm(5)).
#include "edgebreaker/residual_tokens.hpp"

#include <algorithm>

#include "core/bit_stream.hpp"
#include "core/error.hpp"
#include "core/little_endian.hpp"

namespace fest::edgebreaker {

using range_coding::BitReader;
using range_coding::BitWriter;
using range_coding::kRansAlphabet;
using range_coding::kRansTotal;
using range_coding::RansEncoder;
using range_coding::RansEntry;
using range_coding::RansTable;

namespace {

int bit_length(std::uint64_t v) { return v == 0 ? 0 : 64 - __builtin_clzll(v); }

std::vector<int> alphabets(int bits) { return std::vector<int>(static_cast<std::size_t>(bits + 1), token_alphabet(bits)); }

// The token of |r| = a (bit length k), and its raw bits: the sign, then the bits below the
// token's (token_shape's inverse).
struct Coded {
  int token, raw_count;
  std::uint64_t raw;
};
Coded code(std::int64_t r) {
  const auto a = static_cast<std::uint64_t>(r < 0 ? -r : r);
  const std::uint64_t sign = r < 0 ? 1u : 0u;
  const int k = bit_length(a);
  if (k == 0) return {0, 0, 0};
  if (k <= 2) return {static_cast<int>(a), 1, sign};
  const int below = k - 3;
  const int token = 4 + 4 * below + static_cast<int>((a >> below) & 3u);
  return {token, 1 + below, ((a & ((std::uint64_t{1} << below) - 1u)) << 1) | sign};
}

struct TokenErrors {
  [[noreturn]] void truncated(std::size_t, std::size_t) const { throw bad_input("GEOM section is truncated"); }
  [[noreturn]] void varint_too_long(std::size_t) const { throw bad_input("GEOM section: a number is too long"); }
};

// The section: varint length of the rANS stream, the rANS stream, then one bit stream
// with the tables and after them the raw bits.
std::string_view rans_part(std::string_view section) {
  little_endian::Reader<TokenErrors> r(section, TokenErrors{});
  const std::uint64_t n = r.varint();
  if (n > r.left()) throw bad_input("GEOM section is truncated");
  return r.bytes(static_cast<std::size_t>(n));
}

}  // namespace

int token_alphabet(int bits) { return bits == 1 ? 2 : 4 * bits - 4; }

TokenShape token_shape(int token) {
  TokenShape s;
  if (token < 4) {
    s.lead = static_cast<std::uint32_t>(token);
    s.k = static_cast<std::uint8_t>(bit_length(static_cast<std::uint64_t>(token)));
    s.raw = token == 0 ? 0 : 1;
  } else {
    const int below = (token - 4) / 4;
    s.lead = static_cast<std::uint32_t>(4 + (token & 3)) << below;
    s.k = static_cast<std::uint8_t>(below + 3);
    s.raw = static_cast<std::uint8_t>(1 + below);
  }
  return s;
}

std::optional<std::string> encode_residual_tokens(const std::vector<std::int64_t>& residuals, int bits) {
  const std::size_t n = residuals.size();
  // First pass: tokens and contexts in coding order, and the counts per context.
  std::vector<Coded> coded(n);
  std::vector<std::uint8_t> context(n);
  std::vector<std::array<std::uint32_t, kRansAlphabet>> counts(static_cast<std::size_t>(bits + 1));
  for (auto& c : counts) c.fill(0);
  TokenContexts ctx;
  for (std::size_t i = 0; i < n; ++i) {
    const int axis = static_cast<int>(i % 3);
    coded[i] = code(residuals[i]);
    const int c = ctx.bucket(axis);
    context[i] = static_cast<std::uint8_t>(c);
    ++counts[static_cast<std::size_t>(c)][static_cast<std::size_t>(coded[i].token)];
    ctx.update(axis, token_shape(coded[i].token).k);
  }
  std::vector<RansTable> tables(counts.size());
  for (std::size_t c = 0; c < counts.size(); ++c)
    if (!range_coding::normalise_table(counts[c].data(), token_alphabet(bits), tables[c])) return std::nullopt;
  BitWriter raw;
  range_coding::write_tables(raw, tables, alphabets(bits));
  for (const Coded& c : coded)
    if (c.raw_count > 0) raw.put(c.raw, c.raw_count);
  // rANS is a stack: the symbols go in backwards so the decoder reads them forwards.
  RansEncoder enc;
  for (std::size_t i = n; i-- > 0;) {
    const RansTable& t = tables[context[i]];
    const auto token = static_cast<std::size_t>(coded[i].token);
    enc.put(t.cum[token], t.freq[token]);
  }
  const std::string stream = enc.finish();
  std::string out;
  little_endian::put_varint(out, stream.size());
  out += stream;
  out += raw.finish();
  return out;
}

ResidualTokenDecoder::ResidualTokenDecoder(std::string_view section, int bits) {
  if (bits < 1 || bits > 30) throw bad_input("GEOM version 3 needs 1..30 quantisation bits, not {}", bits);
  const std::string_view stream = rans_part(section);
  const std::string_view rest = section.substr(static_cast<std::size_t>(stream.data() + stream.size() - section.data()));
  BitReader reader(rest);
  std::vector<RansTable> tables;
  if (!range_coding::read_tables(reader, tables, alphabets(bits))) throw bad_input("GEOM section: bad frequency tables");
  // Decoding tables for the contexts that code anything; the others decode zeros without
  // moving the state, so a damaged stream that reaches them fails the final check.
  const auto empty = [](const RansTable& t) { return t.freq[static_cast<std::size_t>(t.implied)] == 0; };
  const auto used = static_cast<std::size_t>(std::count_if(tables.begin(), tables.end(), [&](const RansTable& t) { return !empty(t); }));
  storage_.reset(new RansEntry[std::max<std::size_t>(used, 1) * kRansTotal]);
  table_.assign(tables.size(), range_coding::identity_decode_table());
  std::size_t next = 0;
  for (std::size_t c = 0; c < tables.size(); ++c) {
    if (empty(tables[c])) continue;
    RansEntry* out = storage_.get() + next++ * kRansTotal;
    range_coding::fill_decode_table(tables[c], token_alphabet(bits), out);
    table_[c] = out;
  }
  // Padded copies: the reader's renormalisation and raw-bit loads read a fixed width
  // without a test, clamped to the end (core/rans.hpp's RansDecoder does the same).
  words_.reset(new std::uint8_t[stream.size() + 2]());
  std::memcpy(words_.get(), stream.data(), stream.size());
  raw_.reset(new std::uint8_t[rest.size() + 8]());
  std::memcpy(raw_.get(), rest.data(), rest.size());
  for (int t = 0; t < token_alphabet(bits); ++t) shapes_[static_cast<std::size_t>(t)] = token_shape(t);
  start_.table = table_.data();
  start_.shapes = shapes_.data();
  start_.x = 0;
  for (std::size_t i = 0; i < 4 && i < stream.size(); ++i) start_.x |= static_cast<std::uint32_t>(words_[i]) << (8 * i);
  start_.words = words_.get();
  start_.word_pos = 4;
  start_.word_end = stream.size();
  start_.raw = raw_.get();
  start_.bit_pos = reader.consumed();
  start_.bit_end = 8 * static_cast<std::uint64_t>(rest.size());
}

}  // namespace fest::edgebreaker
