#include "formats/dataset/vtk_messages.hpp"
#include "core/quote.hpp"

#include <cstring>
#include <mutex>
#include <string_view>

#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

namespace fest::formats::detail {
namespace {

// The collector of the MessageCapture active on this thread, if any.
thread_local MessageCollector* active_collector = nullptr;

// Replaces VTK's default window, which writes to stderr (or stdout for plain text):
// messages go to the active collector of the calling thread, or nowhere.
class SilentOutputWindow : public vtkOutputWindow {
 public:
  static SilentOutputWindow* New() {
    auto* window = new SilentOutputWindow;
    window->InitializeObjectBase();
    return window;
  }
  vtkTypeMacro(SilentOutputWindow, vtkOutputWindow)

  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override { forward(true, text); }
  void DisplayWarningText(const char* text) override { forward(false, text); }
  void DisplayGenericWarningText(const char* text) override { forward(false, text); }
  void DisplayDebugText(const char*) override {}

 private:
  static void forward(bool is_error, const char* text) {
    if (active_collector != nullptr) active_collector->add(is_error, text);
  }
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r' || s.back() == '.'))
    s.remove_suffix(1);
  return s;
}

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && s.compare(0, prefix.size(), prefix) == 0;
}

}  // namespace

void silence_vtk() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Messages must still be produced (observers only see them when this is on), but
    // they end in the silent window below instead of the console.
    vtkObject::GlobalWarningDisplayOn();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    auto window = vtkSmartPointer<SilentOutputWindow>::New();
    vtkOutputWindow::SetInstance(window);
  });
}

void MessageCollector::Execute(vtkObject*, unsigned long event_id, void* call_data) {
  const char* text = static_cast<const char*>(call_data);
  if (event_id == vtkCommand::ErrorEvent) add(true, text);
  if (event_id == vtkCommand::WarningEvent) add(false, text);
}

void MessageCollector::add(bool is_error, const char* raw_text) {
  std::string text = clean_vtk_message(raw_text);
  if (text.empty()) text = is_error ? "unspecified VTK error" : "unspecified VTK warning";
  (is_error ? errors_ : warnings_).push_back(std::move(text));
}

MessageCapture::MessageCapture(MessageCollector* collector) : previous_(active_collector) {
  silence_vtk();
  active_collector = collector;
}

MessageCapture::~MessageCapture() { active_collector = previous_; }

void observe(vtkObject* object, MessageCollector* collector) {
  if (object == nullptr) return;
  object->AddObserver(vtkCommand::ErrorEvent, collector);
  object->AddObserver(vtkCommand::WarningEvent, collector);
}

std::string clean_vtk_message(const char* raw_text) {
  if (raw_text == nullptr) return {};
  std::string_view rest(raw_text);
  // VTK's layout: "ERROR: In /path/file.cxx, line 123\nClass (0x...): message\n\n".
  while (!rest.empty()) {
    size_t end = rest.find('\n');
    std::string_view line = trim(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    if (line.empty()) continue;
    if (starts_with(line, "ERROR: In ") || starts_with(line, "Warning: In ") ||
        starts_with(line, "Generic Warning: In "))
      continue;
    // Drop "vtkSomething (0x1234abcd): ".
    size_t paren = line.find(" (0x");
    if (paren != std::string_view::npos) {
      size_t close = line.find("): ", paren);
      if (close != std::string_view::npos) line.remove_prefix(close + 3);
    }
    // The legacy reader appends the (here meaningless) file name.
    for (std::string_view tail : {" for file: (Null FileName)", " for file: "}) {
      size_t at = line.find(tail);
      if (at != std::string_view::npos) line = line.substr(0, at);
    }
    line = trim(line);
    // Escaped and cut: VTK quotes the bytes it could not read (a mutated keyword).
    if (!line.empty()) return fest::quoted_bytes(line, 160);
  }
  return {};
}

}  // namespace fest::formats::detail
