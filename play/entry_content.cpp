#include "play/entry_content.hpp"

#include <algorithm>

#include "display/display_quilt.hpp"
#include "media/quilt_name.hpp"
#include "rgbd/rgbd_view_model.hpp"
#include "util/error.hpp"

namespace lfd::play {

render::QuiltLayout rgbd_layout_for_display(int width, int height, const rgbd::RgbdOptions& options,
                                            const display::Calibration& calibration) {
  const bool stacked = options.depth_loc == rgbd::DepthLocation::top || options.depth_loc == rgbd::DepthLocation::bottom;
  const int colour_height = stacked ? height / 2 : height;
  return rgbd::rgbd_quilt_layout(width, height, options.depth_loc, display::quilt_for_display(calibration).views,
                                 std::clamp(colour_height, 1, kMaxRgbdTileHeight));
}

EntryContent open_entry(const PlaylistEntry& entry, const display::Calibration& calibration,
                        const media::DecoderOptions& decoder) {
  EntryContent content;
  content.name = entry.path.filename().string();
  content.rgbd = entry.rgbd;
  if (content.rgbd) content.rgbd->check(entry.path.string());
  // The display's view aspect (display::quilt_for_display, the one rule): a quilt that names no
  // aspect is read at it, and the interlacer letterboxes one that names another.
  const double display_aspect = display::quilt_for_display(calibration).view_aspect;
  auto layout_of = [&](int width, int height) {
    if (!content.rgbd) return media::quilt_layout_for(entry.path.string(), width, height, entry.quilt, display_aspect);
    try {
      return rgbd_layout_for_display(width, height, *content.rgbd, calibration);
    } catch (const InputError& e) {
      throw_input_error("{}: {}", entry.path.string(), e.what());
    }
  };
  if (media::is_image_file(entry.path)) {
    if (content.rgbd) {
      content.still = media::decode_image(media::read_file_bytes(entry.path), entry.path.string());
    } else {
      media::QuiltImage image = media::read_quilt_image(entry.path, entry.quilt, display_aspect);
      content.still = std::move(image.pixels);
    }
    content.layout = layout_of(content.still->width, content.still->height);
    return content;
  }
  content.video = std::make_unique<VideoStream>(entry.path, decoder);
  const media::VideoInfo& info = content.video->info();
  content.layout = layout_of(info.width, info.height);
  return content;
}

}  // namespace lfd::play
