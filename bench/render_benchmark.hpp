#pragma once
// `lfd bench render`: per-view quilt rendering against G2LF, both on one backend (the library's
// renderers, lightfield/light_field_renderer.hpp; bench/bench_renderers.hpp) in one process on
// the same scenes: per configuration the median frame time of repeated runs after warm-up and
// its spread (bench/frame_timing.hpp), FPS, the speed-up over the per-view quilt, the time with
// the PNG written (what `lfd render` spends after loading the scene), PSNR / SSIM against the
// per-view quilt, plane memory and peak memory. Prints Markdown tables as rows finish; returns
// the figures as JSON.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "display/display_quilt.hpp"
#include "util/default_display.hpp"
#include "lightfield/light_field_renderer.hpp"
#include "scene/gaussian_scene.hpp"

namespace lfd::bench {

// A scene file, or a generated tabletop scene (render/scene_generator.hpp) of `generated`
// Gaussians.
struct SceneSource {
  std::string path;
  size_t generated = 0;
  std::string label() const;
  // The file's Gaussians, or the generated tabletop of `generated`.
  scene::GaussianScene load_gaussians() const;
};

struct RenderBenchOptions {
  std::vector<SceneSource> scenes;
  std::vector<int> views = {kDefaultViewCount, 2 * kDefaultViewCount};
  display::ViewSize size{512, 512};  // the views' width and height in pixels
  float view_cone_deg = float(kDefaultViewConeDeg);
  float shift_fraction = 1.0f;  // D_shift / D_forward (1: reference camera at the base camera)
  std::vector<std::string> binnings = {"quantile"};  // the paper's
  // Configuration sets (bench/render_configs.hpp); `only_chunks`, when not empty, keeps those with
  // one of its N_chunk; `only_plane_scale` > 0 those with that P_s (view-density rows resolve theirs
  // per table and are dropped by it).
  std::vector<std::string> config_sets = {"table1", "chunks", "f32", "density"};
  std::vector<int> only_chunks;
  int only_plane_scale = 0;
  int runs = 0;         // timed frames per configuration; 0: the backend's default
  int warmup = 1;       // untimed frames before them
  int png_runs = 3;     // the first png_runs timed frames also write the quilt PNG (0: never)
  bool per_view = true; // false: G2LF only (no speed-up, PSNR or SSIM)
  // Generated scenes: a person's tabletop framing (elevated, objects filling the view) instead
  // of the default framing (render/default_camera.hpp).
  bool tabletop_camera = false;

  // InputError "render benchmark: <field>: ..." for a value out of range.
  void check() const;
};

// `per_view` renders the ground truth, `g2lf` the configurations (its plane options set per row);
// both Gaussian renderers of one backend.
nlohmann::ordered_json run_render_benchmark(lightfield::LightFieldRenderer& per_view,
                                            lightfield::LightFieldRenderer& g2lf, const RenderBenchOptions& options);

}  // namespace lfd::bench
