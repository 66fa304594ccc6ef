#pragma once
// A raw PGM/PPM/PAM or PFM input file handed to the resize a band of rows at a time
// (formats::NetpbmRowFile as sampling::StoredRows): the first pass reads the file
// directly, so neither the file's bytes nor its decoded pixels are ever held whole.

#include <memory>
#include <string>

#include "formats/image/netpbm_rows.hpp"
#include "sampling/stored_rows.hpp"

namespace fest::resample_tool {

class StreamedInput final : public fest::sampling::StoredRows {
 public:
  // nullptr when `path` is not a raw Netpbm/PFM file that can be streamed (then
  // load_image reads it whole); bad_input for a header read_image would refuse.
  static std::unique_ptr<StreamedInput> open(const std::string& path);

  int width() const override { return file_->header().width; }
  int height() const override { return file_->header().height; }
  int type() const override { return file_->cv_type(); }
  cv::Mat rows(int first, int last, void* buffer) const override;
  fest::ColorSpace color_space() const { return file_->color_space(); }

 private:
  explicit StreamedInput(std::unique_ptr<fest::formats::NetpbmRowFile> f) : file_(std::move(f)) {}
  std::unique_ptr<fest::formats::NetpbmRowFile> file_;
};

}  // namespace fest::resample_tool
