// `lfd record`: a quilt video of a scene along a camera path (docs/record.md).
//   lfd record --scene s.ply --calibration visual.json --path turntable --seconds 6 --out s.mp4
//   lfd record --scene s.ply --path path.json --save-cameras cams/ --out s.mp4
//   lfd record --scene s.ply --path turntable --frames 0-99 --out s.mp4      (one segment)
//   lfd record --concat s_qs5x9a1_f0000-0099.mp4 s_qs5x9a1_f0100-0179.mp4 --out s.mp4
//   lfd record --scene monkey_%04d.sog --scene-fps 24 --fps 24 --out monkey.mp4  (a moving scene)
#include <filesystem>
#include <iostream>
#include <optional>

#include <fmt/format.h>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "apps/render_flags.hpp"
#include "interlace/quilt_file_name.hpp"
#include "lightfield/render_settings.hpp"
#include "lightfield/renderer_factory.hpp"
#include "media/quilt_name.hpp"
#include "media/video_concat.hpp"
#include "record/frame_cameras.hpp"
#include "record/interrupt.hpp"
#include "record/recorder.hpp"
#include "record/scene_frames.hpp"
#include "render/camera_json.hpp"
#include "render/quilt_layout.hpp"
#include "scene/scene.hpp"
#include "scene/scene_sequence.hpp"
#include "util/error.hpp"
#include "util/progress.hpp"

namespace lfd::apps {
namespace {

namespace fs = std::filesystem;

// `lfd record`'s own flags (beside render's).
struct RecordFlags {
  std::string path, frames_text, codec = "h264", save_cameras;
  std::optional<double> seconds, scene_fps;
  std::optional<int> fps;
  int quality = 18;
};

void add_record_options(CLI::App& app, RecordFlags& r, RenderFlags& f) {
  app.add_option("--path", r.path,
                 "the camera's motion: turntable (one turn about the framed focal point), orbit:DEG (a swing of "
                 "DEG degrees that loops), or a camera path file (lfd keyframes or nerfstudio's camera_path.json)")
      ->excludes(f.camera_option);
  app.add_option("--frames", r.frames_text,
                 "frames of the recording, N; or A-B to render only frames A..B of it into a segment "
                 "(default: the path's duration, else --seconds, else 4 s)");
  app.add_option("--seconds", r.seconds, "length of the recording (frames = seconds x fps)")->check(CLI::Range(0.01, 36000.0));
  app.add_option("--fps", r.fps, "frame rate (default 30, or a nerfstudio path's)")->check(CLI::Range(1, 240));
  app.add_option("--scene-fps", r.scene_fps,
                 "a moving scene (--scene name_%04d.ply, a folder or a .txt list of frames): its frames per second "
                 "(default: one scene frame per video frame)")
      ->check(CLI::Range(0.001, 1000.0));
  app.add_option("--codec", r.codec, "h264 (what Bridge and browsers play) or hevc")
      ->check(CLI::IsMember({"h264", "hevc"}))->capture_default_str();
  app.add_option("--quality", r.quality, "constant rate factor: lower is better and larger (x264/x265 CRF)")
      ->check(CLI::Range(0, 51))->capture_default_str();
  app.add_option("--save-cameras", r.save_cameras, "write each frame's cam.json into this folder (frame_NNNNN.json)");
  app.add_option("--out", f.out, "the quilt video, NAME.mp4: written as NAME_qsCxRaA.mp4 (segments: _fA-B added)");
}

// N, or A-B (a segment of the recording).
struct FrameChoice {
  std::optional<int> count;
  std::optional<std::pair<int, int>> range;
};

FrameChoice parse_frames(const std::string& text) {
  FrameChoice c;
  if (text.empty()) return c;
  const size_t dash = text.find('-');
  const auto number = [&](const std::string& s) {
    size_t used = 0;
    int v = -1;
    try {
      v = std::stoi(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != s.size() || v < 0) throw_input_error("--frames: '{}' is not N or A-B (frame numbers)", text);
    return v;
  };
  if (dash == std::string::npos) {
    c.count = number(text);
    if (*c.count < 1) throw_input_error("--frames: {} must be at least 1", *c.count);
  } else {
    c.range = std::make_pair(number(text.substr(0, dash)), number(text.substr(dash + 1)));
  }
  return c;
}

// --fps, else a nerfstudio path's own rate, else 30.
int choose_fps(const RecordFlags& r, const record::CameraMotion& motion) {
  const bool path_rate = motion.kind == record::PathKind::kKeyframes && motion.keyframes.frame_rate > 0;
  return r.fps.value_or(path_rate ? int(std::lround(motion.keyframes.frame_rate)) : 30);
}

// The frames of the whole recording and the part this run renders; `sequence_frames`: the video
// frames a moving scene needs to show every frame once (0 for a still scene).
void choose_frames(const RecordFlags& r, const record::CameraMotion& motion, int sequence_frames,
                   record::RecordOptions& o) {
  const FrameChoice c = parse_frames(r.frames_text);
  if (c.count && r.seconds) throw_input_error("--frames, --seconds: give one of them");
  o.frames = c.count ? *c.count
             : r.seconds ? std::max(1, int(std::lround(*r.seconds * o.fps)))
             : sequence_frames > 0 && motion.kind == record::PathKind::kStill ? sequence_frames
                                                                             : record::default_frame_count(motion, o.fps);
  if (c.range) {
    o.first = c.range->first;
    o.last = c.range->second;
    if (o.first > o.last || o.last >= o.frames)
      throw_input_error("--frames: {}-{} is not a range within the recording's frames 0..{}", o.first, o.last,
                        o.frames - 1);
  }
}

// NAME_qsCxRaA.mp4, with _fA-B before the extension for a segment.
fs::path video_name(const RecordFlags& r, const std::string& out, const render::QuiltLayout& layout,
                    const record::RecordOptions& o) {
  fs::path p(out);
  if (p.extension() != ".mp4") throw_input_error("--out: '{}' must end in .mp4", out);
  p = interlace::quilt_file_name(out, layout);
  if (!r.frames_text.empty() && r.frames_text.find('-') != std::string::npos)
    p.replace_filename(fmt::format("{}_f{:04d}-{:04d}{}", p.stem().string(), o.first, o.last, p.extension().string()));
  return p;
}

// lfd record --concat SEGMENT... --out NAME.mp4: the segments joined without re-encoding.
int run_concat(int argc, char** argv) {
  CLI::App app{"Join segments of one recording (lfd record --frames A-B) without re-encoding.\n"
               "Example:\n"
               "  lfd record --concat s_qs5x9a1_f0000-0099.mp4 s_qs5x9a1_f0100-0179.mp4 --out s.mp4",
               "record --concat"};
  std::vector<std::string> segments;
  std::string out;
  app.add_option("--concat", segments, "the segments, in order")->required();
  app.add_option("--out", out, "the joined video (.mp4; the segments' _qsCxRaA is added when it has none)")->required();
  if (auto code = parse(app, argc, argv)) return *code;
  fs::path target(out);
  if (target.extension() != ".mp4") throw_input_error("--out: '{}' must end in .mp4", out);
  // The tiling travels with the name: the first segment's unless --out names one.
  const auto named = media::parse_quilt_name(fs::path(segments.front()).filename().string());
  if (!media::parse_quilt_name(target.filename().string()) && named)
    target.replace_filename(target.stem().string() + render::quilt_suffix(named->cols, named->rows, named->aspect) +
                            ".mp4");
  const std::vector<fs::path> paths(segments.begin(), segments.end());
  const long frames = media::concat_videos(paths, target);
  std::cout << fmt::format("wrote {} ({} frames from {} segments, not re-encoded)\n", target.string(), frames,
                           segments.size());
  return 0;
}

bool asks_concat(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--concat") return true;
  return false;
}

}  // namespace

int RunRecord(int argc, char** argv) {
  if (asks_concat(argc, argv)) return run_concat(argc, argv);
  CLI::App app{"Record a quilt video of a scene along a camera path: each frame's quilt rendered as lfd render\n"
               "renders it (every view, grid, size, method and backend option applies) and encoded with\n"
               "FFmpeg's libraries (H.264 yuv420p by default). Ctrl-C ends it with a playable video of the\n"
               "frames done.\n"
               "Examples:\n"
               "  lfd record --scene s.ply --calibration visual.json --path turntable --seconds 6 --out s.mp4\n"
               "  lfd record --scene s.ply --path orbit:30 --frames 90 --codec hevc --out s.mp4\n"
               "  lfd record --scene s.ply --path camera_path.json --save-cameras cams --out s.mp4\n"
               "  lfd record --scene s.ply --path turntable --seconds 60 --frames 0-449 --out s.mp4\n"
               "  lfd record --concat s_qs5x9a1_f0000-0449.mp4 s_qs5x9a1_f0450-0899.mp4 ... --out s.mp4\n"
               "  lfd record --scene monkey_%04d.sog --scene-fps 24 --fps 24 --out monkey.mp4",
               "record"};
  RenderFlags f;
  RecordFlags r;
  add_scene_and_plane_options(app, f);
  add_camera_and_display_options(app, f, "also (or, without --out, only) record the quilt interlaced for the display "
                                         "into this video (.mp4, the panel's size)");
  add_record_options(app, r, f);
  if (auto code = parse(app, argc, argv)) return *code;
  if (f.out.empty() && f.panel_path.empty()) throw_input_error("--out: required (or --panel for the panel's video)");
  if (!f.panel_path.empty() && fs::path(f.panel_path).extension() != ".mp4")
    throw_input_error("--panel: '{}' must end in .mp4", f.panel_path);
  check_output_flags(f, app);
  const DisplayChoice display = choose_display(f);
  const scene::SceneSequence sequence = scene::find_scene_sequence(f.scene_path);
  const bool moving = scene::is_scene_sequence(f.scene_path);
  if (r.scene_fps && !moving)
    throw_input_error("--scene-fps: {} is one scene; a moving one is a pattern (name_%04d.ply), a folder or a list",
                      f.scene_path);
  const scene::SceneKind kind = scene::scene_kind_of_file(sequence.frames.front());
  const RendererChoice choice = choose_renderer(f, kind);
  const record::CameraMotion motion = record::parse_camera_motion(r.path, f.s.camera);

  record::RecordOptions o;
  o.fps = choose_fps(r, motion);
  record::SceneFrames scenes(sequence, r.scene_fps.value_or(0.0), o.fps);
  choose_frames(r, motion, moving ? scenes.video_frames() : 0, o);
  o.video.codec = r.codec == "hevc" ? "libx265" : "libx264";
  o.video.crf = r.quality;
  o.cameras_dir = r.save_cameras;
  o.panel.blend = interlace::parse_view_blend(f.blend);
  o.panel.overscan = f.overscan;
  o.panel_video = f.panel_path;
  const scene::Scene& scene = scenes.first();  // the framing: the first frame's
  const lightfield::ViewRequest request =
      lightfield::view_request(f.s, display.calibration ? &*display.calibration : nullptr);
  // The first frame's plan names the video (and reports the grid's refusal by its flags).
  lightfield::ViewRequest first = request;
  first.camera = record::plan_frame(request, motion, scene, o.first, o).camera;
  const lightfield::ViewPlan plan = lightfield::plan_render_views(f.s, first, scene, kFlags);
  print_display(display, plan);
  if (!f.out.empty()) o.quilt_video = video_name(r, f.out, plan.layout, o);
  o.check();
  if (!o.cameras_dir.empty()) {
    std::error_code ec;
    fs::create_directories(o.cameras_dir, ec);
    if (ec) throw_input_error("--save-cameras: cannot create '{}' ({})", o.cameras_dir.string(), ec.message());
  }

  const auto renderer = lightfield::make_renderer(choice.options, kind, choice.device);
  const int count = (o.last < 0 ? o.frames - 1 : o.last) - o.first + 1;
  const record::StopRequest stop;
  Progress progress("record", count, "frames");
  const record::RecordResult result = record::record_video(
      request, motion, scene, [&](int frame) -> const scene::Scene& { return scenes.at(frame); }, *renderer,
      display.calibration ? &*display.calibration : nullptr, o, &record::StopRequest::flag(),
      [&](int) { progress.advance(); });
  progress.finish();
  for (const fs::path& written : result.written) {
    const bool panel = written == o.panel_video;
    std::cout << fmt::format(
        "wrote {} ({} frames at {} fps, {}, {} {} on the {}, {} views of {}x{}{}) in {:.1f} s, {:.2f} frames/s\n",
        written.string(), result.frames_done, o.fps, r.codec, panel ? "the panel of" : "quilts of",
        lightfield::method_name(choice.options.method, kind), lightfield::processor_name(choice.options.backend),
        plan.views, plan.geometry.base.width, plan.geometry.base.height,
        panel ? fmt::format(", interlaced for {}", display.path) : "", result.seconds,
        result.frames_done / std::max(result.seconds, 1e-9));
  }
  if (result.stopped) {
    std::cerr << fmt::format("interrupted: {} of {} frames recorded\n", result.frames_done, count);
    return 130;
  }
  return 0;
}

}  // namespace lfd::apps
