#include "bench/frame_timing.hpp"

#include <sys/resource.h>

#include <chrono>

namespace lfd::bench {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// User + system time of all threads: on a shared machine it tells the work done, which wall
// time does not when other jobs take the cores.
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

}  // namespace

FrameTimings time_frames(lightfield::LightFieldRenderer& renderer, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const FramePlan& plan) {
  FrameTimings m;
  renderer.reset_peak_memory();
  for (int w = 0; w < plan.warmup; ++w) renderer.render_quilt(geometry, layout);
  std::vector<double> render, with_png, cpu;
  for (int r = 0; r < plan.runs; ++r) {
    const double c0 = process_cpu_seconds();
    const auto t0 = Clock::now();
    m.stats.push_back(renderer.render_quilt(geometry, layout));
    const double t = seconds_since(t0);
    render.push_back(t);
    cpu.push_back(process_cpu_seconds() - c0);
    if (r < plan.png_runs) {
      const auto t1 = Clock::now();
      write_png(plan.png_path, to_uint8(renderer.read_quilt()));
      with_png.push_back(t + seconds_since(t1));
    }
  }
  m.peak_bytes = renderer.peak_memory_bytes();
  m.render = summarize(render);
  m.with_png = summarize(with_png);
  m.cpu = summarize(cpu);
  return m;
}

}  // namespace lfd::bench
