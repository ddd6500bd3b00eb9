// lfd demo: the main job end to end on the embedded defaults.
#include <iostream>

#include "apps/backend.hpp"
#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "pipeline/demo.hpp"

namespace lfd::apps {

int RunDemo(int argc, char** argv) {
  CLI::App app{"Run the main job on the bundled data: a simulated display unit, the bundled scene\n"
               "rendered with G2LF, interlaced, photographed from three positions, validated, and\n"
               "an HTML report.\n\nExamples:\n  lfd demo\n  lfd demo --out /tmp/demo --unit my.visual.json",
               "demo"};
  pipeline::DemoOptions options;
  std::string out = options.out_dir.string(), unit, scene;
  app.add_option("--out", out, "report folder")->capture_default_str();
  app.add_option("--unit", unit, "calibration of the simulated unit (default: bundled real unit)");
  app.add_option("--scene", scene, "Gaussian scene (default: data/scenes/playbot.sog, \"PLAYBOT\" by Stephane Agullo, CC-BY-4.0)");
  app.add_option("--warp", options.warp_amplitude_periods,
                 "lens-array warp of the simulated unit, lens periods")->capture_default_str();
  app.add_option("--capture-width", options.capture_width,
                 "width of the simulated photographs, pixels (smaller: faster, less accurate)")
      ->check(CLI::Range(320, 8192))->capture_default_str();
  app.add_option("--tile-width", options.tile_width, "quilt tile width, pixels")
      ->check(CLI::Range(16, 4096))->capture_default_str();
  app.add_option("--points", options.validation_points,
                 "panel points per validation profile")->check(CLI::Range(10, 100000))
      ->capture_default_str();
  std::string raster = "hardware";
  add_raster_option(app, raster);
  if (auto code = parse(app, argc, argv)) return *code;
  options.raster = gpu::parse_raster_path(raster);
  options.out_dir = out;
  options.unit_calibration = unit;
  options.scene = scene;
  std::cout << "lfd demo -> " << out << "\n";
  const auto index = pipeline::run_demo(options);
  std::cout << "report: " << index.string() << "\n";
  return 0;
}

}  // namespace lfd::apps
