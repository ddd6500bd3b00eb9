#pragma once
// The timing loop both benchmarks share (`lfd bench render`, `lfd bench voxels`): a renderer's
// quilt frames after warm-up, each timed alone (wall and process CPU seconds), the first few
// also read back, converted to 8 bits and written as PNG, the peak memory since the loop began.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "bench/timing_stats.hpp"
#include "lightfield/light_field_renderer.hpp"

namespace lfd::bench {

struct FramePlan {
  int warmup = 1;  // untimed frames first
  int runs = 3;    // timed frames
  int png_runs = 0;  // of the timed frames, how many also write the quilt to png_path
  std::filesystem::path png_path;
};

struct FrameTimings {
  TimingStats render;    // render-only frame time
  TimingStats with_png;  // frame + read-back + 8-bit conversion + PNG write
  TimingStats cpu;       // process CPU seconds per frame
  size_t peak_bytes = 0;
  std::vector<lightfield::QuiltStats> stats;  // per timed frame
};

// Resets the renderer's peak memory, then runs plan.warmup + plan.runs quilt frames.
FrameTimings time_frames(lightfield::LightFieldRenderer& renderer, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const FramePlan& plan);

}  // namespace lfd::bench
