#pragma once
// A VTK XML reader that refuses cell offsets the input cannot back.
//
// vtkXMLUnstructuredDataReader::ReadCellArray sizes the connectivity array by the
// last cell offset it has just read from the data, and allocates it before reading
// a single id: one corrupt offset asks for terabytes. The markup scan cannot see
// that value (it may be in raw or compressed appended data), but ReadArrayValues is
// virtual and reads the offsets first, so this subclass checks them right there.

#include <cstring>

#include <vtkDataArray.h>
#include <vtkXMLDataElement.h>

namespace fest::formats::detail {

template <typename Reader>
class GuardedXmlReader : public Reader {
 public:
  static GuardedXmlReader* New() {
    auto* reader = new GuardedXmlReader;
    reader->InitializeObjectBase();
    return reader;
  }

  void SetMaxDataDrivenValues(vtkIdType n) { max_values_ = n; }

 protected:
  int ReadArrayValues(vtkXMLDataElement* element, vtkIdType array_index, vtkAbstractArray* array,
                      vtkIdType start_index, vtkIdType num_values,
                      typename Reader::FieldType type = Reader::OTHER) override {
    int ok = Reader::ReadArrayValues(element, array_index, array, start_index, num_values, type);
    const char* name = element ? element->GetAttribute("Name") : nullptr;
    auto* values = vtkDataArray::SafeDownCast(array);
    if (!ok || name == nullptr || std::strcmp(name, "offsets") != 0 || values == nullptr || num_values <= 0)
      return ok;
    double last = values->GetComponent(array_index + num_values - 1, 0);
    if (last > static_cast<double>(max_values_)) {
      vtkErrorMacro("cell offsets end at " << static_cast<long long>(last) << ", more point ids than the input can hold");
      return 0;
    }
    return ok;
  }

 private:
  vtkIdType max_values_ = 0;
};

}  // namespace fest::formats::detail
