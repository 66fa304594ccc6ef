#pragma once
// VTK reports problems by printing them (vtkOutputWindow, vtkLogger) and carries on.
// fest must never print from library code, and must turn those reports into errors,
// so every VTK call in this folder runs inside a MessageCapture: VTK's console is
// silenced once for the whole process, and what VTK says is collected here instead.

#include <string>
#include <vector>

#include <vtkCommand.h>

class vtkObject;

namespace fest::formats::detail {

// Collects VTK's error and warning texts, cleaned to one line each ("Cannot read
// points array from Points in piece 0").
class MessageCollector : public vtkCommand {
 public:
  static MessageCollector* New() { return new MessageCollector; }
  void Execute(vtkObject* caller, unsigned long event_id, void* call_data) override;

  void add(bool is_error, const char* raw_text);
  const std::vector<std::string>& errors() const { return errors_; }
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::vector<std::string> errors_;
  std::vector<std::string> warnings_;
};

// Installs the silent output window (once per process) and, while alive, routes every
// message VTK sends to that window from this thread into `collector` (messages from
// objects that have no observer of their own, e.g. arrays inside a reader).
class MessageCapture {
 public:
  explicit MessageCapture(MessageCollector* collector);
  ~MessageCapture();
  MessageCapture(const MessageCapture&) = delete;
  MessageCapture& operator=(const MessageCapture&) = delete;

 private:
  MessageCollector* previous_;
};

// Makes VTK quiet for the whole process; idempotent and thread-safe.
void silence_vtk();

// Observes ErrorEvent and WarningEvent of `object` into `collector`.
void observe(vtkObject* object, MessageCollector* collector);

// "vtkXMLUnstructuredGridReader (0x55d0...): Error parsing XML ..." -> "Error parsing
// XML ...": the first meaningful line of a VTK message without file, line or address.
std::string clean_vtk_message(const char* raw_text);

}  // namespace fest::formats::detail
