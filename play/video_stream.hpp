#pragma once
// A quilt video decoding ahead on its own thread (docs/play.md "Timing"): the decoder
// (media::VideoDecoder) fills a short queue of frames; the player's GL thread takes, once per
// vsync, the newest frame due at the playback clock. Frames that were decoded but passed over
// because a later one was already due are the dropped frames. After open and after a seek the
// GL thread waits for the first frame (bounded), so the frame on screen is the one asked for.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "media/video_decoder.hpp"

namespace lfd::play {

// Frames decoded ahead of the clock (three 4K 4:2:0 frames: 37 MB).
inline constexpr size_t kDecodeAhead = 3;
// How long the GL thread waits for the first frame after an open or a seek.
inline constexpr double kFirstFrameTimeoutS = 10.0;

class VideoStream {
 public:
  // Opens the file on the calling thread (so a bad file is an InputError here) and starts
  // decoding.
  VideoStream(const std::filesystem::path& path, const media::DecoderOptions& options);
  ~VideoStream();
  VideoStream(const VideoStream&) = delete;
  VideoStream& operator=(const VideoStream&) = delete;

  const media::VideoInfo& info() const { return info_; }
  const std::string& decode_path() const { return decode_path_; }

  // The newest frame with pts <= `clock_s` not yet handed out (nullopt: keep showing the last);
  // the frames it passes over are added to `dropped`. Waits for the first frame after an open
  // or seek. Throws InputError when the decoder failed on corrupt data.
  std::optional<media::YuvFrame> frame_due(double clock_s, int64_t& dropped);
  // Whether the stream has ended and every decoded frame has been handed out or passed over.
  bool finished();
  void seek(double seconds);
  int64_t frames_decoded();

 private:
  void decode_loop();

  media::VideoDecoder decoder_;
  media::VideoInfo info_;
  std::string decode_path_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<media::YuvFrame> queue_;
  std::optional<double> seek_to_;      // asked for, not yet done by the decoder thread
  bool waiting_first_ = true;          // after open/seek: frame_due waits for a frame
  bool ended_ = false, stop_ = false;
  int64_t generation_ = 0;             // bumped by seek: frames of an older one are discarded
  int64_t decoded_ = 0;
  std::string error_;
  std::thread thread_;
};

}  // namespace lfd::play
