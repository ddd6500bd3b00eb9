#pragma once
// G2LF on the GPU against the CPU reference on scenes larger than the test suite can afford
// on llvmpipe (`lfd bench gl-vs-cpu`; docs/gpu.md, "G2LF on the GPU"): the PSNR of
// gpu::GlG2lfRenderer's quilt against render::render_quilt_g2lf with the same options, the GL
// stage times and the CPU reference's time. The tests hold smaller scenes to 40 dB.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gpu/gl/gl_context.hpp"
#include "lightfield/view_plan.hpp"
#include "render/camera.hpp"
#include "render/g2lf.hpp"
#include "scene/gaussian_scene.hpp"

namespace lfd::bench {

struct GlVsCpuScene {
  std::string name;
  scene::GaussianScene scene;
  render::Camera base;
  float focal_distance = 0;
};

// The views both GL benchmarks render of `s`: `views` views from its base camera, the default
// cone, one row of tiles (the view plan, lightfield/view_plan.hpp).
lightfield::ViewRequest strip_of_views(const GlVsCpuScene& s, int views);

// A scene file framed by render::frame_scene, views of size x size.
GlVsCpuScene gl_vs_cpu_scene_file(const std::string& path, int size);
// The generated tabletop (seed 5) seen from (0, -1, -5) toward the origin, views of size x size.
GlVsCpuScene gl_vs_cpu_tabletop(int gaussians, int size);

// The four option sets of docs/gpu.md: N 64 mixed nearest u8, N 64 quantile bilinear P_s 2
// u8, N 512 mixed nearest u8, N 64 mixed nearest f32 (D_shift = D_forward throughout).
std::vector<render::G2lfOptions> gl_vs_cpu_configs();

struct GlVsCpuRow {
  std::string scene;
  size_t gaussians = 0;
  int views = 0, width = 0, height = 0;  // views of width x height
  std::string options;                   // "N=64 mixed nearest P_s=1 u8"
  double psnr_db = 0;                    // GL quilt against the CPU's
  double gpu_binning_s = 0, gpu_planes_s = 0, gpu_swizzle_s = 0;  // GL stage times
  double gl_frame_s = 0, cpu_frame_s = 0;                         // wall time of one quilt
};

// Renders `scene` in `views` views across the default cone with every configuration on the GL
// context current now (`info`: its limits) and on the CPU. One row per configuration.
std::vector<GlVsCpuRow> run_gl_vs_cpu(const GlVsCpuScene& scene, int views, const gpu::GlInfo& info);

// The rows as a Markdown table, and as JSON.
std::string gl_vs_cpu_table(const std::vector<GlVsCpuRow>& rows);
nlohmann::ordered_json gl_vs_cpu_json(const std::vector<GlVsCpuRow>& rows);

}  // namespace lfd::bench
