#pragma once
// Quilt videos decoded with FFmpeg's libraries (libavformat, libavcodec, libswscale; docs/play.md
// "Video"): MP4/MOV with H.264 or H.265, WebM/MKV with VP9 or AV1 (whichever decoders Debian's
// libavcodec has), audio ignored. Frame threads on the CPU; hardware decoding through VA-API
// (av_hwdevice_ctx_create) tried first when asked, with the software decoder as the fallback and
// the path taken reported. Frames come out as 8-bit 4:2:0 YUV planes (media/yuv_frame.hpp): the
// decoder's own frame when it is already that, else converted by libswscale (10-bit, 4:4:4,
// VA-API's NV12 downloads).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "media/yuv_frame.hpp"

namespace lfd::media {

// The largest frame accepted (the 32" Gen3's 8192^2 quilts fit).
inline constexpr int kMaxVideoSide = 8192;

struct DecoderOptions {
  bool try_hardware = true;  // VA-API, DRM, V4L2 M2M first (docs/arm.md); software when they are absent or fail
  int threads = 0;           // decoder threads; 0: one per core
};

struct VideoInfo {
  int width = 0, height = 0;
  double frame_rate = 0;     // frames per second (the stream's average, else its base rate)
  double duration_s = 0;     // 0 when the container does not say
  std::string codec;         // "h264", "hevc", "vp9", "av1", ...
  std::string container;     // "mov,mp4,m4a,3gp,3g2,mj2", "matroska,webm", ...
};

class VideoDecoder {
 public:
  // A file. InputError "PATH: ..." when it is not a video FFmpeg can open, has no video stream,
  // no decoder for its codec, or frames outside the bounds.
  VideoDecoder(const std::filesystem::path& path, const DecoderOptions& options = {});
  // Bytes in memory (the fuzz target, a video received over the network), called `name`.
  VideoDecoder(std::vector<uint8_t> bytes, const std::string& name, const DecoderOptions& options = {});
  ~VideoDecoder();
  VideoDecoder(const VideoDecoder&) = delete;
  VideoDecoder& operator=(const VideoDecoder&) = delete;

  const VideoInfo& info() const;
  // "software (N threads)" or "VA-API"; with the reason hardware decoding was not used, e.g.
  // "software (2 threads; VA-API: no device: ...)".
  const std::string& decode_path() const;
  const std::string& name() const;

  // The next frame in presentation order; nullopt at the end of the stream. The planes stay
  // valid until the frame's `storage` is released (the decoder does not reuse them).
  // InputError "NAME: ..." on corrupt data (a truncated file ends early instead when the
  // container simply stops).
  std::optional<YuvFrame> next_frame();
  // The next next_frame() is the frame shown at `seconds` (the last frame with pts <= seconds,
  // decoded forward from the keyframe before it); clamped to the stream.
  void seek(double seconds);
  // Frames decoded so far (including those decoded and passed over to reach a seek target).
  int64_t frames_decoded() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lfd::media
