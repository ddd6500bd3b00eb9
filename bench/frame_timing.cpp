#include "bench/frame_timing.hpp"

#include <sys/resource.h>

#include "util/stopwatch.hpp"

namespace lfd::bench {
namespace {

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
    const Stopwatch stopwatch;
    m.stats.push_back(renderer.render_quilt(geometry, layout));
    const double t = stopwatch.seconds();
    render.push_back(t);
    cpu.push_back(process_cpu_seconds() - c0);
    if (r < plan.png_runs) {
      const Stopwatch png_write;
      write_png(plan.png_path, to_uint8(renderer.read_quilt()));
      with_png.push_back(t + png_write.seconds());
    }
  }
  m.peak_bytes = renderer.peak_memory_bytes();
  m.render = summarize(render);
  m.with_png = summarize(with_png);
  m.cpu = summarize(cpu);
  return m;
}

}  // namespace lfd::bench
