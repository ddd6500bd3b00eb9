#pragma once
// What one playlist entry shows (play/player.cpp): a still quilt (an image file, or a picture
// handed over in memory) or a quilt video decoding on its thread, with the tiling to interlace
// it with. Opening one is where a bad file becomes an InputError naming it.
#include <memory>
#include <optional>
#include <string>

#include "display/calibration_file.hpp"
#include "media/quilt_image.hpp"
#include "play/transport.hpp"
#include "render/quilt_layout.hpp"
#include "play/video_stream.hpp"

namespace lfd::play {

struct EntryContent {
  std::string name;                     // the file name (or the in-memory picture's)
  render::QuiltLayout layout;           // the quilt shown (an RGB-D entry's: the views made of it)
  std::optional<rgbd::RgbdOptions> rgbd;  // set: the picture is an RGB-D frame
  std::optional<Image8> still;          // a quilt image (uploaded once)
  std::unique_ptr<VideoStream> video;   // or a quilt video
};

// Opens a playlist entry for the display of `calibration` (its aspect for quilts without one;
// its view count for RGB-D). How long it runs is the transport's rule (play/transport.hpp).
EntryContent open_entry(const PlaylistEntry& entry, const display::Calibration& calibration,
                        const media::DecoderOptions& decoder);

// The views an RGB-D frame of width x height becomes on this display: the display's view count
// (display::quilt_for_display), tiles as tall as the colour half up to kMaxRgbdTileHeight.
inline constexpr int kMaxRgbdTileHeight = 512;
render::QuiltLayout rgbd_layout_for_display(int width, int height, const rgbd::RgbdOptions& options,
                                            const display::Calibration& calibration);

}  // namespace lfd::play
