#include "play/entry_content.hpp"

#include "media/quilt_name.hpp"

namespace lfd::play {

EntryContent open_entry(const PlaylistEntry& entry, double display_aspect, double default_duration_s,
                        const media::DecoderOptions& decoder) {
  EntryContent content;
  content.name = entry.path.filename().string();
  if (media::is_image_file(entry.path)) {
    media::QuiltImage image = media::read_quilt_image(entry.path, entry.quilt, display_aspect);
    content.layout = image.layout;
    content.still = std::move(image.pixels);
    content.duration_s = entry.duration_s.value_or(default_duration_s);
    return content;
  }
  content.video = std::make_unique<VideoStream>(entry.path, decoder);
  const media::VideoInfo& info = content.video->info();
  content.layout = media::quilt_layout_for(entry.path.string(), info.width, info.height, entry.quilt, display_aspect);
  content.duration_s = entry.duration_s.value_or(0.0);
  return content;
}

}  // namespace lfd::play
