#pragma once
// `lfd record`'s loop (docs/record.md): for each frame, the camera of the motion
// (record/frame_cameras.hpp), the views the one view plan makes of it (lightfield/view_plan.hpp),
// the quilt the renderer makes of them (any method, CPU or GL), optionally interlaced for the
// display, encoded into the video (record/video_file.hpp). A stop request ends it after the frame
// it is on with a playable video of the frames done.
#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>

#include "display/calibration_file.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/light_field_renderer.hpp"
#include "lightfield/view_plan.hpp"
#include "media/video_encoder.hpp"
#include "record/frame_cameras.hpp"
#include "scene/scene.hpp"

namespace lfd::record {

struct RecordOptions {
  int fps = 30;
  int frames = 0;            // frames of the whole recording (its timing: the turn, the path's times)
  int first = 0, last = -1;  // the frames this run renders, inclusive (a segment); last -1: to the end
  media::EncoderOptions video;         // codec and quality (size and rate are set here)
  std::filesystem::path quilt_video;   // the quilt video's final name; empty: none
  std::filesystem::path panel_video;   // the interlaced panel's video (needs the display); empty: none
  std::filesystem::path cameras_dir;   // each frame's cam.json (frame_NNNNN.json); empty: none
  interlace::InterlaceOptions panel;   // --blend, --overscan
  // InputError naming the field: fps in 1..240, frames >= 1, 0 <= first <= last < frames, an output.
  void check() const;
};

struct RecordResult {
  int frames_done = 0;
  bool stopped = false;  // a stop request came before the last frame
  double seconds = 0.0;
  std::vector<std::filesystem::path> written;
};

// The scene of each frame (a sequence's frame, or the one scene throughout); called once per
// frame, in order. The renderer gets a new scene only when the pointer changes.
using SceneOfFrame = std::function<const scene::Scene&(int frame)>;

// The plan of frame `frame`: `request` (the display, views, size, grid, focal distance; its
// camera ignored) with the motion's camera, and that camera with the views' size (what
// `lfd render --camera` of it renders again).
struct FramePlan {
  render::CameraSpec camera;
  lightfield::ViewPlan plan;
};
FramePlan plan_frame(const lightfield::ViewRequest& request, const CameraMotion& motion, const scene::Scene& scene,
                     int frame, const RecordOptions& options);

// Records frames options.first..last. `framing` frames the scene for the motion (a sequence's
// first frame: the framing stays put while the scene moves). `display` is needed for the panel
// video. `progress`
// (nullable) is called after each frame with the frames done. Errors propagate with no video
// left under its final name; a stop (`stop` raised) keeps the frames done.
RecordResult record_video(const lightfield::ViewRequest& request, const CameraMotion& motion,
                          const scene::Scene& framing, const SceneOfFrame& scene_of_frame, lightfield::LightFieldRenderer& renderer,
                          const display::Calibration* display, const RecordOptions& options,
                          const std::atomic<bool>* stop = nullptr,
                          const std::function<void(int)>& progress = {});

}  // namespace lfd::record
