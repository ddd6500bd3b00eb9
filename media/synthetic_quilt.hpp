#pragma once
// Synthetic quilts for the tests and `lfd bench play` (docs/play.md "Test videos"), so no picture
// or video has to be stored: every view a different, smooth-edged pattern (a view-coloured
// gradient, a disc that moves with the view and the frame, the view's number as bars), which
// makes a wrong view, a flipped row or a stale frame show up in a comparison, and compresses
// like real content rather than noise.
#include <filesystem>
#include <string>

#include "media/video_encoder.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::media {

// One quilt picture (RGB, rows top-down, view 0 in the bottom-left tile) of layout.width x
// layout.height; `frame` moves the pattern (a video's frame index).
Image8 synthetic_quilt(const render::QuiltLayout& layout, int frame = 0);

// Writes `frames` synthetic quilt frames of `layout` as a video (codec, rate and quality in
// `options`; its width/height are taken from the layout).
void write_synthetic_quilt_video(const std::filesystem::path& path, const render::QuiltLayout& layout, int frames,
                                 EncoderOptions options);

}  // namespace lfd::media
