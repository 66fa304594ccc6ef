#pragma once
// The stored pixels of an image, handed out a band of rows at a time (docs/resample.md,
// "Streaming"): the resize reads its input through this, so that a file can feed the
// first pass directly and the whole input is never held in memory.

#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace fest::sampling {

class StoredRows {
 public:
  virtual ~StoredRows() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual int type() const = 0;  // CV_8UC(c), CV_16UC(c) or CV_32FC(c), native byte order

  // Rows [first, last) of the image (top to bottom) as a (last - first) x width matrix:
  // a view of memory the source owns, or of `buffer` (room for the rows, packed, aligned
  // for the samples), which the source fills. Called from several threads at once, each
  // with its own buffer. A read failure throws fest::Error.
  virtual cv::Mat rows(int first, int last, void* buffer) const = 0;
};

// An image already in memory: rows() returns views, nothing is copied.
class MatRows final : public StoredRows {
 public:
  explicit MatRows(const cv::Mat& m) : m_(m) {}
  int width() const override { return m_.cols; }
  int height() const override { return m_.rows; }
  int type() const override { return m_.type(); }
  cv::Mat rows(int first, int last, void*) const override { return m_.rowRange(first, last); }

 private:
  const cv::Mat& m_;
};

}  // namespace fest::sampling
