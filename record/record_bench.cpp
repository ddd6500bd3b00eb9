#include "record/record_bench.hpp"

#include "record/frame_cameras.hpp"
#include "record/recorder.hpp"
#include "record/video_file.hpp"
#include "util/stopwatch.hpp"

namespace lfd::record {
namespace {

// One run of the frames: rendered, read back and converted; encoded too when `file` is given,
// its encoder flushed and the file closed inside the time (the recording's whole cost).
double frames_per_s(lightfield::LightFieldRenderer& renderer, const std::vector<FramePlan>& plans, VideoFile* file) {
  const Stopwatch stopwatch;
  for (const FramePlan& f : plans) {
    renderer.render_quilt(f.plan.geometry, f.plan.layout);
    const Image8 quilt8 = to_uint8(renderer.read_quilt());
    if (file) file->add(quilt8);
  }
  if (file) file->finish();
  return double(plans.size()) / stopwatch.seconds();
}

}  // namespace

RecordBenchRow bench_record(lightfield::LightFieldRenderer& renderer, const scene::Scene& scene,
                            const lightfield::ViewRequest& request, const RecordBenchOptions& options) {
  renderer.set_scene(scene);
  RecordOptions timing;
  timing.frames = options.frames;
  timing.quilt_video = options.work_dir / "bench.mp4";
  // The plans are made before the clocks start: the runs time the renderer and the encoder.
  CameraMotion turntable;
  turntable.kind = PathKind::kTurntable;
  std::vector<FramePlan> plans;
  for (int frame = 0; frame < timing.frames; ++frame) plans.push_back(plan_frame(request, turntable, scene, frame, timing));
  const render::QuiltLayout& layout = plans.front().plan.layout;
  media::EncoderOptions video = options.video;
  video.frame_rate = timing.fps;
  std::vector<double> render_only, recorded;
  for (int run = 0; run <= options.runs; ++run) {  // run 0: the warm-up
    const double alone = frames_per_s(renderer, plans, nullptr);
    VideoFile file(timing.quilt_video, layout.width, layout.height, video);
    const double with_encoder = frames_per_s(renderer, plans, &file);
    if (run == 0) continue;
    render_only.push_back(alone);
    recorded.push_back(with_encoder);
  }
  RecordBenchRow row;
  row.device = renderer.device();
  row.width = layout.width;
  row.height = layout.height;
  row.render_fps = render_only;
  row.record_fps = recorded;
  return row;
}

}  // namespace lfd::record
