// Reading and writing VTK datasets in memory. Every VTK call runs with its messages
// captured (vtk_messages.hpp); readers only see bytes that a structural scan has
// found plausible (legacy_scan.hpp, xml_scan.hpp), and their output is checked for
// consistency (dataset_validate.hpp) before anyone else can trust it.

#include "formats/dataset/vtk_dataset_io.hpp"

#include <climits>
#include <cstdio>
#include <new>
#include <stdexcept>

#include <vtkDataReader.h>
#include <vtkDataSetWriter.h>
#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkRectilinearGrid.h>
#include <vtkRectilinearGridReader.h>
#include <vtkStructuredGrid.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStructuredGridReader.h>
#include <vtkStructuredPointsReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkXMLStructuredGridWriter.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "core/error_detail.hpp"
#include "core/quote.hpp"
#include "formats/dataset/dataset_validate.hpp"
#include "formats/dataset/guarded_xml_reader.hpp"
#include "formats/dataset/legacy_scan.hpp"
#include "formats/dataset/vtk_messages.hpp"
#include "formats/dataset/vtk_reasons.hpp"
#include "formats/dataset/xml_blocks.hpp"
#include "formats/dataset/xml_scan.hpp"
#include "lib/core/error.hpp"

namespace fest::formats::detail {
namespace {


// Warnings about array metadata (information keys VTK cannot place) do not make the
// data wrong; every other warning from a reader means it skipped or guessed something.
bool harmless_warning(const std::string& text) {
  for (const char* prefix : {"Could not locate key", "Ignoring line in INFORMATION", "Malformed data block",
                             "Invalid information header", "Could not deserialize", "Invalid line in information"})
    if (text.rfind(prefix, 0) == 0) return true;
  return false;
}

// vtkErrorCode::GetStringFromErrorCode lives in VTK::CommonMisc, which fest does
// not link; the few codes readers set are named here.
const char* error_code_text(unsigned long code) {
  switch (code) {
    case vtkErrorCode::UnrecognizedFileTypeError: return "unrecognized file type";
    case vtkErrorCode::PrematureEndOfFileError: return "premature end of file";
    case vtkErrorCode::FileFormatError: return "file format error";
    default: return "VTK could not read it";
  }
}

// What VTK said, kept as the detail of fest's message (shown with -v only): it may
// quote input bytes, so those are escaped (xml_blocks.hpp) and the text is cut short.
std::string vtk_says(const std::string& text) { return "VTK: " + printable_bytes(text, 160); }

// fest's sentence for what VTK said -- a reason it recognises in its own words, else
// `what` -- with VTK's text behind it as the detail.
Error refused_by_vtk(const char* format, const char* what, const std::string& vtk_text) {
  std::string words = fest_words_for_vtk_reason(vtk_text);
  if (words.empty()) words = what;
  return Error(Status::bad_input, with_error_detail(fmt::format("{}: {}", format, words), vtk_says(vtk_text)));
}

// The XML readers warn about files VTK itself writes (an empty grid has "No Points
// element"), and say what is wrong through errors, so only the legacy readers'
// warnings count: there "No points read!" is how a file that stops early shows.
// `what` says in fest's words what went wrong when VTK's reason is not one fest
// recognises ("the data do not read as the markup declares them"); VTK's text is the
// error's detail, never the message.
void fail_on_messages(const MessageCollector& messages, const char* format, bool warnings_count, const char* what) {
  for (const std::string& error : messages.errors()) {
    // vtkXMLUnstructuredDataReader says this as an error about the files its own
    // writer makes for a grid without points; validate_dataset checks what matters.
    if (error.rfind("No Points element available in first piece", 0) == 0) continue;
    // expat's complaint, relayed by VTK, said in fest's words: where and why.
    unsigned long line = 0, column = 0, byte = 0;
    int reason_at = 0;
    if (std::sscanf(error.c_str(), "Error parsing XML in stream at line %lu, column %lu, byte index %lu: %n", &line,
                    &column, &byte, &reason_at) == 3 &&
        reason_at > 0)
      throw Error(Status::bad_input,
                  with_error_detail(fmt::format("{}: the markup is not well-formed XML at line {}, column {} (byte {})",
                                                format, line, column + 1, byte),
                                    "expat: " + quoted_bytes(std::string_view(error).substr(static_cast<std::size_t>(reason_at)), 60)));
    throw refused_by_vtk(format, what, error);
  }
  if (!warnings_count) return;
  for (const std::string& warning : messages.warnings())
    if (!harmless_warning(warning))
      throw refused_by_vtk(format, what, warning);
}

// VTK code is not written for exceptions, but allocations inside it can still throw.
template <typename Work>
void run_vtk(const char* format, Work work) {
  try {
    work();
  } catch (const std::bad_alloc&) {
    throw bad_input("{}: the sizes in the file need more memory than is available", format);
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    throw Error(Status::bad_input, with_error_detail(fmt::format("{}: the data do not read as the file declares them", format),
                                                     vtk_says(e.what())));
  }
}

// The reader's output stays tied to its pipeline; hand out a detached shallow copy.
vtkSmartPointer<vtkDataSet> detach(vtkDataObject* output, const char* expected_class, const char* format) {
  vtkDataSet* dataset = vtkDataSet::SafeDownCast(output);
  if (dataset == nullptr || !dataset->IsA(expected_class))
    throw bad_input("{}: VTK produced {} instead of {}", format, output ? output->GetClassName() : "nothing",
                    expected_class);
  vtkSmartPointer<vtkDataSet> copy;
  copy.TakeReference(dataset->NewInstance());
  copy->ShallowCopy(dataset);
  return copy;
}

template <typename Reader>
vtkSmartPointer<vtkDataSet> read_xml(std::string_view bytes, std::string_view type, const char* expected_class,
                                     const char* format) {
  XmlLimits limits = scan_vtk_xml(bytes, type, format);
  auto messages = vtkSmartPointer<MessageCollector>::New();
  MessageCapture capture(messages);
  auto reader = vtkSmartPointer<GuardedXmlReader<Reader>>::New();
  reader->SetMaxDataDrivenValues(static_cast<vtkIdType>(limits.max_data_driven_values));
  observe(reader, messages);
  reader->SetReaderErrorObserver(messages);
  reader->SetParserErrorObserver(messages);
  reader->ReadFromInputStringOn();
  reader->SetInputString(std::string(bytes));
  run_vtk(format, [&] { reader->Update(); });
  fail_on_messages(*messages, format, false, "the data do not read as the markup declares them");
  if (reader->GetErrorCode() != vtkErrorCode::NoError)
    throw bad_input("{}: {}", format, error_code_text(reader->GetErrorCode()));
  vtkSmartPointer<vtkDataSet> dataset = detach(reader->GetOutputDataObject(0), expected_class, format);
  validate_dataset(dataset, format);
  return dataset;
}

// vtkStructuredGridReader's metadata pass (VTK 9.1) scans every word of the file and
// treats any word starting with "field" as field data, dereferencing a null pointer
// when that is not one: a valid file with a scalar named "field_x" crashes it. Its
// only job is the whole extent, which the legacy scan already knows.
class StructuredGridReaderWithKnownExtent : public vtkStructuredGridReader {
 public:
  static StructuredGridReaderWithKnownExtent* New() {
    auto* reader = new StructuredGridReaderWithKnownExtent;
    reader->InitializeObjectBase();
    return reader;
  }
  void SetKnownDimensions(const int dims[3]) {
    for (int axis = 0; axis < 3; ++axis) dims_[axis] = dims[axis];
  }
  int ReadMetaDataSimple(const std::string&, vtkInformation* metadata) override {
    int extent[6] = {0, dims_[0] - 1, 0, dims_[1] - 1, 0, dims_[2] - 1};
    metadata->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    return 1;
  }

 private:
  int dims_[3] = {0, 0, 0};
};

vtkSmartPointer<vtkDataReader> legacy_reader(const LegacyHeader& header, const char** expected_class) {
  const std::string& dataset_type = header.dataset_type;
  if (dataset_type == "polydata") {
    *expected_class = "vtkPolyData";
    return vtkSmartPointer<vtkPolyDataReader>::New();
  }
  if (dataset_type == "structured_points") {
    *expected_class = "vtkImageData";
    return vtkSmartPointer<vtkStructuredPointsReader>::New();
  }
  if (dataset_type == "structured_grid") {
    *expected_class = "vtkStructuredGrid";
    auto reader = vtkSmartPointer<StructuredGridReaderWithKnownExtent>::New();
    reader->SetKnownDimensions(header.dimensions);
    return reader;
  }
  if (dataset_type == "rectilinear_grid") {
    *expected_class = "vtkRectilinearGrid";
    return vtkSmartPointer<vtkRectilinearGridReader>::New();
  }
  *expected_class = "vtkUnstructuredGrid";
  return vtkSmartPointer<vtkUnstructuredGridReader>::New();
}

vtkSmartPointer<vtkDataSet> read_legacy(std::string_view bytes) {
  const char* format = "vtk";
  // vtkDataReader keeps the length of its input in an int.
  if (bytes.size() > static_cast<size_t>(INT_MAX))
    throw bad_input("vtk: {} bytes is more than the legacy reader can take (2 GiB)", bytes.size());
  LegacyHeader header = scan_legacy_vtk(bytes);
  // vtkDataSetReader would pick the reader itself, but its inner reader's messages
  // never reach an observer on the outer one; choosing here keeps them.
  const char* expected_class = nullptr;
  vtkSmartPointer<vtkDataReader> reader = legacy_reader(header, &expected_class);

  auto messages = vtkSmartPointer<MessageCollector>::New();
  MessageCapture capture(messages);
  observe(reader, messages);
  reader->ReadFromInputStringOn();
  reader->SetBinaryInputString(bytes.data(), static_cast<int>(bytes.size()));
  // By default the reader keeps only the first SCALARS, VECTORS, ... and drops the
  // rest silently; a converter must keep them all.
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  run_vtk(format, [&] { reader->Update(); });
  fail_on_messages(*messages, format, true, "the data do not read as the header declares them");
  if (reader->GetErrorCode() != vtkErrorCode::NoError)
    throw bad_input("vtk: {}", error_code_text(reader->GetErrorCode()));
  vtkSmartPointer<vtkDataSet> dataset = detach(reader->GetOutputDataObject(0), expected_class, format);
  validate_dataset(dataset, format);
  return dataset;
}

template <typename Writer>
std::string write_xml(vtkDataSet* dataset, bool ascii, const char* format, bool zlib = false) {
  auto messages = vtkSmartPointer<MessageCollector>::New();
  MessageCapture capture(messages);
  auto writer = vtkSmartPointer<Writer>::New();
  observe(writer, messages);
  writer->SetInputData(dataset);
  writer->WriteToOutputStringOn();
  // Uncompressed, fixed byte order and header widths: the same dataset always gives
  // the same bytes, on any machine.
  writer->SetCompressorTypeToNone();
  if (zlib) writer->SetCompressorTypeToZLib();  // deterministic too: same input, same bytes
  writer->SetByteOrderToLittleEndian();
  writer->SetHeaderTypeToUInt64();
  writer->SetIdTypeToInt64();
  if (ascii) {
    writer->SetDataModeToAscii();
  } else {
    writer->SetDataModeToAppended();
    writer->EncodeAppendedDataOff();  // raw bytes, not base64
  }
  int ok = 0;
  run_vtk(format, [&] { ok = writer->Write(); });
  fail_on_messages(*messages, format, true, "VTK could not write the dataset");
  if (!ok) throw bad_input("{}: VTK could not write this {}", format, dataset->GetClassName());
  return writer->GetOutputString();
}

std::string write_legacy(vtkDataSet* dataset, bool ascii) {
  auto messages = vtkSmartPointer<MessageCollector>::New();
  MessageCapture capture(messages);
  auto writer = vtkSmartPointer<vtkDataSetWriter>::New();
  observe(writer, messages);
  writer->SetInputData(dataset);
  writer->WriteToOutputStringOn();
  if (ascii) {
    writer->SetFileTypeToASCII();
  } else {
    writer->SetFileTypeToBinary();
  }
  int ok = 0;
  run_vtk("vtk", [&] { ok = writer->Write(); });
  fail_on_messages(*messages, "vtk", true, "VTK could not write the dataset");
  if (!ok) throw bad_input("vtk: VTK could not write this {}", dataset->GetClassName());
  return writer->GetOutputStdString();
}

void require_class(vtkDataSet* dataset, const char* wanted, const char* format, const char* holds) {
  if (!dataset->IsA(wanted))
    throw bad_input("{} holds {}, not a {}; convert it first or write .vtk", format, holds, dataset->GetClassName());
}

}  // namespace

vtkSmartPointer<vtkDataSet> read_vtk_dataset(std::string_view bytes, Format format) {
  switch (format) {
    case Format::vtu:
      return read_xml<vtkXMLUnstructuredGridReader>(bytes, "UnstructuredGrid", "vtkUnstructuredGrid", "vtu");
    case Format::vti:
      return read_xml<vtkXMLImageDataReader>(bytes, "ImageData", "vtkImageData", "vti");
    case Format::vtp:
      return read_xml<vtkXMLPolyDataReader>(bytes, "PolyData", "vtkPolyData", "vtp");
    case Format::vts:
      return read_xml<vtkXMLStructuredGridReader>(bytes, "StructuredGrid", "vtkStructuredGrid", "vts");
    case Format::vtk:
      return read_legacy(bytes);
    default:
      throw usage_error("format {} is not a VTK dataset format", static_cast<int>(format));
  }
}

std::string write_vtk_dataset(vtkDataSet* dataset, Format format, const DatasetWriteOptions& options) {
  if (dataset == nullptr) throw bad_input("no dataset to write");
  switch (format) {
    case Format::vtu:
      require_class(dataset, "vtkUnstructuredGrid", "vtu", "unstructured grids");
      return write_xml<vtkXMLUnstructuredGridWriter>(dataset, options.ascii, "vtu");
    case Format::vti:
      require_class(dataset, "vtkImageData", "vti", "image data");
      return write_xml<vtkXMLImageDataWriter>(dataset, options.ascii, "vti", options.zlib);
    case Format::vtp:
      require_class(dataset, "vtkPolyData", "vtp", "polygonal data");
      return write_xml<vtkXMLPolyDataWriter>(dataset, options.ascii, "vtp");
    case Format::vts:
      require_class(dataset, "vtkStructuredGrid", "vts", "structured grids");
      return write_xml<vtkXMLStructuredGridWriter>(dataset, options.ascii, "vts");
    case Format::vtk:
      if (!dataset->IsA("vtkPolyData") && !dataset->IsA("vtkImageData") && !dataset->IsA("vtkStructuredGrid") &&
          !dataset->IsA("vtkRectilinearGrid") && !dataset->IsA("vtkUnstructuredGrid"))
        throw bad_input("vtk: legacy files cannot hold a {}", dataset->GetClassName());
      return write_legacy(dataset, options.ascii);
    default:
      throw usage_error("format {} is not a VTK dataset format", static_cast<int>(format));
  }
}

}  // namespace fest::formats::detail
