// lfd bench record: frames/s of a recording (render + encode) against rendering alone, on the CPU
// and on GL in one run (record/record_bench.hpp, docs/record.md "Speed").
#include <cstdio>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/timing_stats.hpp"
#include "lightfield/backend_choice.hpp"
#include "lightfield/gl_device.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "record/record_bench.hpp"
#include "render/default_camera.hpp"
#include "scene/scene.hpp"
#include "util/atomic_file.hpp"
#include "util/data_dir.hpp"

namespace lfd::apps {
namespace {

// A row's runs summarised: medians and spread, and the encoder's share of a recorded frame
// (1 - record / render, of the medians).
struct Summary {
  std::string renderer;  // "G2LF on the CPU"
  bench::TimingStats render, record;
  double encoder_share = 0.0;
};

Summary summarize(const record::RecordBenchRow& r, const std::string& renderer) {
  Summary s{renderer, bench::summarize(r.render_fps), bench::summarize(r.record_fps)};
  if (s.render.median > 0) s.encoder_share = 1.0 - s.record.median / s.render.median;
  return s;
}

nlohmann::ordered_json row_json(const record::RecordBenchRow& r, const Summary& s) {
  nlohmann::ordered_json j;
  j["renderer"] = s.renderer;
  j["device"] = r.device;
  j["quilt_width"] = r.width;
  j["quilt_height"] = r.height;
  j["render_frames_per_s"] = s.render.to_json();
  j["record_frames_per_s"] = s.record.to_json();
  j["encoder_share"] = s.encoder_share;
  return j;
}

}  // namespace

int RunBenchRecord(int argc, char** argv) {
  CLI::App app{"Recording speed: a turntable's quilts rendered, read back and converted alone, and the same\n"
               "frames also encoded into a video (lfd record's loop), on the CPU and on GL (skipped with a\n"
               "notice without a GL context): frames/s of each (medians of --runs after a warm-up run; the\n"
               "spread is the MAD) and the encoder's share of a recorded frame.\n"
               "Example:\n"
               "  lfd bench record --scene data/scenes/demo.ply --size 256x256 --views 16 --json record.json",
               "bench record"};
  std::string scene_path = (data_dir() / "scenes" / "demo.ply").string(), json_path, codec = "h264";
  std::vector<std::string> backends{"cpu", "gl"};
  int size = 256, views = 16, quality = 18;
  record::RecordBenchOptions o;
  app.add_option("--scene", scene_path, "the scene")->capture_default_str();
  app.add_option("--size", size, "square views of this many pixels")->check(CLI::Range(16, 4096))->capture_default_str();
  app.add_option("--views", views, "views per quilt")->check(CLI::Range(1, 256))->capture_default_str();
  app.add_option("--backend", backends, "cpu, gl or both")->check(CLI::IsMember({"cpu", "gl"}))->capture_default_str();
  app.add_option("--frames", o.frames, "frames per run")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_option("--runs", o.runs, "timed runs after one warm-up")->check(CLI::Range(1, 50))->capture_default_str();
  app.add_option("--codec", codec, "h264 or hevc")->check(CLI::IsMember({"h264", "hevc"}))->capture_default_str();
  app.add_option("--quality", quality, "x264/x265 CRF")->check(CLI::Range(0, 51))->capture_default_str();
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  o.video.codec = codec == "hevc" ? "libx265" : "libx264";
  o.video.crf = quality;

  const scene::Scene scene = scene::load_scene(scene_path);
  lightfield::ViewRequest request;
  request.size = display::ViewSize{size, size};
  request.views = views;
  std::vector<record::RecordBenchRow> rows;
  std::vector<Summary> summaries;
  for (const std::string& backend : backends) {
    // gl where a context can be made; without one the row is skipped, not an error.
    const auto device = lightfield::GlDevice::adopt(lightfield::open_backend_context(
        backend == "gl" ? lightfield::BackendChoice::kAuto : lightfield::BackendChoice::kCpu,
        [](const std::string& reason) { std::cerr << "notice: GL skipped: " << reason << "\n"; }));
    if (backend == "gl" && !device) continue;
    lightfield::RendererOptions options;
    options.backend = lightfield::backend_for(device);
    const auto renderer = lightfield::make_renderer(options, scene.kind(), device);
    rows.push_back(record::bench_record(*renderer, scene, request, o));
    summaries.push_back(summarize(rows.back(), lightfield::method_name(options.method, scene.kind()) + " on the " +
                                                   lightfield::processor_name(options.backend)));
  }
  std::cout << fmt::format("{} ({} {}), {} views of {}x{}, {} frames per run, {} runs after a warm-up, {} CRF {}\n",
                           scene_path, scene.size(), scene.primitives(), views, size, size, o.frames, o.runs, codec,
                           quality);
  std::cout << fmt::format("{:<18} {:>11} {:>18} {:>18} {:>14}\n", "renderer", "quilt", "render frames/s",
                           "record frames/s", "encoder share");
  for (size_t i = 0; i < rows.size(); ++i) {
    const Summary& s = summaries[i];
    std::cout << fmt::format("{:<18} {:>5}x{:<5} {:>9.2f} +-{:<6.2f} {:>9.2f} +-{:<6.2f} {:>13.0f}%\n", s.renderer,
                             rows[i].width, rows[i].height, s.render.median, s.render.mad, s.record.median,
                             s.record.mad, 100.0 * s.encoder_share);
  }
  for (size_t i = 0; i < rows.size(); ++i) std::cout << summaries[i].renderer << ": " << rows[i].device << "\n";
  if (!json_path.empty()) {
    nlohmann::ordered_json result;
    result["benchmark"] = "record";
    result["scene"] = scene_path;
    result["views"] = views;
    result["view_size"] = size;
    result["frames_per_run"] = o.frames;
    result["runs"] = o.runs;
    result["warmup_runs"] = 1;
    result["codec"] = codec;
    result["quality_crf"] = quality;
    result["rows"] = nlohmann::ordered_json::array();
    for (size_t i = 0; i < rows.size(); ++i) result["rows"].push_back(row_json(rows[i], summaries[i]));
    write_text_atomic(json_path, result.dump(2) + "\n");
    std::printf("\nwrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
