#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a recording (docs/record.md "Interrupted"): while a
// StopRequest lives, the signals only raise its flag, so the recorder finishes the frame it is on,
// closes the video with the frames done and returns; a second Ctrl-C ends the program as usual.
#include <atomic>

namespace lfd::record {

class StopRequest {
 public:
  StopRequest();   // installs the handlers
  ~StopRequest();  // restores the previous ones
  StopRequest(const StopRequest&) = delete;
  StopRequest& operator=(const StopRequest&) = delete;
  // True once a signal came; the flag the recorder polls between frames.
  static const std::atomic<bool>& flag();
};

}  // namespace lfd::record
