#include "pipeline/eye_photo_comparison.hpp"

#include <cstdio>
#include <filesystem>

#include <fmt/format.h>

#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_model.hpp"
#include "display/view_count.hpp"
#include "lightfield/view_plan.hpp"
#include "interlace/interlacer.hpp"
#include "render/default_camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/rasterizer_cpu.hpp"
#include "sim/simulator.hpp"
#include "util/error.hpp"
#include "validate/eye_photographs.hpp"

namespace lfd::pipeline {
namespace {

// The panels of the three paths from one set of planes, and of the quilt path from exact
// per-view renders (what view rounding alone costs, without the planes' approximation).
struct Panels {
  ImageF direct, nearest, linear, per_view_nearest, per_view_linear;
};

Panels render_panels(lightfield::LightFieldRenderer& sweeping, const scene::Scene& scene,
                     const render::QuiltGeometry& geometry,
                     const render::QuiltLayout& layout, const display::LensModel& lens,
                     const EyePhotoOptions& options) {
  lightfield::RendererOptions o = sweeping.options();
  o.planes.chunks = options.chunks;
  sweeping.set_options(o);
  sweeping.render_quilt(geometry, layout);
  const ImageF& quilt = sweeping.read_quilt();
  Panels p;
  interlace::InterlaceOptions io;
  p.nearest = interlace::interlace(quilt, layout, lens, io);
  io.blend = interlace::ViewBlend::kLinear;
  p.linear = interlace::interlace(quilt, layout, lens, io);
  lightfield::RendererOptions direct = o;
  direct.direct_filter = options.direct_filter;
  sweeping.set_options(direct);
  sweeping.render_panel(geometry, lens, {});
  p.direct = sweeping.read_panel();
  sweeping.set_options(o);
  const ImageF per_view = render::render_quilt_per_view(scene.gaussians(), geometry, layout);
  p.per_view_nearest = interlace::interlace(per_view, layout, lens);
  p.per_view_linear = interlace::interlace(per_view, layout, lens, io);
  return p;
}

// The per-view render at the eye's continuous view position (the exact 3DGS pass).
ImageF view_at(const scene::GaussianScene& scene, const render::QuiltGeometry& geometry, double position_s) {
  const render::RasterImage r = render::rasterize(scene, geometry.view_camera_at(float(position_s)));
  ImageF view(r.width, r.height, 3);
  std::copy(r.rgb.begin(), r.rgb.end(), view.pixels.begin());
  return view;
}

}  // namespace

void EyePhotoOptions::check() const {
  const auto fail = [](const std::string& field, const std::string& problem) {
    throw_input_error("eye photographs: {}: {}", field, problem);
  };
  if (chunks < 1 || chunks > 4096) fail("chunks", fmt::format("{} is outside 1..4096", chunks));
  if (view_height < 16 || view_height > 4096) fail("view_height", fmt::format("{} is outside 16..4096", view_height));
  if (between.empty()) fail("between", "no position");
  for (double t : between)
    if (!(t >= 0.0 && t < 1.0)) fail("between", fmt::format("{} is outside [0, 1)", t));
  for (int j : views)
    if (j < 0) fail("views", fmt::format("{} is negative", j));
  if (photo_width != 0 && (photo_width < 16 || photo_width > 8192))
    fail("photo_width", fmt::format("{} is outside 16..8192 (0: the view width)", photo_width));
  if (supersample < 1 || supersample > 8) fail("supersample", fmt::format("{} is outside 1..8", supersample));
}

void print_eye_photo_table_header(const EyePhotoOptions& options) {
  std::printf("lfd bench direct-photos: photographs (optics simulator, lens point spread of the calibration, "
              "%d x %d samples per pixel) from distant eyes at view fraction (j + 1/2 + t) / V, each against the "
              "photograph of the per-view render at that exact view position shown on every subpixel; PSNR over "
              "the central 90 %%; direct and quilt: the sweeping planes (N_chunk %d); per-view quilt: the quilt path from exact "
              "per-view renders\n\n",
              options.supersample, options.supersample, options.chunks);
  std::printf("| scene | display | V | j | t | fraction | PSNR direct [dB] | PSNR quilt nearest [dB] "
              "| PSNR quilt linear [dB] | PSNR per-view quilt nearest [dB] | PSNR per-view quilt linear [dB] |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
}

nlohmann::ordered_json compare_eye_photographs(lightfield::LightFieldRenderer& sweeping,
                                               const scene::Scene& scene,
                                               const std::string& scene_label,
                                               const std::string& calibration_path,
                                               const EyePhotoOptions& options) {
  options.check();
  const display::Calibration calibration = display::read_calibration(calibration_path);
  const display::LensModel lens(calibration.display, calibration.correction);
  // The views the display asks for around the scene's framing (as `lfd bench direct` frames them).
  const lightfield::ViewPlan plan = lightfield::plan_views(lightfield::display_views_request(calibration, options.view_height), &scene);
  const display::ViewSize size{plan.geometry.base.width, plan.geometry.base.height};
  const render::QuiltGeometry& geometry = plan.geometry;
  const render::QuiltLayout& layout = plan.layout;
  const Panels panels = render_panels(sweeping, scene, geometry, layout, lens, options);

  const sim::DisplaySimulator simulator(lens);
  const double psf = calibration.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma);
  const int width = options.photo_width > 0 ? options.photo_width : size.width;
  const int views = geometry.views;
  std::vector<int> js = options.views;
  if (js.empty()) js = {views / 4, views / 2, 3 * views / 4};
  const std::string display_name = std::filesystem::path(calibration_path).filename().string();
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int j : js) {
    if (j >= views - 1) throw_input_error("eye photographs: views: {} is outside 0..{} for {}", j, views - 2, display_name);
    for (double t : options.between) {
      const validate::EyeBetweenViews eye = validate::eye_between_views(lens, views, j, t);
      const auto photo = [&](const ImageF& panel) {
        return validate::photograph(simulator, panel, eye, width, psf, options.supersample);
      };
      const ImageF reference =
          photo(validate::single_view_panel(lens, view_at(scene.gaussians(), geometry, eye.position_s)));
      const double direct = validate::photo_psnr(photo(panels.direct), reference);
      const double nearest = validate::photo_psnr(photo(panels.nearest), reference);
      const double linear = validate::photo_psnr(photo(panels.linear), reference);
      const double pv_nearest = validate::photo_psnr(photo(panels.per_view_nearest), reference);
      const double pv_linear = validate::photo_psnr(photo(panels.per_view_linear), reference);
      std::printf("| %s | %s | %d | %d | %.2f | %.4f | %.2f | %.2f | %.2f | %.2f | %.2f |\n", scene_label.c_str(),
                  display_name.c_str(), views, j, t, eye.fraction, direct, nearest, linear, pv_nearest, pv_linear);
      std::fflush(stdout);
      rows.push_back({{"view", j},
                      {"between", t},
                      {"fraction", eye.fraction},
                      {"eye_m", {eye.eye.x(), eye.eye.y(), eye.eye.z()}},
                      {"psnr_direct_db", direct},
                      {"psnr_quilt_nearest_db", nearest},
                      {"psnr_quilt_linear_db", linear},
                      {"psnr_per_view_quilt_nearest_db", pv_nearest},
                      {"psnr_per_view_quilt_linear_db", pv_linear}});
    }
  }
  return {{"scene", scene_label},
          {"primitives", scene.size()},
          {"display", display_name},
          {"views", views},
          {"view_size", {size.width, size.height}},
          {"photo_width", width},
          {"psf_sigma_phase", psf},
          {"eyes", rows}};
}

}  // namespace lfd::pipeline
