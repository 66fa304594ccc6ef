#include "formats/dataset/xml_blocks.hpp"

#include <algorithm>
#include <cstdint>
#include <string>

#include <zlib.h>

#include "lib/core/error.hpp"

namespace fest::formats::detail {
namespace {

constexpr size_t npos = std::string_view::npos;
// Compressed string and offsets blocks are inflated to check them; past this size
// only their block structure is checked (the reader's own guards stay in place).
constexpr uint64_t kMaxInflate = uint64_t{1} << 28;

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

std::string quoted_bytes(std::string_view s, size_t max) { return "\"" + printable_bytes(s, max, true) + "\""; }

std::string printable_bytes(std::string_view s, size_t max, bool escape_quotes) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (size_t i = 0; i < s.size() && i < max; ++i) {
    unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7f && !(escape_quotes && c == '"') && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    }
  }
  if (s.size() > max) out += "...";
  return out;
}

namespace {

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// The bytes of one DataArray's data, as the reader will see them.
struct Block {
  uint64_t length = 0;       // uncompressed bytes of data
  std::string payload;       // the uncompressed data, when needed and decodable
  bool have_payload = false;
  size_t end = 0;            // input offset just past the block (appended blocks)
};

class BlockChecker {
 public:
  BlockChecker(std::string_view s, const XmlEncoding& e, const char* format) : s_(s), e_(e), format_(format) {}

  [[noreturn]] void fail(const XmlArray& a, size_t at, const std::string& problem) const {
    throw bad_input("{}: DataArray {} at byte {}: {}", format_, quoted_bytes(a.name, 40), at, problem);
  }

  // Reads `n` bytes of a stream that starts at `begin` (raw) or is base64 text from
  // `begin`, ending before `limit`. `chars` is how far the stream has got (in input
  // bytes); base64 streams are padded to whole quads at their end.
  class Stream {
   public:
    Stream(const BlockChecker& c, const XmlArray& a, size_t begin, size_t limit, bool base64)
        : c_(c), a_(a), pos_(begin), limit_(limit), base64_(base64) {}

    // Appends `n` decoded bytes to `out` (or skips them when out is null).
    void read(uint64_t n, std::string* out, const char* what) {
      if (!base64_) {
        if (n > limit_ - pos_)
          c_.fail(a_, pos_,
                  fmt::format("{} of {} bytes runs past the end of the data ({} bytes left)", what, n, limit_ - pos_));
        if (out) out->append(c_.s_.data() + pos_, n);
        pos_ += n;
        return;
      }
      // Bytes still buffered from the last quad come first.
      while (n > 0 && have_ > 0) {
        if (out) out->push_back(static_cast<char>(buffer_[3 - have_]));
        --have_;
        --n;
      }
      uint64_t quads = (n + 2) / 3;
      if (quads > (limit_ - pos_) / 4)
        c_.fail(a_, pos_,
                fmt::format("{} of {} bytes runs past the end of the base64 data ({} characters left)", what, n,
                            limit_ - pos_));
      if (out) out->reserve(out->size() + n);
      while (n > 0) {
        unsigned v[4];
        int real = 4;
        for (int k = 0; k < 4; ++k) {
          char ch = c_.s_[pos_ + k];
          int d = base64_value(ch);
          if (ch == '=' && k >= 2) {
            real = std::min(real, k);
            d = 0;
          } else if (d < 0 || real < 4) {
            c_.fail(a_, pos_ + k, fmt::format("{} is not base64 data", quoted_bytes(c_.s_.substr(pos_ + k, 4))));
          }
          v[k] = static_cast<unsigned>(d);
        }
        pos_ += 4;
        unsigned char bytes[3] = {static_cast<unsigned char>(v[0] << 2 | v[1] >> 4),
                                  static_cast<unsigned char>(v[1] << 4 | v[2] >> 2),
                                  static_cast<unsigned char>(v[2] << 6 | v[3])};
        int got = real - 1;  // bytes this quad holds
        if (static_cast<uint64_t>(got) < std::min<uint64_t>(n, 3))
          c_.fail(a_, pos_ - 4, fmt::format("{} ends early, {} bytes short", what, n - static_cast<uint64_t>(got)));
        int take = static_cast<int>(std::min<uint64_t>(n, 3));
        for (int k = 0; k < take; ++k)
          if (out) out->push_back(static_cast<char>(bytes[k]));
        n -= static_cast<uint64_t>(take);
        if (n == 0 && take < got) {  // keep the rest of this quad for the next read
          have_ = got - take;
          for (int k = 0; k < have_; ++k) buffer_[3 - have_ + k] = bytes[take + k];
        }
      }
    }

    // A base64 stream ends at the end of its last quad; bytes left in it belong to
    // nothing (VTK starts a new stream at the next quad).
    void end_stream() { have_ = 0; }
    size_t pos() const { return pos_; }

   private:
    const BlockChecker& c_;
    const XmlArray& a_;
    size_t pos_, limit_;
    bool base64_;
    unsigned char buffer_[3] = {0, 0, 0};
    int have_ = 0;
  };

  uint64_t word(const std::string& bytes, size_t index) const {
    uint64_t v = 0;
    const unsigned n = e_.header_bytes;
    for (unsigned k = 0; k < n; ++k) {
      unsigned char b = static_cast<unsigned char>(bytes[index * n + k]);
      unsigned shift = e_.big_endian ? 8 * (n - 1 - k) : 8 * k;
      v |= static_cast<uint64_t>(b) << shift;
    }
    return v;
  }

  // Reads the header and data of a binary block starting at `begin`.
  Block binary(const XmlArray& a, size_t begin, size_t limit, bool base64, bool want_payload) const {
    Stream in(*this, a, begin, limit, base64);
    Block block;
    std::string header;
    const unsigned hb = e_.header_bytes;
    if (!e_.compressed) {
      in.read(hb, &header, "the block header");
      block.length = word(header, 0);
      if (block.length > limit - begin)
        fail(a, begin, fmt::format("its block header {} declares {} bytes, more than the {} bytes left in the file",
                           quoted_bytes(header), block.length, limit - begin));
      block.have_payload = want_payload;
      in.read(block.length, want_payload ? &block.payload : nullptr, "the data");
      in.end_stream();
      block.end = in.pos();
      return block;
    }
    in.read(3 * uint64_t{hb}, &header, "the compression header");
    const uint64_t blocks = word(header, 0), block_size = word(header, 1), last_size = word(header, 2);
    if (blocks > (limit - begin) / hb)
      fail(a, begin,
           fmt::format("its compression header {} declares {} blocks, more than the file holds", quoted_bytes(header),
                       blocks));
    // The reader holds one whole block in memory while it inflates it.
    if (block_size > kMaxInflate)
      fail(a, begin, fmt::format("its compression header declares blocks of {} bytes, more than 2^28", block_size));
    if (blocks > 0 && (block_size == 0 || last_size > block_size))
      fail(a, begin,
           fmt::format("its compression header declares blocks of {} bytes with a last block of {}", block_size,
                         last_size));
    in.read(blocks * hb, &header, "the compressed block sizes");
    in.end_stream();
    uint64_t compressed_total = 0;
    for (uint64_t b = 0; b < blocks; ++b) {
      uint64_t size = word(header, 3 + b);
      if (size > limit - begin || compressed_total + size > limit - begin)
        fail(a, begin, fmt::format("compressed block {} of {} bytes runs past the end of the file", b, size));
      compressed_total += size;
    }
    if (blocks == 0) {
      block.length = 0;
    } else if (block_size > UINT64_MAX / blocks) {
      fail(a, begin, fmt::format("its compression header declares {} blocks of {} bytes", blocks, block_size));
    } else {
      block.length = (blocks - 1) * block_size + (last_size == 0 ? block_size : last_size);
    }
    std::string compressed;
    const bool inflate = want_payload && e_.zlib && block.length <= kMaxInflate;
    in.read(compressed_total, inflate ? &compressed : nullptr, "the compressed data");
    in.end_stream();
    block.end = in.pos();
    if (!inflate) return block;
    block.payload.resize(block.length);
    uint64_t from = 0, to = 0;
    for (uint64_t b = 0; b < blocks; ++b) {
      uint64_t size = word(header, 3 + b);
      uLongf want = static_cast<uLongf>(b + 1 == blocks && last_size != 0 ? last_size : block_size);
      uLongf got = want;
      int status = uncompress(reinterpret_cast<Bytef*>(&block.payload[to]), &got,
                              reinterpret_cast<const Bytef*>(compressed.data() + from), static_cast<uLong>(size));
      if (status != Z_OK || got != want)
        fail(a, begin,
             fmt::format("compressed block {} does not inflate to the {} bytes its header declares", b, want));
      from += size;
      to += want;
    }
    block.have_payload = true;
    return block;
  }


  std::string_view s_;
  XmlEncoding e_;
  const char* format_;
};

// The value of the last element of an integer array's data, or false when it has none.
bool last_integer(const std::string& payload, uint64_t type_size, std::string_view type, bool big_endian,
                  int64_t* value) {
  if (payload.size() < type_size || type_size == 0 || type_size > 8) return false;
  uint64_t v = 0;
  const char* p = payload.data() + payload.size() - type_size;
  for (uint64_t k = 0; k < type_size; ++k) {
    uint64_t shift = big_endian ? 8 * (type_size - 1 - k) : 8 * k;
    v |= static_cast<uint64_t>(static_cast<unsigned char>(p[k])) << shift;
  }
  if (type.substr(0, 3) == "Int" && type_size < 8 && (v >> (8 * type_size - 1)) != 0)
    v |= ~uint64_t{0} << (8 * type_size);  // sign-extend
  if (type.substr(0, 5) == "Float") return false;
  *value = static_cast<int64_t>(v);
  return true;
}

std::string type_words(uint64_t values, std::string_view type, uint64_t size) {
  return fmt::format("{} values of {} ({} bytes)", values, type, values * size);
}

}  // namespace

bool xml_type_size(std::string_view type, uint64_t* size) {
  if (type == "Int8" || type == "UInt8" || type == "Bit") {  // Bit: packed, 8 values a byte
    *size = 1;
  } else if (type == "Int16" || type == "UInt16") {
    *size = 2;
  } else if (type == "Int32" || type == "UInt32" || type == "Float32") {
    *size = 4;
  } else if (type == "Int64" || type == "UInt64" || type == "Float64") {
    *size = 8;
  } else if (type == "String") {
    *size = 0;
  } else {
    return false;
  }
  return true;
}

void check_xml_blocks(std::string_view s, const XmlEncoding& encoding, std::vector<XmlArray>& arrays,
                      size_t appended_begin, size_t appended_end, bool base64_appended, const char* format) {
  BlockChecker checker(s, encoding, format);
  struct Extent {
    size_t begin, end;
    size_t array;
  };
  std::vector<Extent> extents;
  // Offsets first: their last value says how long connectivity is.
  std::vector<size_t> order;
  for (size_t i = 0; i < arrays.size(); ++i)
    if (!arrays[i].values_from_offsets) order.push_back(i);
  for (size_t i = 0; i < arrays.size(); ++i)
    if (arrays[i].values_from_offsets) order.push_back(i);
  std::vector<int64_t> last_offset(arrays.size(), -1);

  // The data of a binary block against the markup: as many strings or values as it
  // asks for; an offsets array's last value is kept for its connectivity.
  auto check_contents = [&](const XmlArray& a, size_t i, size_t begin, const Block& block, const char* holds) {
    uint64_t size = 0;
    xml_type_size(a.type, &size);
    if (size == 0) {
      if (!block.have_payload) return;
      uint64_t strings = static_cast<uint64_t>(std::count(block.payload.begin(), block.payload.end(), '\0'));
      if (strings != a.values || (!block.payload.empty() && block.payload.back() != '\0'))
        checker.fail(a, begin,
                     fmt::format("its {} bytes hold {} strings, not {} (do header_type and byte_order match the data?)",
                                 block.length, strings, a.values));
      return;
    }
    if (!a.values_known) {
      if (block.length % size != 0)
        checker.fail(a, begin, fmt::format("{} bytes is not a whole number of {} values", block.length, a.type));
    } else if (block.length / size != a.values || block.length % size != 0) {
      checker.fail(a, begin,
                   a.values_from_offsets
                       ? fmt::format("the cell offsets end at {}, but {} {} bytes ({} values)", a.values, holds,
                                     block.length, block.length / size)
                       : fmt::format("{} {} bytes, but the markup asks for {}", holds, block.length,
                                     type_words(a.values, a.type, size)));
    }
    if (!a.is_offsets || !block.have_payload) return;
    int64_t last = 0;
    if (last_integer(block.payload, size, a.type, encoding.big_endian, &last)) {
      if (last < 0) checker.fail(a, begin, fmt::format("the last cell offset is {}", last));
      last_offset[i] = last;
    } else if (block.length == 0) {
      last_offset[i] = 0;
    }
  };

  for (size_t i : order) {
    XmlArray& a = arrays[i];
    uint64_t size = 0;
    if (a.type.empty()) checker.fail(a, a.tag_offset, "has no type attribute");
    if (!xml_type_size(a.type, &size))
      checker.fail(a, a.tag_offset,
                   fmt::format("type {} is not a VTK type (Int8..Int64, UInt8..UInt64, Float32, Float64, "
                                        "String, Bit)",
                                        quoted_bytes(a.type)));
    const bool is_string = size == 0;
    a.values_known = a.type != "Bit";
    if (a.values_from_offsets) {
      if (a.offsets_of < 0 || last_offset[static_cast<size_t>(a.offsets_of)] < 0) {
        a.values_known = false;
      } else {
        a.values = static_cast<uint64_t>(last_offset[static_cast<size_t>(a.offsets_of)]);
      }
    }
    const bool want_payload = is_string || a.is_offsets;
    if (a.format == "appended") {
      if (appended_begin == npos)
        checker.fail(a, a.tag_offset, "format=\"appended\" but the file has no <AppendedData>");
      std::string_view o = a.offset;
      while (!o.empty() && is_space(o.front())) o.remove_prefix(1);
      while (!o.empty() && is_space(o.back())) o.remove_suffix(1);
      uint64_t offset = 0;
      bool ok = !o.empty() && o.size() <= 18;
      for (char c : o) {
        if (c < '0' || c > '9') ok = false;
        if (ok) offset = offset * 10 + static_cast<uint64_t>(c - '0');
      }
      if (!ok) checker.fail(a, a.tag_offset, fmt::format("offset {} is not a byte offset", quoted_bytes(o)));
      if (offset >= appended_end - appended_begin)
        checker.fail(a, a.tag_offset,
                     fmt::format("offset {} lies past the end of the appended data ({} bytes)", offset,
                                          appended_end - appended_begin));
      const size_t begin = appended_begin + offset;
      Block block = checker.binary(a, begin, appended_end, base64_appended, want_payload);
      extents.push_back({begin, block.end, i});
      a.text_begin = begin;
      check_contents(a, i, begin, block, "its block holds");
    } else if (a.format == "binary") {
      size_t begin = a.text_begin;
      while (begin < a.text_end && is_space(s[begin])) ++begin;
      Block block = checker.binary(a, begin, a.text_end, true, want_payload);
      // The data end where the element's text does (InformationKey children may follow).
      size_t after = block.end;
      while (after < a.text_end && is_space(s[after])) ++after;
      if (after < a.text_end && s[after] != '<')
        checker.fail(a, block.end,
                     fmt::format("{} characters after its data, from byte {}, belong to nothing (does header_type "
                                 "match the data?)",
                                 a.text_end - block.end, block.end));
      check_contents(a, i, begin, block, "its data hold");
    } else if (a.format == "ascii") {
      // Words of the element's text, child elements (InformationKey) left out.
      uint64_t words = 0, zeros = 0;
      std::string_view last_word;
      size_t p = a.text_begin;
      int depth = 0;  // inside child elements, whose text is theirs
      while (p < a.text_end) {
        if (s[p] == '<') {
          size_t close = s.find('>', p);
          if (close == npos || close >= a.text_end) break;
          if (s[p + 1] == '/') {
            --depth;
          } else if (s[close - 1] != '/' && s[p + 1] != '?' && s[p + 1] != '!') {
            ++depth;
          }
          p = close + 1;
          continue;
        }
        if (depth > 0 || is_space(s[p])) {
          ++p;
          continue;
        }
        size_t start = p;
        while (p < a.text_end && !is_space(s[p]) && s[p] != '<') ++p;
        last_word = s.substr(start, p - start);
        ++words;
        if (last_word == "0") ++zeros;
      }
      if (is_string) {
        if (zeros != a.values || (words > 0 && last_word != "0"))
          checker.fail(a, a.text_begin, fmt::format("its text holds {} strings, not {}", zeros, a.values));
      } else if (a.values_known && words != a.values) {
        checker.fail(a, a.text_begin,
                     a.values_from_offsets
                         ? fmt::format("the cell offsets end at {}, but its text holds {} values", a.values, words)
                         : fmt::format("its text holds {} values, but the markup asks for {}", words, a.values));
      }
      if (a.is_offsets) {
        if (words == 0) {
          last_offset[i] = 0;
        } else {
          std::string text(last_word.substr(0, 20));
          char* end = nullptr;
          long long v = std::strtoll(text.c_str(), &end, 10);
          if (end != text.c_str() + text.size() || v < 0)
            checker.fail(a, a.text_begin, fmt::format("the last cell offset {} is not a count", quoted_bytes(text)));
          last_offset[i] = v;
        }
      }
    } else {
      checker.fail(a, a.tag_offset,
                   fmt::format("format {} is not ascii, binary or appended", quoted_bytes(a.format)));
    }
  }

  // Appended blocks tile the appended data: one that runs into the next, or bytes
  // that belong to none (the signature of a header_type that does not match the
  // data), mean the offsets and headers are not what the writer wrote.
  if (extents.empty()) return;
  std::sort(extents.begin(), extents.end(),
            [](const Extent& x, const Extent& y) { return x.begin != y.begin ? x.begin < y.begin : x.end < y.end; });
  size_t covered = appended_begin;
  for (size_t k = 0; k < extents.size(); ++k) {
    const Extent& x = extents[k];
    if (k > 0 && x.begin == extents[k - 1].begin) {
      if (x.end != extents[k - 1].end)
        checker.fail(arrays[x.array], x.begin, "shares its block with another array that reads it differently");
      continue;
    }
    if (x.begin < covered)
      checker.fail(arrays[x.array], x.begin,
                   fmt::format("its block starts inside the one before it (which ends at byte {})", covered));
    if (x.begin > covered)
      checker.fail(arrays[x.array], x.begin,
                   fmt::format("{} bytes before its block, from byte {}, belong to no array (does header_type "
                                        "match the data?)",
                                        x.begin - covered, covered));
    covered = x.end;
  }
  size_t tail = covered;
  while (tail < appended_end && is_space(s[tail])) ++tail;
  if (tail < appended_end)
    checker.fail(arrays[extents.back().array], covered,
                 fmt::format("{} bytes after the last block, from byte {}, belong to no array (does "
                                      "header_type match the data?)",
                                      appended_end - covered, covered));
}

}  // namespace fest::formats::detail
