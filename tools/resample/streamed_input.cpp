#include "streamed_input.hpp"

namespace resample_tool {

std::unique_ptr<StreamedInput> StreamedInput::open(const std::string& path) {
  auto f = fest::formats::NetpbmRowFile::open(path);
  if (!f) return nullptr;
  return std::unique_ptr<StreamedInput>(new StreamedInput(std::move(f)));
}

cv::Mat StreamedInput::rows(int first, int last, std::vector<std::uint8_t>& scratch) const {
  scratch.resize(static_cast<std::size_t>(last - first) * file_->row_bytes());
  file_->read_rows(first, last, scratch.data());
  return cv::Mat(last - first, width(), type(), scratch.data());
}

}  // namespace resample_tool
