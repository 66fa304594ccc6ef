// EXR through OpenEXR directly (not OpenCV) so that half/float and the channel layout
// are ours to choose, on in-memory streams so no temporary file is involved. Every
// channel is read as 32-bit float; files hold R,G,B(,A) or Y(,A) (header_exr.cpp).
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <string>

#include <ImfChannelList.h>
#include <ImfCompression.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <Iex.h>
#include <half.h>

#include "core/error.hpp"
#include "formats/image/exr_channels.hpp"
#include "formats/image/image_codecs.hpp"

namespace fest::formats::image_detail {
namespace {

class MemoryInput : public Imf::IStream {
 public:
  explicit MemoryInput(std::string_view bytes) : Imf::IStream("<memory>"), bytes_(bytes) {}

  bool read(char c[], int n) override {
    if (n < 0 || pos_ > bytes_.size() || std::uint64_t(n) > bytes_.size() - pos_)
      throw Iex::InputExc("unexpected end of file");
    std::memcpy(c, bytes_.data() + pos_, std::size_t(n));
    pos_ += std::uint64_t(n);
    return pos_ < bytes_.size();
  }
  std::uint64_t tellg() override { return pos_; }
  void seekg(std::uint64_t pos) override { pos_ = pos; }  // read() checks the bounds

 private:
  std::string_view bytes_;
  std::uint64_t pos_ = 0;
};

class MemoryOutput : public Imf::OStream {
 public:
  MemoryOutput() : Imf::OStream("<memory>") {}

  void write(const char c[], int n) override {
    if (n <= 0) return;
    if (pos_ + std::uint64_t(n) > data_.size()) data_.resize(pos_ + std::size_t(n));
    std::memcpy(data_.data() + pos_, c, std::size_t(n));
    pos_ += std::uint64_t(n);
  }
  std::uint64_t tellp() override { return pos_; }
  // OpenEXR seeks back to fill in the chunk offset table once the pixels are written.
  void seekp(std::uint64_t pos) override { pos_ = pos; }
  std::string take() { return std::move(data_); }

 private:
  std::string data_;
  std::uint64_t pos_ = 0;
};

// The channels an image of n channels is stored as.
std::vector<const char*> channel_names(int n) {
  switch (n) {
    case 1: return {"Y"};
    case 2: return {"Y", "A"};
    case 3: return {"R", "G", "B"};
    default: return {"R", "G", "B", "A"};
  }
}

// Opens the EXR file held in `bytes` and hands it to `read`; what OpenEXR throws is bad
// input ("EXR data: ..."), fest's own errors pass unchanged.
template <class Read>
auto read_exr_file(std::string_view bytes, Read&& read) {
  try {
    MemoryInput stream(bytes);
    Imf::InputFile file(stream);
    return read(file);
  } catch (const fest::Error&) {
    throw;
  } catch (const std::exception& e) {
    throw bad_input("EXR data: {}", e.what());
  }
}

// Reads the whole data window of `file` with `frame` (float slices into an image of
// that window's size).
void read_window(Imf::InputFile& file, const Imath::Box2i& window, const Imf::FrameBuffer& frame) {
  file.setFrameBuffer(frame);
  file.readPixels(window.min.y, window.max.y);
}

// Writes a ZIP-compressed EXR of width x height to memory: `describe(header, frame)`
// adds the channels and attributes to the header and their slices to the frame buffer.
// ZIP is lossless and deterministic; it compresses 16 lines at a time. What OpenEXR
// throws is a runtime failure of the writer. With a `progress` listener the lines go in
// 16 blocks at a time, each reported: OpenEXR buffers whole blocks either way, so the
// bytes are the same as one writePixels(height).
template <class Describe>
std::string write_exr_file(int width, int height, Describe&& describe, const ProgressFn& progress = {}) {
  MemoryOutput stream;
  try {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    Imf::FrameBuffer frame;
    describe(header, frame);
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    if (!progress) {
      file.writePixels(height);
    } else {
      constexpr int kLinesPerReport = 16 * 16;
      for (int y = 0; y < height; y += kLinesPerReport) {
        const int lines = std::min(kLinesPerReport, height - y);
        file.writePixels(lines);
        progress(std::uint64_t(y + lines), std::uint64_t(height));
      }
    }
  } catch (const std::exception& e) {
    throw runtime_failure("EXR writer: {}", e.what());
  }
  return stream.take();
}

}  // namespace

cv::Mat decode_exr(std::string_view bytes) {
  const ExrLayout layout = read_exr_layout(bytes);
  const ImageHeader& h = layout.header;
  return read_exr_file(bytes, [&](Imf::InputFile& file) {
    // OpenEXR parsed the header itself; it must agree with ours, which sized the image.
    const Imath::Box2i window = file.header().dataWindow();
    if (window.min.x != layout.data_window[0] || window.min.y != layout.data_window[1] ||
        window.max.x != layout.data_window[2] || window.max.y != layout.data_window[3])
      throw bad_input("EXR header: inconsistent data window");
    cv::Mat out(h.height, h.width, CV_MAKETYPE(CV_32F, h.channels), cv::Scalar::all(0));
    const std::size_t x_stride = sizeof(float) * std::size_t(h.channels);
    Imf::FrameBuffer frame;
    for (int c = 0; c < h.channels; ++c) {
      const std::string& name = layout.channels[std::size_t(c)].name;
      if (!file.header().channels().findChannel(name))
        throw bad_input("EXR header: inconsistent channel list (no '{}')", name);
      frame.insert(name, Imf::Slice::Make(Imf::FLOAT, out.ptr<float>() + c, window, x_stride, x_stride * h.width));
    }
    read_window(file, window, frame);
    return out;
  });
}

std::string encode_exr(const cv::Mat& pixels, bool half, const ProgressFn& progress) {
  const std::vector<const char*> names = channel_names(pixels.channels());
  const cv::Mat continuous = pixels.isContinuous() ? pixels : pixels.clone();
  std::vector<Imath::half> halves;
  return write_exr_file(continuous.cols, continuous.rows, [&](Imf::Header& header, Imf::FrameBuffer& frame) {
    for (const char* name : names) header.channels().insert(name, Imf::Channel(half ? Imf::HALF : Imf::FLOAT));
    // OutputFile does not convert float slices to half channels, so halves are made
    // here (Imath rounds to nearest, ties to even).
    const std::size_t samples = continuous.total() * names.size();
    if (half) {
      halves.resize(samples);
      const float* from = continuous.ptr<float>();
      for (std::size_t i = 0; i < samples; ++i) halves[i] = Imath::half(from[i]);
    }
    const std::size_t sample_size = half ? sizeof(Imath::half) : sizeof(float);
    char* base = half ? reinterpret_cast<char*>(halves.data()) : const_cast<char*>(continuous.ptr<char>());
    const std::size_t x_stride = sample_size * names.size();
    for (std::size_t c = 0; c < names.size(); ++c)
      frame.insert(names[c], Imf::Slice(half ? Imf::HALF : Imf::FLOAT, base + c * sample_size, x_stride,
                                        x_stride * std::size_t(continuous.cols)));
  }, progress);
}

}  // namespace fest::formats::image_detail

// ---- EXR with extra channels and attributes (exr_extras.hpp) ----------------------

#include <ImfChromaticitiesAttribute.h>
#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfFloatVectorAttribute.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include "formats/image/exr_extras.hpp"

namespace fest::formats::image_detail {

std::string exr_write_with_extras(const cv::Mat& rgb, const ExrExtras& extras, bool half) {
  if (rgb.type() != CV_32FC3) throw bad_input("EXR writer: extras need a float RGB image");
  std::vector<std::pair<std::string, cv::Mat>> planes;
  {
    std::vector<cv::Mat> split;
    cv::split(rgb, split);
    planes = {{"R", split[0]}, {"G", split[1]}, {"B", split[2]}};
  }
  for (const auto& [name, m] : extras.channels) {
    if (m.type() != CV_32FC1 || m.size() != rgb.size())
      throw bad_input("EXR writer: channel '{}' must be one float plane of the image's size", name);
    planes.emplace_back(name, m.isContinuous() ? m : m.clone());
  }
  std::vector<std::vector<Imath::half>> halves(planes.size());
  return write_exr_file(rgb.cols, rgb.rows, [&](Imf::Header& header, Imf::FrameBuffer& frame) {
    if (extras.srgb_chromaticities) Imf::addChromaticities(header, Imf::Chromaticities());
    for (const auto& [k, v] : extras.strings) header.insert(k, Imf::StringAttribute(v));
    for (const auto& [k, v] : extras.doubles) header.insert(k, Imf::DoubleAttribute(v));
    for (const auto& [k, v] : extras.float_vectors) header.insert(k, Imf::FloatVectorAttribute(v));
    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;
    for (const auto& p : planes) header.channels().insert(p.first, Imf::Channel(type));
    for (std::size_t c = 0; c < planes.size(); ++c) {
      const float* from = planes[c].second.ptr<float>();
      if (half) {
        halves[c].assign(from, from + planes[c].second.total());
        frame.insert(planes[c].first, Imf::Slice(Imf::HALF, reinterpret_cast<char*>(halves[c].data()), sizeof(Imath::half),
                                                 sizeof(Imath::half) * std::size_t(rgb.cols)));
      } else {
        frame.insert(planes[c].first, Imf::Slice(Imf::FLOAT, const_cast<char*>(reinterpret_cast<const char*>(from)),
                                                 sizeof(float), sizeof(float) * std::size_t(rgb.cols)));
      }
    }
  });
}

cv::Mat exr_read_channel(std::string_view bytes, const std::string& name) {
  read_exr_layout(bytes);  // the same sanity checks as read_image
  return read_exr_file(bytes, [&](Imf::InputFile& file) {
    if (!file.header().channels().findChannel(name)) throw bad_input("EXR data: no channel '{}'", name);
    const Imath::Box2i window = file.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    cv::Mat out(height, width, CV_32FC1, cv::Scalar(0));
    Imf::FrameBuffer frame;
    frame.insert(name, Imf::Slice::Make(Imf::FLOAT, out.ptr<float>(), window, sizeof(float), sizeof(float) * std::size_t(width)));
    read_window(file, window, frame);
    return out;
  });
}

ExrExtras exr_read_attributes(std::string_view bytes) {
  read_exr_layout(bytes);
  return read_exr_file(bytes, [](Imf::InputFile& file) {
    ExrExtras out;
    out.srgb_chromaticities = false;
    for (auto it = file.header().begin(); it != file.header().end(); ++it) {
      if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute())) out.strings[it.name()] = s->value();
      else if (auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&it.attribute())) out.doubles[it.name()] = d->value();
      else if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&it.attribute())) out.doubles[it.name()] = f->value();
      else if (auto* v = dynamic_cast<const Imf::FloatVectorAttribute*>(&it.attribute())) out.float_vectors[it.name()] = v->value();
      else if (std::string(it.name()) == "chromaticities") out.srgb_chromaticities = true;
    }
    return out;
  });
}

}  // namespace fest::formats::image_detail
