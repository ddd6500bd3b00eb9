// lfd_bench_render: the paper's Table 1 on the CPU reference renderers.
// For each scene (the real guitar scene and a generated scene of >= 1M Gaussians) it renders the
// per-view quilt (the ground truth) and G2LF in the Table 1 configurations, and reports render
// time, plane memory, process peak RSS, PSNR and SSIM against the per-view quilt, and the
// speed-up of G2LF over per-view rendering.
//   lfd_bench_render --guitar ../shared/data/scenes/guitar.compressed.ply --json render_bench.json
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "render/default_camera.hpp"
#include "render/g2lf.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/scene_generator.hpp"
#include "render/scene_io.hpp"

using namespace lfd;
using namespace lfd::render;

namespace {

struct Config {
  std::string name;
  int chunks;
  int plane_scale;
  PlaneFilter filter;
};

const std::vector<Config> kTable1 = {
    {"G2LF (N=64)", 64, 1, PlaneFilter::kNearest},
    {"G2LF (N=64, Ps=2)", 64, 2, PlaneFilter::kNearest},
    {"G2LF (N=512)", 512, 1, PlaneFilter::kNearest},
    {"G2LF (N=512, Bi.)", 512, 1, PlaneFilter::kBilinear},
    {"G2LF (N=512, Ps=2)", 512, 2, PlaneFilter::kNearest},
    {"G2LF (N=512, Ps=2, Bi.)", 512, 2, PlaneFilter::kBilinear},
    {"G2LF (N=512, Ps=3, Bi.)", 512, 3, PlaneFilter::kBilinear},
};

double peak_rss_gb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / (1024.0 * 1024.0);  // ru_maxrss is in KiB on Linux
}

template <typename F>
double seconds_of(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A tabletop framed as a person would: 3 units above the ground (y = +1, "up" is -y), 7.5 in
// front of the middle object row, looking down 18 degrees at the objects, which fill the view;
// the ground's near edge is below the view, nothing lies nearer than ~4.9 (D_forward 4.2).
CameraSpec tabletop_camera() {
  CameraSpec s;
  s.position = glm::vec3(0.0f, -2.0f, -7.5f);
  s.look_at = glm::vec3(0.0f, 0.4f, 0.5f);
  s.up = glm::vec3(0.0f, -1.0f, 0.0f);
  s.fov_y_deg = 40.0f;
  return s;
}

nlohmann::json run_scene(const std::string& label, const GaussianScene& scene, int views, int size,
                         float view_cone_deg, float shift_fraction, bool quick,
                         const std::vector<std::string>& binnings, const CameraSpec* camera = nullptr) {
  const CameraSpec spec = camera ? *camera : frame_scene(scene);
  const Camera base = camera_from_spec(spec, size, size);
  const QuiltGeometry geometry =
      make_quilt_geometry(base, glm::length(spec.look_at - spec.position), view_cone_deg, views);
  const QuiltLayout layout = make_quilt_layout(geometry, 5, (views + 4) / 5);
  const float d_shift = shift_fraction * make_reference_camera(geometry, 0.0f, 1).d_forward;

  ImageF truth;
  const double t_per_view = seconds_of([&] { truth = render_quilt_per_view(scene, geometry, layout); });
  std::printf("\n%s: %zu Gaussians, %d views of %dx%d, view cone %.0f deg, D_shift %.2f\n", label.c_str(),
              scene.size(), views, size, size, view_cone_deg, d_shift);
  std::printf("camera (%.2f, %.2f, %.2f) -> (%.2f, %.2f, %.2f), D_focal %.2f\n", spec.position.x,
              spec.position.y, spec.position.z, spec.look_at.x, spec.look_at.y, spec.look_at.z,
              geometry.focal_distance);
  std::printf("%-32s %9s %8s %10s %10s %8s %7s\n", "method", "time [s]", "FPS", "planes[GB]",
              "peakRSS[GB]", "PSNR", "SSIM");
  std::printf("%-32s %9.3f %8.3f %10s %10.2f %8s %7s\n", "per-view 3DGS (truth)", t_per_view,
              1.0 / t_per_view, "-", peak_rss_gb(), "-", "-");
  nlohmann::json rows = nlohmann::json::array();
  rows.push_back({{"method", "per-view"}, {"seconds", t_per_view}, {"peak_rss_gb", peak_rss_gb()}});
  double speedup_64 = 0.0;
  for (const std::string& binning : binnings)
  for (const Config& c : kTable1) {
    if (quick && c.chunks > 64) continue;
    G2lfOptions o;
    o.binning = parse_chunk_binning(binning);
    o.chunks = c.chunks;
    o.plane_scale = c.plane_scale;
    o.filter = c.filter;
    o.d_shift = d_shift;
    G2lfStats stats;
    ImageF quilt;
    const double t = seconds_of([&] { quilt = render_quilt_g2lf(scene, geometry, layout, o, {}, &stats); });
    const double p = psnr(quilt, truth), s = ssim(quilt, truth);
    const double plane_gb = double(stats.plane_bytes) / 1e9;
    const std::string name = c.name + (binning == "quantile" ? "" : " mixed");
    std::printf("%-32s %9.3f %8.3f %10.3f %10.2f %8.2f %7.4f   (bin %.3f, planes %.3f, swizzle %.3f s)\n",
                name.c_str(), t, 1.0 / t, plane_gb, peak_rss_gb(), p, s, stats.seconds_binning,
                stats.seconds_planes, stats.seconds_swizzle);
    if (c.chunks == 64 && c.plane_scale == 1 && binning == binnings.front()) speedup_64 = t_per_view / t;
    rows.push_back({{"method", name}, {"binning", binning}, {"chunks", c.chunks}, {"plane_scale", c.plane_scale},
                    {"filter", c.filter == PlaneFilter::kBilinear ? "bilinear" : "nearest"},
                    {"seconds", t}, {"seconds_binning", stats.seconds_binning},
                    {"seconds_planes", stats.seconds_planes}, {"seconds_swizzle", stats.seconds_swizzle},
                    {"plane_gb", plane_gb}, {"planes", stats.planes},
                    {"gaussians_in_frustum", stats.gaussians_in_frustum}, {"peak_rss_gb", peak_rss_gb()},
                    {"psnr_db", p}, {"ssim", s}, {"speedup", t_per_view / t}});
  }
  std::printf("speed-up of G2LF (N=64, Ps=1) over per-view: %.1fx\n", speedup_64);
  return {{"scene", label}, {"gaussians", scene.size()}, {"views", views}, {"size", size},
          {"view_cone_deg", view_cone_deg}, {"d_shift", d_shift}, {"speedup_n64", speedup_64}, {"rows", rows}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"G2LF vs per-view quilt rendering on the CPU (paper Table 1 configurations)."};
  std::string guitar = std::string(LFD_SHARED_DATA_DIR) + "/scenes/guitar.compressed.ply";
  std::string json_path;
  size_t generated = 1000000;
  int views = 45, size = 512;
  float cone = 40.0f, shift = 1.0f;
  bool quick = false, tabletop = false;
  std::vector<std::string> binnings = {"quantile", "mixed"};
  app.add_option("--guitar", guitar, "real scene to render (empty: skip)")->capture_default_str();
  app.add_option("--generated", generated, "Gaussians in the generated scene (0: skip)")->capture_default_str();
  app.add_option("--views", views, "quilt views")->capture_default_str();
  app.add_option("--size", size, "view width = height in pixels")->capture_default_str();
  app.add_option("--view-cone", cone, "view cone in degrees")->capture_default_str();
  app.add_option("--shift", shift, "D_shift as a fraction of D_forward (1: reference camera at the base camera; 0: paper)")->capture_default_str();
  app.add_option("--binning", binnings, "chunk binnings to run: quantile (paper), mixed (default of lfd render)")
      ->delimiter(',')->capture_default_str();
  app.add_flag("--tabletop-camera", tabletop,
               "generated scene: a person's tabletop framing (elevated, objects filling the view) "
               "instead of the default framing (render/default_camera.hpp)");
  app.add_flag("--quick", quick, "only the N_chunk = 64 configurations");
  app.add_option("--json", json_path, "write the results as JSON");
  CLI11_PARSE(app, argc, argv);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // rows appear as they finish, also in a log file

  try {
    nlohmann::json out;
    out["threads"] = omp_get_max_threads();
    out["scenes"] = nlohmann::json::array();
    if (!guitar.empty()) {
      const GaussianScene scene = load_scene(guitar);
      out["scenes"].push_back(run_scene("guitar", scene, views, size, cone, shift, quick, binnings));
    }
    if (generated > 0) {
      SceneGeneratorOptions g;
      g.count = generated;
      const GaussianScene scene = generate_scene(g);
      const CameraSpec camera = tabletop_camera();
      out["scenes"].push_back(run_scene(fmt::format("generated {} ({}){}", g.kind, generated,
                                                    tabletop ? ", tabletop camera" : ""),
                                        scene, views, size, cone, shift, quick, binnings,
                                        tabletop ? &camera : nullptr));
    }
    if (!json_path.empty()) {
      std::ofstream(json_path) << out.dump(2) << "\n";
      std::printf("\nwrote %s\n", json_path.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lfd_bench_render: %s\n", e.what());
    return 1;
  }
  return 0;
}
