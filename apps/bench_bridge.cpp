// lfd bench bridge: how long libbridge_inproc's draw_interop_quilt_texture_gl holds its caller
// (bridge_inproc/bridge_bench.hpp, docs/bridge-inproc.md "Speed").
#include <filesystem>
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "bench/timing_stats.hpp"
#include "bridge_inproc/bridge_bench.hpp"
#include "bridge_inproc/bridge_registration.hpp"
#include "gpu/gl/gl_context.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchBridge(int argc, char** argv) {
  CLI::App app{"The time draw_interop_quilt_texture_gl of lfd's libbridge_inproc holds its caller (the copy of\n"
               "the caller's texture), and a whole frame (the call and the panel read back after it), for\n"
               "square 8x6 quilts: medians of --runs after --warmup, the caller a headless EGL context, the\n"
               "library loaded with dlopen as the vendor's clients load it.\n"
               "Examples:\n"
               "  lfd bench bridge --calibration tests/data/calibrations/LKG-PORT-portrait.visual.json\n"
               "  lfd bench bridge --calibration visual.json --sizes 4096 --runs 50 --json bridge.json",
               "bench bridge"};
  bridge::BridgeBenchOptions o;
  std::string calibration, library, json_path;
  app.add_option("--calibration", calibration, "the display's calibration")->required();
  app.add_option("--library", library, "libbridge_inproc.so (default: the one built with this program)");
  app.add_option("--sizes", o.quilt_sizes, "quilt sizes (square, pixels)")->capture_default_str();
  app.add_option("--warmup", o.warmup, "untimed calls first")->check(CLI::Range(0, 100))->capture_default_str();
  app.add_option("--runs", o.runs, "timed calls")->check(CLI::Range(1, 1000))->capture_default_str();
  app.add_flag("--on-screen", o.on_screen, "draw into the display's window (needs X) instead of offscreen");
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  o.calibration = calibration;
  o.library = library.empty()
                  ? bridge::default_library_dir(std::filesystem::read_symlink("/proc/self/exe")) / "libbridge_inproc.so"
                  : std::filesystem::path(library);
  const std::vector<bridge::BridgeBenchRow> rows = bridge::run_bridge_bench(o);
  std::string renderer;
  {
    gpu::HeadlessContext probe;
    renderer = probe.info().summary();
  }
  std::cout << fmt::format("{}\n{:>10} {:>16} {:>16} {:>10}\n", renderer, "quilt", "caller held ms", "frame ms", "runs");
  nlohmann::ordered_json j;
  j["renderer"] = renderer;
  j["rows"] = nlohmann::ordered_json::array();
  for (const auto& r : rows) {
    const bench::TimingStats hold = bench::summarize(r.hold_s), frame = bench::summarize(r.frame_s);
    std::cout << fmt::format("{:>10} {:>16.2f} {:>16.2f} {:>10}\n", fmt::format("{0}x{0}", r.quilt_size),
                             hold.median * 1e3, frame.median * 1e3, r.hold_s.size());
    j["rows"].push_back({{"quilt_size", r.quilt_size}, {"caller_held_s", hold.to_json()}, {"frame_s", frame.to_json()}});
  }
  if (!json_path.empty()) write_text_atomic(json_path, j.dump(2) + "\n");
  return 0;
}

}  // namespace lfd::apps
