#pragma once
// The data of every DataArray of a VTK XML file, checked against its markup before
// VTK reads it.
//
// vtkXMLReader trusts the block headers it meets: a header wider or narrower than the
// file says (header_type), in the other byte order (byte_order), or a length or offset
// past the end of the file makes it read the wrong bytes as lengths and string data,
// and it crashes on some of them (VTK 9.1). This check decodes each block's header the
// way the file declares (UInt32/UInt64, LittleEndian/BigEndian, uncompressed or in
// compressed blocks, inline base64, appended raw or base64, ASCII) and requires that
// it lies inside the file and holds exactly the values the markup asks for.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fest::formats::detail {

struct XmlEncoding {
  unsigned header_bytes = 4;  // UInt32 (VTK's default) or UInt64
  bool big_endian = false;
  bool compressed = false;
  bool zlib = false;  // compressed with zlib: decodable here (LZ4/LZMA blocks are only sized)
};

// One DataArray (or Array) as its markup declares it.
struct XmlArray {
  std::string_view name;         // Name attribute, for messages
  std::string_view type;         // type attribute
  std::string_view format;       // "ascii", "binary" or "appended"
  std::string_view offset;       // offset attribute (appended)
  size_t tag_offset = 0;         // byte offset of the <DataArray tag
  size_t text_begin = 0, text_end = 0;  // inline content (ascii, binary), child tags included
  uint64_t values = 0;           // values (tuples x components) the markup asks for
  bool values_from_offsets = false;  // connectivity: as many as the last cell offset says
  bool values_known = true;      // set by the check: false where only the data say how many
  int offsets_of = -1;           // for connectivity: index of its offsets array, or -1
  bool is_offsets = false;       // a cell offsets array (its last value sizes connectivity)
};

// `appended_begin` is the byte after the '_' of <AppendedData>, or npos when there is
// none; `appended_end` is where </AppendedData> starts (or the end of the input).
// `base64_appended` is AppendedData's encoding. Throws bad_input naming the array, the
// problem and the byte offset.
void check_xml_blocks(std::string_view bytes, const XmlEncoding& encoding, std::vector<XmlArray>& arrays,
                      size_t appended_begin, size_t appended_end, bool base64_appended, const char* format);

// Bytes per value of a VTK XML type name into *size (0 for String); false for a name
// VTK does not know.
bool xml_type_size(std::string_view type, uint64_t* size);

// `s` in double quotes for a message: at most `max` bytes, anything unprintable escaped.
std::string quoted_bytes(std::string_view s, size_t max = 12);
// The same without the quotes, for text that is not input (VTK's messages quote it).
std::string printable_bytes(std::string_view s, size_t max, bool escape_quotes = false);

}  // namespace fest::formats::detail
