#include "record/recorder.hpp"

#include <memory>

#include <fmt/format.h>

#include "display/lens_model.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "record/video_file.hpp"
#include "render/camera_json.hpp"
#include "util/atomic_file.hpp"
#include "util/error.hpp"
#include "util/stopwatch.hpp"

namespace lfd::record {

void RecordOptions::check() const {
  if (fps < 1 || fps > 240) throw_input_error("fps: {} is outside 1..240", fps);
  if (frames < 1) throw_input_error("frames: {} must be at least 1", frames);
  const int end = last < 0 ? frames - 1 : last;
  if (first < 0 || first > end || end >= frames)
    throw_input_error("frames: {}-{} is not a range within 0..{}", first, end, frames - 1);
  if (quilt_video.empty() && panel_video.empty()) throw_input_error("out: no video to write");
}

FramePlan plan_frame(const lightfield::ViewRequest& request, const CameraMotion& motion, const scene::Scene& scene,
                     int frame, const RecordOptions& options) {
  // The views' aspect frames the scene as `lfd render` frames it without a camera.
  lightfield::ViewRequest framing = request;
  framing.camera.reset();
  const render::Camera& base = lightfield::plan_views(framing, &scene).geometry.base;
  FramePlan f;
  f.camera = frame_camera(motion, scene, frame, options.frames, options.fps, float(base.width) / float(base.height));
  lightfield::ViewRequest r = request;
  r.camera = f.camera;
  f.plan = lightfield::plan_views(r, &scene);
  f.camera.width = f.plan.geometry.base.width;
  f.camera.height = f.plan.geometry.base.height;
  return f;
}

RecordResult record_video(const lightfield::ViewRequest& request, const CameraMotion& motion,
                          const scene::Scene& framing, const SceneOfFrame& scene_of_frame, lightfield::LightFieldRenderer& renderer,
                          const display::Calibration* display, const RecordOptions& options,
                          const std::atomic<bool>* stop, const std::function<void(int)>& progress) {
  options.check();
  if (!options.panel_video.empty() && !display) throw_input_error("panel: needs the display");
  const Stopwatch stopwatch;
  const int last = options.last < 0 ? options.frames - 1 : options.last;
  media::EncoderOptions video = options.video;
  video.frame_rate = options.fps;

  std::unique_ptr<display::LensModel> lens;
  if (display) lens = std::make_unique<display::LensModel>(display->display, display->correction);
  std::unique_ptr<VideoFile> quilt_file, panel_file;
  std::optional<render::QuiltLayout> first_layout;
  const scene::Scene* current = nullptr;
  RecordResult result;
  for (int frame = options.first; frame <= last; ++frame) {
    if (stop && stop->load()) {
      result.stopped = true;
      break;
    }
    const scene::Scene& scene = scene_of_frame(frame);
    if (&scene != current) {
      renderer.set_scene(scene);
      current = &scene;
    }
    const FramePlan f = plan_frame(request, motion, framing, frame, options);
    const render::QuiltLayout& layout = f.plan.layout;
    if (!first_layout) {
      first_layout = layout;
      // The files open before the first frame renders: an unwritable output fails at once.
      // An odd side is padded by a row or column the tiles never read (floor(W / C) stays), which
      // a single row or column of tiles would read.
      if ((layout.width % 2 && layout.cols == 1) || (layout.height % 2 && layout.rows == 1))
        throw_input_error("size: a {}x{} quilt of {}x{} tiles has an odd side a codec cannot take; give the views an "
                          "even size",
                          layout.width, layout.height, layout.cols, layout.rows);
      if (!options.quilt_video.empty())
        quilt_file = std::make_unique<VideoFile>(options.quilt_video, layout.width, layout.height, video);
      if (!options.panel_video.empty())
        panel_file = std::make_unique<VideoFile>(options.panel_video, display->display.screen_w,
                                                 display->display.screen_h, video);
    } else if (layout.width != first_layout->width || layout.height != first_layout->height) {
      throw_input_error("frame {}: its quilt is {}x{}, the video's {}x{} (keyframes of different sizes?)", frame,
                        layout.width, layout.height, first_layout->width, first_layout->height);
    }
    if (!options.cameras_dir.empty())
      write_text_atomic(options.cameras_dir / fmt::format("frame_{:05d}.json", frame), render::camera_json_text(f.camera));
    renderer.render_quilt(f.plan.geometry, layout);
    const Image8 quilt8 = to_uint8(renderer.read_quilt());
    if (quilt_file) quilt_file->add(quilt8);
    // The panel as `lfd interlace` makes it of the 8-bit quilt; on the GPU when the quilt was
    // rendered there.
    if (panel_file)
      panel_file->add(to_uint8(
          lightfield::interlace_panel(to_float(quilt8), layout, *lens, options.panel, renderer.options().backend)));
    ++result.frames_done;
    if (progress) progress(result.frames_done);
  }
  if (quilt_file) result.written.push_back(quilt_file->finish());
  if (panel_file) result.written.push_back(panel_file->finish());
  result.seconds = stopwatch.seconds();
  return result;
}

}  // namespace lfd::record
