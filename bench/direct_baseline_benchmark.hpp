#pragma once
// `lfd bench direct --baseline` (docs/performance.md "Direct panel rendering"): the per-view direct
// baseline. Each quilt view rasterised with the exact 3DGS forward pass (render/rasterizer_cpu.hpp)
// only where the panel reads it (interlace/view_masks.hpp), then interlaced, against the same views
// rasterised whole, and against the direct pass of the sweeping planes, on the CPU in one process,
// the three sides alternating. Per display and scene: the fraction of view pixels masked in, the
// median frame time of each side after warm-up, and the largest difference between the masked and
// the unmasked panel (0: the mask changes nothing the panel shows). Prints a Markdown table as rows
// finish; returns JSON.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/render_benchmark.hpp"
#include "interlace/interlacer.hpp"
#include "lightfield/light_field_renderer.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::bench {

struct DirectBaselineOptions {
  std::vector<std::string> calibrations;  // visual.json / calibration.json files
  std::vector<SceneSource> scenes;
  int chunks = 64;        // N_chunk of the direct pass
  int runs = 2;           // timed frames per side
  int warmup = 1;         // untimed frames of each side first
  int view_height = 512;  // view height; the width follows the display's aspect
  // View counts of the rows; 0: the display's recommendation. The more views, the fewer of each
  // view's pixels the panel reads, and the more the mask leaves out.
  std::vector<int> views = {0};
  interlace::ViewBlend blend = interlace::ViewBlend::kNearest;  // the interlacer's (and masks')
  render::PlaneFilter direct_filter = render::PlaneFilter::kBilinear;

  // InputError "direct baseline benchmark: <field>: ..." for a value out of range.
  void check() const;
};

// `sweeping`: the CPU G2LF renderer (the direct pass; its plane options are set here).
nlohmann::ordered_json run_direct_baseline_benchmark(lightfield::LightFieldRenderer& sweeping,
                                                     const DirectBaselineOptions& options);

}  // namespace lfd::bench
