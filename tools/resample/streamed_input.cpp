#include "streamed_input.hpp"

namespace fest::resample_tool {

std::unique_ptr<StreamedInput> StreamedInput::open(const std::string& path) {
  auto f = fest::formats::NetpbmRowFile::open(path);
  if (!f) return nullptr;
  return std::unique_ptr<StreamedInput>(new StreamedInput(std::move(f)));
}

cv::Mat StreamedInput::rows(int first, int last, void* buffer) const {
  file_->read_rows(first, last, buffer);
  return cv::Mat(last - first, width(), type(), buffer);
}

}  // namespace fest::resample_tool
