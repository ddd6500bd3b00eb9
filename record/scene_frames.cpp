#include "record/scene_frames.hpp"

#include <algorithm>
#include <cmath>

namespace lfd::record {

SceneFrames::SceneFrames(scene::SceneSequence sequence, double scene_fps, int video_fps)
    : sequence_(std::move(sequence)),
      ratio_(scene_fps > 0.0 ? scene_fps / video_fps : 1.0),
      first_(scene::load_scene(sequence_.frames.front())) {}

int SceneFrames::scene_frame_of(int frame) const {
  return std::min(int(std::floor(frame * ratio_ + 1e-9)), count() - 1);
}

int SceneFrames::video_frames() const { return std::max(1, int(std::ceil(count() / ratio_ - 1e-9))); }

const scene::Scene& SceneFrames::at(int frame) {
  const int index = scene_frame_of(frame);
  if (index == 0) return first_;
  if (!current_ || current_index_ != index) {
    current_.reset();  // one frame beside the first in memory
    current_.emplace(scene::load_scene(sequence_.frames[size_t(index)]));
    current_index_ = index;
  }
  return *current_;
}

}  // namespace lfd::record
