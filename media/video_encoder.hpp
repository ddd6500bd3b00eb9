#pragma once
// Writes quilt videos with libavcodec's software encoders (docs/play.md "Test videos",
// docs/record.md "Encoding"): `lfd record`'s videos, the test fixtures and `lfd bench play`'s
// synthetic 4K quilt videos are made with it, so no video file has to be stored or downloaded. RGB frames go to 8-bit 4:2:0 BT.709 limited range (libswscale),
// tagged so a decoder reads them back with the same matrix and range.
#include <filesystem>
#include <memory>
#include <string>

#include "util/image.hpp"

namespace lfd::media {

struct EncoderOptions {
  std::string codec = "libx264";  // any libavcodec video encoder ("libx264", "libx265", "libvpx-vp9", "mpeg4")
  int width = 0, height = 0;      // even
  int frame_rate = 30;
  int crf = 18;                   // quality for x264/x265/vpx (lower is better)
  std::string preset = "veryfast";  // x264/x265 speed preset
  int gop = 0;                    // keyframe interval in frames; 0: one per second
  // MP4/MOV written as fragments (one per keyframe interval) after an empty header, so a file cut
  // off by a crash still plays up to its last whole fragment (docs/record.md "Interrupted").
  bool fragmented = false;
};

// InputError "<what>: WxH ..." unless libavcodec's `codec` takes frames of that size: even sides
// (4:2:0), at least 16 pixels, and within the largest level of H.264 and H.265 (6.2: 35,651,584
// pixels, each side at most 16384).
void check_video_size(const std::string& codec, int width, int height, const std::string& what);

class VideoEncoder {
 public:
  // The container comes from the file's extension (.mp4, .mov, .mkv, .webm). InputError naming
  // the file when the encoder or container is missing or the file cannot be created.
  VideoEncoder(const std::filesystem::path& path, const EncoderOptions& options);
  ~VideoEncoder();  // finishes the file if finish() was not called (errors then are swallowed)
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // One frame: RGB, rows top-down, the size given.
  void add_frame(const Image8& rgb);
  // Flushes the encoder and writes the trailer.
  void finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lfd::media
