#pragma once
// Checks that a dataset VTK has read is consistent enough for code that trusts it:
// arrays as long as the points or cells they describe, cell lists whose offsets and
// point ids stay in range, cell types VTK knows with the number of points they need.
// VTK's readers accept files that break all of these, and later walks over such a
// dataset read out of bounds.

#include <string>

class vtkDataSet;

namespace fest::formats::detail {

// Throws bad_input("<format>: ...") naming the first inconsistency.
void validate_dataset(vtkDataSet* dataset, const char* format);

}  // namespace fest::formats::detail
