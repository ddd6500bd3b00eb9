#pragma once
// The scene of each video frame when the scene moves (docs/record.md "Scenes that move"): a
// sequence's frames (scene/scene_sequence.hpp) at their own rate mapped onto the video's, each
// scene frame held (video faster) or skipped (video slower) to keep time; one frame loaded at a
// time, in order, so memory holds the first frame (the framing) and the current one.
#include <optional>

#include "scene/scene.hpp"
#include "scene/scene_sequence.hpp"

namespace lfd::record {

class SceneFrames {
 public:
  // `scene_fps` <= 0: one scene frame per video frame. Loads the first frame (InputError naming it).
  SceneFrames(scene::SceneSequence sequence, double scene_fps, int video_fps);

  int count() const { return int(sequence_.frames.size()); }
  const scene::Scene& first() const { return first_; }
  // The scene frame shown at video frame `frame`: floor(frame x scene_fps / video_fps), the last
  // one held after the sequence ends.
  int scene_frame_of(int frame) const;
  // The video frames that show every scene frame once at the rates.
  int video_frames() const;
  // The scene at video frame `frame` (read when it changes; InputError naming a bad frame file).
  const scene::Scene& at(int frame);

 private:
  scene::SceneSequence sequence_;
  double ratio_;  // scene frames per video frame
  scene::Scene first_;
  std::optional<scene::Scene> current_;
  int current_index_ = 0;
};

}  // namespace lfd::record
