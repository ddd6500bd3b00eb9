// `lfd bench gpu-probe`: what the GPU offers each raster path (gpu/probes/gl_throughput_probe.hpp) and
// the probe --raster auto decides by (gpu/probes/gl_raster_probe.hpp), in one run.
//   lfd bench gpu-probe --json probe.json
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "apps/backend.hpp"
#include "apps/bench.hpp"
#include "apps/cli.hpp"
#include "gpu/probes/gl_raster_probe.hpp"
#include "gpu/probes/gl_throughput_probe.hpp"
#include "util/atomic_file.hpp"

namespace lfd::apps {

int RunBenchGpuProbe(int argc, char** argv) {
  CLI::App app{"The GPU's compute arithmetic rate (GFLOP/s of fused multiply-adds) and memory bandwidth (a\n"
               "copy dispatch, bytes read + written), the raster pipeline's blended fill rate (full-target\n"
               "triangles into RGBA16F), and --raster auto's probes (one per-view quilt of Gaussians and one of\n"
               "voxels, each both ways) with their choices. Medians of --runs after --warmup, wall clock around glFinish.\n"
               "\nExample (docs/gpu.md \"Choosing the path: auto\"):\n"
               "  lfd bench gpu-probe --json probe.json\n"
               "  lfd bench gpu-probe --quick          (llvmpipe: smaller dispatches)",
               "gpu-probe"};
  gpu::ThroughputProbeOptions o;
  std::string json_path;
  bool quick = false;
  app.add_option("--runs", o.runs, "timed runs per figure")->capture_default_str()->check(CLI::Range(1, 1000));
  app.add_option("--warmup", o.warmup, "untimed runs before them")->capture_default_str()->check(CLI::Range(0, 100));
  app.add_flag("--quick", quick, "a CPU-sized probe (llvmpipe): 1/16 of the work");
  app.add_option("--json", json_path, "write the figures as JSON to this file");
  if (auto code = parse(app, argc, argv)) return *code;
  if (quick) {
    o.invocations /= 16;
    o.copy_bytes /= 16;
    o.fill_layers /= 16;
  }
  const auto context = open_backend(lightfield::BackendChoice::kGl, false);
  const std::string device = context->info().summary();
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  std::printf("gpu-probe on %s, medians of %d runs after %d warm-up\n\n", device.c_str(), o.runs, o.warmup);
  const gpu::ThroughputProbe p = gpu::probe_throughput(o);
  std::printf("| figure | value | one run |\n|---|---|---|\n");
  std::printf("| compute FMA rate | %.1f GFLOP/s | %.2f ms |\n", p.fma_gflops, 1e3 * p.fma_s);
  std::printf("| compute memory bandwidth (copy) | %.1f GB/s | %.2f ms |\n", p.bandwidth_gbs, 1e3 * p.copy_s);
  std::printf("| raster fill, blended RGBA16F | %.2f Gpixel/s | %.2f ms |\n", p.fill_gpixels, 1e3 * p.fill_s);
  const gpu::RasterProbe r = gpu::probe_raster_paths(gpu::RasterSubject::kGaussians);
  const gpu::RasterProbe v = gpu::probe_raster_paths(gpu::RasterSubject::kVoxels);
  for (const gpu::RasterProbe* probe : {&r, &v}) {
    const char* what = gpu::raster_subject_name(probe->subject);
    std::printf("| probe quilt of %s, --raster hardware | %.2f ms | |\n", what, 1e3 * probe->hardware_s);
    std::printf("| probe quilt of %s, --raster compute | %.2f ms | |\n", what, 1e3 * probe->compute_s);
  }
  std::printf("\n");
  for (const gpu::RasterProbe* probe : {&r, &v})
    std::printf("--raster auto picks %s for %s here (%.2fx)\n", gpu::raster_path_name(probe->faster),
                gpu::raster_subject_name(probe->subject),
                probe->faster == gpu::RasterPath::kCompute ? probe->hardware_s / probe->compute_s
                                                           : probe->compute_s / probe->hardware_s);
  if (!json_path.empty()) {
    const nlohmann::ordered_json j = {
        {"device", device},
        {"runs", o.runs},
        {"warmup", o.warmup},
        {"fma_gflops", p.fma_gflops},
        {"bandwidth_gbs", p.bandwidth_gbs},
        {"fill_gpixels", p.fill_gpixels},
        {"probe_quilt_hardware_s", r.hardware_s},
        {"probe_quilt_compute_s", r.compute_s},
        {"auto", gpu::raster_path_name(r.faster)},
        {"probe_voxel_quilt_hardware_s", v.hardware_s},
        {"probe_voxel_quilt_compute_s", v.compute_s},
        {"auto_voxels", gpu::raster_path_name(v.faster)}};
    write_text_atomic(json_path, j.dump(2) + "\n");
    std::printf("wrote %s\n", json_path.c_str());
  }
  return 0;
}

}  // namespace lfd::apps
