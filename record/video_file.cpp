#include "record/video_file.hpp"

#include <algorithm>
#include <cstring>

#include "util/error.hpp"

namespace lfd::record {

std::filesystem::path partial_path(const std::filesystem::path& final_path) {
  std::filesystem::path p = final_path;
  return p.replace_filename(final_path.stem().string() + ".partial" + final_path.extension().string());
}

VideoFile::VideoFile(const std::filesystem::path& final_path, int width, int height, media::EncoderOptions options)
    : final_(final_path), partial_(partial_path(final_path)), width_(width), height_(height) {
  options.width = width + width % 2;
  options.height = height + height % 2;
  options.fragmented = true;
  std::error_code ec;
  if (final_.has_parent_path()) std::filesystem::create_directories(final_.parent_path(), ec);
  if (ec) throw_input_error("{}: cannot create its folder ({})", final_.string(), ec.message());
  encoder_ = std::make_unique<media::VideoEncoder>(partial_, options);
  padded_ = Image8(options.width, options.height, 3, 0);
}

VideoFile::~VideoFile() {
  if (finished_) return;
  encoder_.reset();
  std::error_code ec;
  std::filesystem::remove(partial_, ec);
}

void VideoFile::add(const Image8& rgb) {
  if (rgb.width != width_ || rgb.height != height_ || rgb.channels != 3)
    throw std::invalid_argument(final_.string() + ": a frame's size differs from the video's");
  if (padded_.width == width_ && padded_.height == height_) {
    encoder_->add_frame(rgb);
  } else {
    // Rows top-down: the padding row is the top one, the column the right one.
    const int dy = padded_.height - height_;
    for (int y = 0; y < height_; ++y)
      std::memcpy(&padded_.pixels[(size_t(y + dy) * padded_.width) * 3], &rgb.pixels[size_t(y) * width_ * 3],
                  size_t(width_) * 3);
    encoder_->add_frame(padded_);
  }
  ++frames_;
}

const std::filesystem::path& VideoFile::finish() {
  encoder_->finish();
  encoder_.reset();
  std::filesystem::rename(partial_, final_);
  finished_ = true;
  return final_;
}

}  // namespace lfd::record
