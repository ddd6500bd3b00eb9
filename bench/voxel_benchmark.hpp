#pragma once
// `lfd bench voxels`: the paper's Table 1 for V2LF: per-view voxel quilts (the exact voxel
// rasterizer with the scene's supersampling, SVR's quilts in the paper) against V2LF
// (voxel/v2lf.hpp) in the Table 1 configurations (bench/render_configs.hpp, "G2LF" read as
// "V2LF"), both in one process on the same scene and quilt: per configuration the median frame
// time of repeated runs after warm-up and its spread, FPS, the speed-up over the per-view quilt,
// PSNR / SSIM against it, plane memory and peak memory. Prints Markdown tables as rows finish;
// returns the figures as JSON. On the CPU or the GL voxel path (the library's renderers,
// bench/bench_renderers.hpp): both sides of a table on the same backend.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/default_display.hpp"
#include "lightfield/light_field_renderer.hpp"

namespace lfd::bench {

struct VoxelBenchOptions {
  std::string scene_path;   // a voxel scene (.voxels, svraster-webgl .ply); empty: generated
  int generated_level = 8;  // the generated tabletop's finest level (voxel/voxel_generator.hpp)
  std::string camera_path;  // cam.json; empty: the tabletop camera of docs/voxels.md for a
                            // generated scene, else voxel::frame_voxel_scene
  std::vector<int> views = {9};
  int size = 256;           // views of size x size pixels
  float view_cone_deg = float(kDefaultViewConeDeg);
  std::vector<std::string> binnings = {"quantile"};  // the paper's
  std::vector<std::string> config_sets = {"table1"};
  int only_chunks = 0;      // > 0: only the configurations with this N_chunk
  int split_levels = 0;     // V2lfOptions::split_levels
  bool plane_lowpass = true;
  int runs = 0;             // timed frames per configuration (0: the backend's default, CPU 3, GL 10)
  int warmup = 1;           // untimed frames before them

  // InputError "voxel benchmark: <field>: ..." for a value out of range.
  void check() const;
};

// `per_view` renders the ground truth, `v2lf` the configurations (its plane options set per row);
// both voxel renderers of one backend.
nlohmann::ordered_json run_voxel_benchmark(lightfield::LightFieldRenderer& per_view, lightfield::LightFieldRenderer& v2lf,
                                           const VoxelBenchOptions& options);

}  // namespace lfd::bench
