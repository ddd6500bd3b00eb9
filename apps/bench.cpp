// lfd bench: a table of benchmarks (speed lives here, never in tests: docs/performance.md).
#include <cstdio>
#include <cstring>
#include <iostream>
#include <string_view>
#include <vector>

#include "apps/bench.hpp"
#include "apps/commands.hpp"

namespace lfd::apps {

namespace {

struct Bench {
  const char* name;
  int (*run)(int, char**);
  const char* summary;
};

const std::vector<Bench>& benches() {
  static const std::vector<Bench> table = {
      {"render", RunBenchRender, "per-view quilts vs G2LF: the paper's Table 1 (--backend cpu)"},
      {"voxels", RunBenchVoxels, "per-view voxel quilts vs V2LF: the paper's Table 1, V2LF half (CPU)"},
      {"gl-vs-cpu", RunBenchGlVsCpu, "GL G2LF against the CPU reference on large scenes (PSNR, times)"},
      {"gpu-frame", RunBenchGpuFrame, "the GL frame: timers waited for vs read late, swizzle variants"},
      {"gpu-probe", RunBenchGpuProbe, "compute FMA rate and bandwidth vs raster fill rate; which --raster auto picks"},
#ifndef LFD_NO_PLAYBACK  // a renderer-only build without FFmpeg (-DLFD_WITH_PLAYBACK=OFF)
      {"play", RunBenchPlay, "quilt video playback: decoded, shown and dropped frames per second (4K)"},
      {"record", RunBenchRecord, "lfd record: frames/s of render + encode against render alone, CPU and GL"},
      {"serve", RunBenchServe, "load test of a running lfd serve: many clients at once (docs/serve.md)"},
#endif
      {"bridge", RunBenchBridge, "libbridge_inproc: how long a quilt draw holds its caller (llvmpipe or GPU)"},
      {"direct", RunBenchDirect, "the direct panel pass against swizzle + interlace (times, memory, PSNR)"},
#ifndef LFD_RENDER_ONLY  // the renderer-only build has no OpenCV or Ceres
      {"simulate", RunBenchSimulate, "1920x1080 synthetic capture of a 3840x2160 panel"},
      {"calibration", RunBenchCalibration, "calibration errors and times on synthetic units"},
      {"camera-poses", RunBenchCameraPoses, "camera calibration: focal-length error against board poses"},
      {"direct-photos", RunBenchDirectPhotos, "photographs between two quilt views: direct vs quilt path (PSNR)"},
#endif
  };
  return table;
}

void print_usage() {
  std::cout << "Usage: lfd bench <name> [--json FILE] [options]\n\nBenchmarks:\n";
  for (const auto& b : benches()) std::printf("  %-12s %s\n", b.name, b.summary);
  std::cout << "\nRun 'lfd bench <name> --help' for its options.\n";
}

}  // namespace

int RunBench(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    print_usage();
    return argc < 2 ? 2 : 0;
  }
  const std::string_view name = argv[1];
  for (const auto& b : benches())
    if (name == b.name) return b.run(argc - 1, argv + 1);
  std::cerr << "lfd bench: unknown benchmark '" << name << "' (see lfd bench --help)\n";
  return 2;
}

}  // namespace lfd::apps
