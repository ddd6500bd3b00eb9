#pragma once
// What one playlist entry shows (play/player.cpp): a still quilt (an image file, or a picture
// handed over in memory) or a quilt video decoding on its thread, with the tiling to interlace
// it with. Opening one is where a bad file becomes an InputError naming it.
#include <memory>
#include <optional>
#include <string>

#include "media/quilt_image.hpp"
#include "play/player.hpp"
#include "play/video_stream.hpp"

namespace lfd::play {

struct EntryContent {
  std::string name;                     // the file name (or the in-memory picture's)
  render::QuiltLayout layout;
  std::optional<Image8> still;          // a quilt image (uploaded once)
  std::unique_ptr<VideoStream> video;   // or a quilt video
  double duration_s = 0;                // how long the entry runs (0: a video to its end)
};

// Opens a playlist entry for a display of `display_aspect`; `default_duration_s` for images.
EntryContent open_entry(const PlaylistEntry& entry, double display_aspect, double default_duration_s,
                        const media::DecoderOptions& decoder);

}  // namespace lfd::play
