#pragma once
// The file a recording is encoded into (docs/record.md "Interrupted"): written as a fragmented
// MP4 under NAME.partial.mp4, so a crash leaves the frames of its whole fragments playable there,
// and renamed to NAME.mp4 when finished; an error mid-way removes it, so the final name never
// holds half a video.
#include <filesystem>
#include <memory>

#include "media/video_encoder.hpp"
#include "util/image.hpp"

namespace lfd::record {

// NAME.partial.EXT beside NAME.EXT.
std::filesystem::path partial_path(const std::filesystem::path& final_path);

class VideoFile {
 public:
  // Frames of width x height (odd sides are padded by a black column at the right or row at the
  // top, the quilt's unused margin). InputError naming the file when it cannot be created.
  VideoFile(const std::filesystem::path& final_path, int width, int height, media::EncoderOptions options);
  ~VideoFile();  // removes the partial file unless finish() ran
  VideoFile(const VideoFile&) = delete;
  VideoFile& operator=(const VideoFile&) = delete;

  void add(const Image8& rgb);
  int frames() const { return frames_; }
  // Flushes, closes and renames to the final name; returns it.
  const std::filesystem::path& finish();

 private:
  std::filesystem::path final_, partial_;
  int width_, height_;
  std::unique_ptr<media::VideoEncoder> encoder_;
  Image8 padded_;
  int frames_ = 0;
  bool finished_ = false;
};

}  // namespace lfd::record
