// lfd bench gl-vs-cpu: G2LF on the GPU against the CPU reference on large scenes
// (docs/gpu.md, "G2LF on the GPU").
#include <cstdio>
#include <string>
#include <vector>

#include "apps/backend.hpp"
#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/gl_vs_cpu_benchmark.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchGlVsCpu(int argc, char** argv) {
  CLI::App app{"PSNR of the GL G2LF quilt against the CPU reference's with the same options\n"
               "(N 64 mixed nearest u8, N 64 quantile bilinear P_s 2 u8, N 512 u8, N 64 f32), the\n"
               "GL stage times and both frame times, on a scene file and a generated tabletop.\n"
               "\nExample (docs/gpu.md's table):\n"
               "  lfd bench gl-vs-cpu --scene ../shared/data/scenes/guitar.compressed.ply",
               "gl-vs-cpu"};
  std::string json_path, scene_path;
  int scene_size = 128, generated = 1000000, generated_size = 256, views = 5;
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  app.add_option("--scene", scene_path, "a Gaussian scene file, framed automatically");
  app.add_option("--scene-size", scene_size, "its view width = height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  app.add_option("--generated", generated, "Gaussians of the generated tabletop (0: none)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000000));
  app.add_option("--generated-size", generated_size, "its view width = height in pixels")
      ->capture_default_str()
      ->check(CLI::Range(8, 4096));
  app.add_option("--views", views, "views in one row")->capture_default_str()->check(CLI::Range(1, 256));
  if (auto code = parse(app, argc, argv)) return *code;

  const auto context = open_backend(lightfield::BackendChoice::kGl, false);
  std::printf("backend: gl on %s\n", context->info().summary().c_str());
  std::vector<bench::GlVsCpuRow> rows;
  auto run = [&](const bench::GlVsCpuScene& scene) {
    for (const auto& r : bench::run_gl_vs_cpu(scene, views, context->info())) rows.push_back(r);
  };
  if (!scene_path.empty()) run(bench::gl_vs_cpu_scene_file(scene_path, scene_size));
  if (generated > 0) run(bench::gl_vs_cpu_tabletop(generated, generated_size));
  std::fputs(bench::gl_vs_cpu_table(rows).c_str(), stdout);
  if (!json_path.empty()) {
    auto j = bench::gl_vs_cpu_json(rows);
    j["renderer"] = context->info().summary();
    write_text_atomic(json_path, j.dump(2) + "\n");
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
