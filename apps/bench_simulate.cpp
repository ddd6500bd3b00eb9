// lfd bench simulate: time of one synthetic capture (1920x1080 camera, 3840x2160 panel).
#include <algorithm>
#include <ctime>
#include <cstdio>
#include <random>

#include <nlohmann/json.hpp>
#include <omp.h>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "display/calibration_file.hpp"
#include "sim/simulator.hpp"
#include "util/atomic_file.hpp"
#include "util/stopwatch.hpp"

namespace lfd::apps {

namespace {

// The real 16" Gen2 unit LKG-APW92011 (docs/display-model.md "The test vector"), so the benchmark
// needs no input files.
constexpr const char* kBenchDisplay =
    R"({"serial":"LKG-APW92011","pitch":{"value":50.0693473815918},
    "slope":{"value":-7.521984100341797},"center":{"value":0.07635253667831421},
    "viewCone":{"value":40.0},"invView":{"value":1.0},"DPI":{"value":283.0},
    "screenW":{"value":3840.0},"screenH":{"value":2160.0}})";

}  // namespace

int RunBenchSimulate(int argc, char** argv) {
  CLI::App app{"Time one synthetic capture: a 1920x1080 camera 0.6 m in front of a 3840x2160\n"
               "panel (LKG-APW92011 unless --calibration), every capture effect on.\n"
               "\nExample:\n  lfd bench simulate --json bench_simulate.json",
               "simulate"};
  std::string json_path, calibration_path;
  int repeat = 3;
  sim::CaptureEffects fx;
  fx.blur_px = 0.8;
  fx.noise_sigma = 0.01;
  fx.vignetting = 0.2;
  fx.gamma = 2.2;
  fx.glare_fraction = 0.002;
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  app.add_option("--calibration", calibration_path, "display (default: LKG-APW92011)");
  app.add_option("--repeat", repeat, "timed runs (the minimum is reported)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100));
  app.add_option("--supersample", fx.supersample, "samples per camera pixel per axis")
      ->capture_default_str();
  if (auto code = parse(app, argc, argv)) return *code;

  const display::Calibration cal = calibration_path.empty()
                                     ? display::parse_calibration(kBenchDisplay, "bench display")
                                     : display::read_calibration(calibration_path);
  const sim::DisplaySimulator sim{display::LensModel(cal.display, cal.correction)};
  // Random panel content: no cache-friendly shortcut for the simulator.
  ImageF panel(cal.display.screen_w, cal.display.screen_h, 3);
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> value(0.f, 1.f);
  for (float& p : panel.pixels) p = value(rng);
  const sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(40.0, 1920, 1080),
                                     sim::CameraPose{{0.03, 0.01, 0.6}, {0, 0, 0}, {0, 1, 0}});

  // Wall time is what a user waits; CPU time (all threads) tells the cost on a shared machine
  // where other jobs steal the cores.
  std::vector<double> seconds, cpu_seconds;
  for (int r = 0; r < repeat; ++r) {
    const Stopwatch stopwatch;
    const std::clock_t c0 = std::clock();
    const ImageF capture = sim.capture(panel, camera, fx);
    cpu_seconds.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
    seconds.push_back(
        stopwatch.seconds());
  }
  const double best = *std::min_element(seconds.begin(), seconds.end());
  const double best_cpu = *std::min_element(cpu_seconds.begin(), cpu_seconds.end());
  std::sort(seconds.begin(), seconds.end());
  const double median = seconds[seconds.size() / 2];
  const double samples = 1920.0 * 1080.0 * fx.supersample * fx.supersample;
  const int threads = omp_get_max_threads();

  std::printf("| benchmark | panel | capture | supersample | threads | min s | median s | cpu s | Msamples/s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| simulate | %dx%d | 1920x1080 | %d | %d | %.3f | %.3f | %.3f | %.1f |\n",
              cal.display.screen_w, cal.display.screen_h, fx.supersample, threads, best, median,
              best_cpu, samples / best * 1e-6);
  if (!json_path.empty()) {
    nlohmann::ordered_json j = {{"benchmark", "simulate"},
                                {"display", cal.display.serial},
                                {"panel", {cal.display.screen_w, cal.display.screen_h}},
                                {"capture", {1920, 1080}},
                                {"supersample", fx.supersample},
                                {"threads", threads},
                                {"repeat", repeat},
                                {"seconds_min", best},
                                {"seconds_median", median},
                                {"cpu_seconds_min", best_cpu},
                                {"samples_per_second", samples / best}};
    write_text_atomic(json_path, j.dump(2) + "\n");
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
