// lib/terrainlod/tlp_archive: the .tlp head encoded and decoded again gives the same
// manifest and index, offsets laid out blob after blob; damaged heads are bad input.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "terrainlod/tlp_archive.hpp"

namespace {

using namespace fest::terrainlod;

TEST(TlpArchive, HeadRoundTripsWithOffsetsInTransmissionOrder) {
  std::vector<TlpEntry> tiles(2);
  tiles[0].id = {0, 0, 0};
  tiles[0].length = 10;
  tiles[1].id = {1, 1, 0};
  tiles[1].length = 7;
  tiles[1].texture_length = 5;
  const std::string manifest = R"({"levels":1})";
  const std::string head = encode_tlp_head(manifest, tiles);
  EXPECT_TRUE(looks_like_tlp(head));
  // magic 4 + version 1 + length 4 + manifest + count 4 + 2 entries of 33 bytes
  ASSERT_EQ(head.size(), 4 + 1 + 4 + manifest.size() + 4 + 2 * 33);

  const std::string archive = head + std::string(10 + 7 + 5, 'x');
  const TlpHead h = decode_tlp_head(archive);
  EXPECT_EQ(h.manifest, manifest);
  const std::vector<TlpEntry> index = decode_tlp_index(archive, h.index_at);
  ASSERT_EQ(index.size(), 2u);
  EXPECT_EQ(index[0].id, (TileId{0, 0, 0}));
  EXPECT_EQ(index[0].offset, head.size());
  EXPECT_EQ(index[0].texture_length, 0u);
  EXPECT_EQ(index[0].texture_offset, 0u);
  EXPECT_EQ(index[1].id, (TileId{1, 1, 0}));
  EXPECT_EQ(index[1].offset, head.size() + 10);
  EXPECT_EQ(index[1].length, 7u);
  EXPECT_EQ(index[1].texture_offset, head.size() + 17);
  EXPECT_EQ(index[1].texture_length, 5u);
}

TEST(TlpArchive, DamagedHeadsAreBadInput) {
  const std::string head = encode_tlp_head("{}", {});
  EXPECT_THROW(decode_tlp_head("FTLX" + head.substr(4)), fest::Error);
  EXPECT_THROW(decode_tlp_head(head.substr(0, 8)), fest::Error);
  std::string v2 = head;
  v2[4] = 3;
  EXPECT_THROW(decode_tlp_head(v2), fest::Error);
  // Version 2 must hold a nodata section after the index.
  v2[4] = 2;
  EXPECT_THROW(decode_tlp_nodata(v2, decode_tlp_head(v2)), fest::Error);
  EXPECT_THROW(decode_tlp_head(head.substr(0, head.size() - 1)), fest::Error);
}

TEST(TlpArchive, NodataSectionMakesVersionTwoAndShiftsTheBlobs) {
  std::vector<TlpEntry> tiles(1);
  tiles[0].id = {0, 0, 0};
  tiles[0].length = 10;
  const std::string plain = encode_tlp_head("{}", tiles);
  EXPECT_EQ(plain[4], 1);
  EXPECT_EQ(decode_tlp_nodata(plain, decode_tlp_head(plain)), "");
  const std::string section = "FTNMxyz";
  const std::string head = encode_tlp_head("{}", tiles, section);
  EXPECT_EQ(head[4], 2);
  ASSERT_EQ(head.size(), plain.size() + 4 + section.size());
  const std::string archive = head + std::string(10, 'x');
  const TlpHead h = decode_tlp_head(archive);
  EXPECT_EQ(h.version, 2);
  EXPECT_EQ(decode_tlp_nodata(archive, h), section);
  const auto index = decode_tlp_index(archive, h.index_at);
  ASSERT_EQ(index.size(), 1u);
  EXPECT_EQ(index[0].offset, head.size());
  // A section running past the end is bad input.
  EXPECT_THROW(decode_tlp_nodata(head.substr(0, head.size() - 1), h), fest::Error);
}

}  // namespace
