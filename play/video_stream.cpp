#include "play/video_stream.hpp"

#include <chrono>

#include "util/error.hpp"

namespace lfd::play {

VideoStream::VideoStream(const std::filesystem::path& path, const media::DecoderOptions& options)
    : decoder_(path, options), info_(decoder_.info()), decode_path_(decoder_.decode_path()) {
  thread_ = std::thread([this] { decode_loop(); });
}

VideoStream::~VideoStream() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void VideoStream::decode_loop() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    if (seek_to_) {
      const double target = *seek_to_;
      seek_to_.reset();
      const int64_t generation = generation_;
      lock.unlock();
      std::string error;
      try {
        decoder_.seek(target);
      } catch (const std::exception& e) {
        error = e.what();
      }
      lock.lock();
      if (!error.empty()) error_ = error;
      if (generation == generation_) ended_ = false;
      continue;
    }
    if (ended_ || queue_.size() >= kDecodeAhead || !error_.empty()) {
      changed_.wait(lock);
      continue;
    }
    const int64_t generation = generation_;
    lock.unlock();
    std::optional<media::YuvFrame> frame;
    std::string error;
    try {
      frame = decoder_.next_frame();
    } catch (const std::exception& e) {
      error = e.what();
    }
    lock.lock();
    decoded_ = decoder_.frames_decoded();
    if (generation != generation_ || seek_to_) continue;  // a seek came in meanwhile
    if (!error.empty()) error_ = error;
    else if (frame) queue_.push_back(std::move(*frame));
    else ended_ = true;
    changed_.notify_all();
  }
}

std::optional<media::YuvFrame> VideoStream::frame_due(double clock_s, int64_t& dropped) {
  std::unique_lock lock(mutex_);
  if (waiting_first_) {
    changed_.wait_for(lock, std::chrono::duration<double>(kFirstFrameTimeoutS),
                      [&] { return !queue_.empty() || ended_ || !error_.empty(); });
  }
  if (!error_.empty()) throw InputError(error_);
  std::optional<media::YuvFrame> due;
  // The first frame after an open or seek is shown whatever its time (the clock starts there).
  while (!queue_.empty() && (waiting_first_ || queue_.front().pts_s <= clock_s + 1e-6)) {
    if (due) ++dropped;
    due = std::move(queue_.front());
    queue_.pop_front();
    waiting_first_ = false;
  }
  if (due) changed_.notify_all();
  return due;
}

bool VideoStream::finished() {
  std::lock_guard lock(mutex_);
  return ended_ && queue_.empty() && !seek_to_;
}

void VideoStream::seek(double seconds) {
  {
    std::lock_guard lock(mutex_);
    queue_.clear();
    seek_to_ = seconds;
    ++generation_;
    ended_ = false;
    waiting_first_ = true;
    error_.clear();
  }
  changed_.notify_all();
}

int64_t VideoStream::frames_decoded() {
  std::lock_guard lock(mutex_);
  return decoded_;
}

}  // namespace lfd::play
