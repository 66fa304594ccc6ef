// VTK's reasons for refusing a dataset, said in fest's words (formats/dataset/vtk_reasons):
// the sentences VTK 9.1's XML readers write, as they reach fest's message collector.

#include <gtest/gtest.h>

#include <string>

#include "formats/dataset/vtk_reasons.hpp"

using fest::formats::detail::fest_words_for_vtk_reason;

TEST(VtkReasons, OffsetsNotMonotonic) {
  EXPECT_EQ(fest_words_for_vtk_reason("Cannot read cell connectivity from Cells in piece 0 because the \"offsets\" array is "
                                      "not monotonically increasing or starts with a value other than 0"),
            "the \"offsets\" of the cells of piece 0 do not start at 0 and increase from cell to cell");
}

TEST(VtkReasons, CellArrayShortOrMissing) {
  EXPECT_EQ(fest_words_for_vtk_reason(
                "Cannot read cell types from Cells in piece 2 because the \"types\" array is not long enough"),
            "the \"types\" array of the cells of piece 2 is shorter than its cell count needs");
  EXPECT_EQ(fest_words_for_vtk_reason(
                "Cannot read cell offsets from Cells in piece 0 because the \"offsets\" array could not be found"),
            "the cells of piece 0 have no \"offsets\" array");
  EXPECT_EQ(fest_words_for_vtk_reason("Cannot read cell types from Cells in piece 0 because the \"types\" array could "
                                      "not be converted to a vtkUnsignedCharArray"),
            "the \"types\" array of the cells of piece 0 is not of an integer type");
}

TEST(VtkReasons, ArraysTooShort) {
  EXPECT_EQ(fest_words_for_vtk_reason(
                "Cannot read points array from Points in piece 1.  The data array in the element may be too short."),
            "the points of piece 1 hold fewer values than its NumberOfPoints needs");
  EXPECT_EQ(fest_words_for_vtk_reason("Cannot read point data array \"velocity\" from PointData in piece 0.  The data "
                                      "array in the element may be too short."),
            "point data array \"velocity\" of piece 0 holds fewer values than the piece has points");
  EXPECT_EQ(fest_words_for_vtk_reason("Cannot read cell data array \"id\" from CellData in piece 3.  The data array in "
                                      "the element may be too short."),
            "cell data array \"id\" of piece 3 holds fewer values than the piece has cells");
}

TEST(VtkReasons, BinaryHeaderAndTypes) {
  EXPECT_EQ(fest_words_for_vtk_reason("Error reading uncompressed binary data header.  Read 3 of 8 bytes."),
            "a binary block's header ends after 3 of its 8 bytes");
  EXPECT_EQ(fest_words_for_vtk_reason("Error reading compression header."), "a binary block's header cannot be read");
  EXPECT_EQ(fest_words_for_vtk_reason("Unsupported data type: Flaot64"), "an array has a data type VTK files do not define");
  EXPECT_EQ(fest_words_for_vtk_reason("Invalid 'type' specified in the file: Flaot64"),
            "an array has a data type VTK files do not define");
}

TEST(VtkReasons, ArrayNamesFromTheInputAreEscaped) {
  const std::string words = fest_words_for_vtk_reason(
      "Cannot read point data array \"a\x01\xff" "b\" from PointData in piece 0.  The data array in the element may be "
      "too short.");
  EXPECT_EQ(words.find('\x01'), std::string::npos) << words;
  EXPECT_NE(words.find("\\x01"), std::string::npos) << words;
}

TEST(VtkReasons, UnknownReasonsGiveNothing) {
  EXPECT_EQ(fest_words_for_vtk_reason("Something VTK has never said"), "");
}
