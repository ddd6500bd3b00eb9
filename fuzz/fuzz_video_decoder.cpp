// libFuzzer target: quilt videos from memory (media::VideoDecoder over FFmpeg's demuxers and
// decoders, one thread, no hardware): open, decode up to 8 frames, seek back and decode one,
// converting each to RGB on the CPU. Any input either decodes or throws lfd::InputError.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "media/video_decoder.hpp"
#include "util/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace lfd::media;
  try {
    VideoDecoder decoder(std::vector<uint8_t>(data, data + size), "fuzz.mp4", {false, 1});
    for (int i = 0; i < 8; ++i) {
      const auto frame = decoder.next_frame();
      if (!frame) break;
      if (frame->width > 512 || frame->height > 512) break;  // big frames: slow, not new code
      yuv_to_rgb(*frame);
    }
    decoder.seek(0);
    decoder.next_frame();
  } catch (const lfd::InputError&) {
  }
  return 0;
}
