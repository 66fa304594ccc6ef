#pragma once
// VTK's reasons for refusing a dataset, said in fest's words. VTK's XML readers explain a
// failure in their own sentences ("Cannot read cell connectivity from Cells in piece 0
// because the "offsets" array is not monotonically increasing or starts with a value other
// than 0"); the message a person reads says the same in fest's terms -- which piece, which
// array, what is wrong -- and VTK's sentence is kept only as the error's detail
// (core/error_detail.hpp), shown with -v. No VTK here: plain text in, text out.

#include <string>

namespace fest::formats::detail {

// fest's sentence for a reason of VTK's it recognises, without the format prefix
// ("the \"offsets\" of the cells of piece 0 do not start at 0 and increase"); empty when
// the reason is not one it knows.
std::string fest_words_for_vtk_reason(const std::string& vtk_text);

}  // namespace fest::formats::detail
