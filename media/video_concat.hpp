#pragma once
// Segments of one recording joined into one video without re-encoding (docs/record.md
// "Splitting a long render"): the packets of each segment copied in order with their times
// shifted by the frames before, as FFmpeg's concat demuxer with `-c copy` does. The segments must
// share the codec, size, pixel format and time base (`lfd record --frames A-B` writes them so);
// each starts with a keyframe, as every encoded video does.
#include <filesystem>
#include <vector>

namespace lfd::media {

// Writes `output` (its container from the extension) atomically: InputError naming the segment
// and what differs (or that it is not a video), and nothing under `output`. Returns the frames.
long concat_videos(const std::vector<std::filesystem::path>& segments, const std::filesystem::path& output);

}  // namespace lfd::media
