#include "pipeline/demo.hpp"

#include <iostream>
#include <memory>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "calib/calibrate.hpp"
#include "display/calibration_file.hpp"
#include "display/display_quilt.hpp"
#include "display/lens_relations.hpp"
#include "sim/patterns.hpp"
#include "sim/simulator.hpp"
#include "sim/synthetic_unit.hpp"
#include "display/view_count.hpp"
#include "gpu/gl/gl_context.hpp"
#include "lightfield/backend_choice.hpp"
#include "lightfield/panel_interlacing.hpp"
#include "lightfield/renderer_factory.hpp"
#include "lightfield/view_plan.hpp"
#include "pipeline/numbered_quilt.hpp"
#include "render/default_camera.hpp"
#include "render/g2lf.hpp"
#include "render/per_view_quilt.hpp"
#include "scene/gaussian_io.hpp"
#include "util/atomic_file.hpp"
#include "util/data_dir.hpp"
#include "util/image.hpp"
#include "report/demo_report.hpp"
#include "validate/miscalibration.hpp"
#include "report/validation_report.hpp"
#include "validate/view_metrics.hpp"
#include "util/stopwatch.hpp"

namespace lfd::pipeline {

namespace {

class Step {
 public:
  Step(bool verbose, std::string what) : verbose_(verbose), what_(std::move(what)) {
    if (verbose_) fmt::print("  {} ...", what_), std::fflush(stdout);
  }
  ~Step() {
    if (verbose_)
      fmt::print(" {:.1f} s\n", stopwatch_.seconds());
  }

 private:
  bool verbose_;
  std::string what_;
  Stopwatch stopwatch_;
};

// What passes from one stage of the demo to the next (docs/architecture.md, "Long pipelines
// are named stages").
struct DemoRun {
  explicit DemoRun(const DemoOptions& options) : o(options) {}

  const DemoOptions& o;
  std::filesystem::path out;
  std::filesystem::path unit_path, scene_path;
  report::DemoReport report;
  display::Calibration factory;  // the unit's factory file
  sim::SyntheticUnit unit;   // unit.truth: what the simulated unit really is
  display::Calibration recovered;
  display::ViewCountAdvice advice;
  display::DisplayQuilt display_quilt;
  std::unique_ptr<gpu::HeadlessContext> gl;  // null: the CPU renders and interlaces
  double aspect = 1.0;                       // the panel's width / height
  render::QuiltLayout layout;
  ImageF scene_quilt, numbered;
  ImageF scene_panel, numbered_panel;
};

// The simulated unit: its factory file plus a warp only its own calibration describes,
// a view cone 2 degrees wider than nominal, and a user who starts from nominal values off by
// 1 % in pitch and 0.5 degree in slant (sim/synthetic_unit.hpp).
void simulate_unit(DemoRun& run) {
  const DemoOptions& o = run.o;
  const auto& unit_path = run.unit_path;
  const auto& out = run.out;
  run.factory = display::read_calibration(unit_path);
  const display::Calibration& factory = run.factory;
  sim::SyntheticUnitOptions unit_options;
  unit_options.warp_amplitude = o.warp_amplitude_periods;
  run.unit = sim::make_synthetic_unit(factory.display, unit_options);
  display::Calibration& truth = run.unit.truth;
  truth.provenance = {{"tool", "lfd demo"},
                      {"method", fmt::format("factory calibration {} + smooth lens warp of {} periods",
                                             unit_path.filename().string(), o.warp_amplitude_periods)}};
  display::write_calibration(out / "unit_truth.calibration.json", truth, true);
}

// Calibrate it as a user would: patterns shown on the unit, photographed by the simulator from
// three positions (blur, 2 % noise, vignetting, lens distortion, 5 % glare), solved.
void calibrate_unit(DemoRun& run) {
  const DemoOptions& o = run.o;
  const sim::SyntheticUnit& unit = run.unit;
  const display::Calibration& truth = unit.truth;
  display::Calibration& recovered = run.recovered;
  Step step(o.verbose, "calibrating the unit from simulated photographs");
  const sim::PatternSet set = sim::plan_patterns(unit.nominal);
  const sim::CaptureRig rig =
      sim::make_capture_rig(truth.display, o.capture_width, 3, false, 1);
  const auto captures = sim::simulate_captures(set, truth, rig);
  calib::CalibrateOptions options;
  options.camera = rig.intrinsics;
  const calib::CalibrationOutcome outcome = calib::calibrate_display(set, captures, options);
  recovered = outcome.calibration;
  const sim::CalibrationErrors e = sim::compare_with_truth(recovered, truth);
  run.report.calibration_note = fmt::format(
      "Calibrated from {} patterns photographed at 3 positions ({}x{} px), starting from "
      "nominal values off by 1 % in pitch and 0.5 deg in slant. Errors against the truth: "
      "slant {:.5f} deg, pitch {:.1e} relative, center {:.4f} periods, view cone {:.2f} deg, "
      "correction field {:.4f} periods RMS, lens phase {:.4f} periods RMS. Quality gates: {}.",
      set.patterns.size(), rig.intrinsics.width, rig.intrinsics.height, e.slant_deg, e.pitch_rel,
      e.center_periods, e.view_cone_deg, e.correction_rms_periods, e.phase_rms_periods,
      outcome.gate_failures.empty() ? "passed" : "failed (" + std::to_string(outcome.gate_failures.size()) + ")");
  display::write_calibration(run.out / "recovered.calibration.json", recovered, true);
}

// The display is driven with the calibration recovered from photographs: it chooses the
// views, the tile grid and the (measured) view cone the quilt is rendered with.
void choose_views(DemoRun& run) {
  run.advice = display::recommend_view_count(run.recovered);
  run.report.views = run.advice.views;
  run.report.view_rule = run.advice.rule;
  run.display_quilt = display::quilt_for_display(run.recovered);
}

// The GPU path when a context can be made; the CPU reference otherwise (same images to within
// the GL tests' tolerances).
void open_gpu(DemoRun& run) {
  const DemoOptions& o = run.o;
  const auto choice = o.use_gpu ? lightfield::BackendChoice::kAuto : lightfield::BackendChoice::kCpu;
  run.gl = lightfield::open_backend_context(choice, [&](const std::string& reason) {
    if (o.verbose) std::cerr << fmt::format("notice: rendering on the CPU ({})\n", reason);
  });
}

// The quilts the display shows: the bundled scene through G2LF, and the numbered test quilt
// that tells which view an eye sees.
void render_quilts(DemoRun& run) {
  const DemoOptions& o = run.o;
  const auto& gl = run.gl;
  const auto& out = run.out;
  auto& layout = run.layout;
  auto& scene_quilt = run.scene_quilt;
  auto& report = run.report;
  const double aspect = run.aspect;
  const int tile_h = int(std::lround(o.tile_width / aspect));
  {
    Step step(o.verbose, gl ? "rendering the scene with G2LF on the GPU (" + gl->info().renderer + ")"
                            : std::string("rendering the scene with G2LF on the CPU"));
    const scene::Scene light_field_scene(scene::load_gaussian_scene(run.scene_path));
    const scene::GaussianScene& scene = light_field_scene.gaussians();
    // The recovered calibration's views, tiles o.tile_width wide at the panel's aspect.
    lightfield::ViewRequest request;
    request.display = &run.recovered;
    request.size = display::ViewSize{o.tile_width, tile_h};
    request.framing_aspect = float(aspect);
    const lightfield::ViewPlan plan = lightfield::plan_views(request, &light_field_scene);
    const render::QuiltGeometry& geometry = plan.geometry;
    layout = plan.layout;
    lightfield::RendererOptions options;
    options.planes.chunks = 64;
    options.planes.plane_scale = 2;
    options.planes.filter = render::PlaneFilter::kBilinear;
    const auto device = gl ? lightfield::GlDevice::on_current_context(gl->info()) : nullptr;
    options.backend = lightfield::backend_for(device);
    options.gl.raster = o.raster;
    const auto renderer = lightfield::make_renderer(options, scene::SceneKind::kGaussians, device);
    renderer->set_scene(light_field_scene);
    renderer->render_quilt(geometry, layout);
    scene_quilt = renderer->read_quilt();
    report.scene_gaussians = scene.size();
  }
  const std::string suffix = render::quilt_suffix(layout.cols, layout.rows, layout.aspect);
  write_png(out / ("scene_quilt" + suffix + ".png"), to_uint8(scene_quilt));
  run.numbered = make_numbered_quilt(layout);
  write_png(out / ("numbered_quilt" + suffix + ".png"), to_uint8(run.numbered));
}

// Interlace with the calibration the display is driven with (the recovered one).
void interlace_quilts(DemoRun& run) {
  Step step(run.o.verbose, "interlacing");
  const auto& gl = run.gl;
  const auto& layout = run.layout;
  const display::Calibration& assumed = run.recovered;
  const display::LensModel lens(assumed.display, assumed.correction);
  const lightfield::Backend backend = lightfield::backend_of(gl.get());
  run.scene_panel = lightfield::interlace_panel(run.scene_quilt, layout, lens, {}, backend);
  run.numbered_panel = lightfield::interlace_panel(run.numbered, layout, lens, {}, backend);
  write_png(run.out / "scene_panel.png", to_uint8(run.scene_panel));
  write_png(run.out / "numbered_panel.png", to_uint8(run.numbered_panel));
}

// What a person would see: photographs from three positions across the view cone at 0.45 m,
// through the optics of the true unit, each with the view a viewer there should see.
void photograph_display(DemoRun& run) {
  const DemoOptions& o = run.o;
  const display::Calibration& truth = run.unit.truth;
  const auto& d = truth.display;
  const auto& out = run.out;
  Step step(o.verbose, "photographing the display from three positions");
  const sim::DisplaySimulator display(display::LensModel(truth.display, truth.correction));
  const double distance = 0.45;
  const double fov = 2.0 * std::atan(0.65 * d.width_m() / distance) * 180.0 / std::numbers::pi;
  const int cw = o.capture_width, ch = int(std::lround(cw / run.aspect));
  sim::CaptureEffects fx;
  fx.blur_px = 0.7;
  fx.noise_sigma = 0.01;
  fx.vignetting = 0.15;
  for (auto [name, angle] : {std::pair{"left", -0.3}, {"centre", 0.0}, {"right", 0.3}}) {
    const double theta = angle * d.view_cone_deg * std::numbers::pi / 180.0;
    sim::CameraPose pose;
    pose.position_m = {distance * std::sin(theta), 0.0, distance * std::cos(theta)};
    const sim::PhysicalCamera camera(sim::CameraIntrinsics::from_fov(fov, cw, ch), pose);
    // Which view a viewer there should see (docs/validation.md, "The forward model": f_seen at the panel centre).
    const double f_seen =
        display::seen_fraction_through_cover(pose.position_m.x(), pose.position_m.y(),
                                           pose.position_m.z(), d.cover,
                                           display::LensModel(d).line_tilt(), d.view_cone_deg);
    report::DemoCapture cap;
    cap.name = name;
    cap.angle_deg = theta * 180.0 / std::numbers::pi;
    cap.expected_view = display::LensModel::view_index(f_seen, run.advice.views);
    cap.scene_image = fmt::format("capture_scene_{}.png", name);
    cap.numbered_image = fmt::format("capture_numbered_{}.png", name);
    write_png(out / cap.scene_image, to_uint8(display.capture(run.scene_panel, camera, fx)));
    write_png(out / cap.numbered_image, to_uint8(display.capture(run.numbered_panel, camera, fx)));
    run.report.captures.push_back(cap);
  }
}

// How well the views separate when the unit is driven with its recovered calibration, its
// true one, its factory file and a 0.01-degree slant error: what calibrating it bought.
void validate_views(DemoRun& run) {
  const DemoOptions& o = run.o;
  const display::Calibration& truth = run.unit.truth;
  const display::Calibration& assumed = run.recovered;
  Step step(o.verbose, "validating view separation (4 configurations)");
  validate::ProfileOptions po;
  po.views = run.advice.views;
  po.panel_points = o.validation_points;
  std::vector<report::ValidationCase> cases;
  const std::vector<std::pair<std::string, display::Calibration>> configs = {
      {"recovered calibration", assumed},
      {"true calibration", truth},
      {"factory visual.json (no warp correction)", run.factory},
      {"recovered, slant off by 0.01 deg", validate::apply(assumed, validate::Miscalibration{.slant_deg = 0.01})}};
  for (const auto& [name, cal] : configs) {
    report::ValidationCase c;
    c.name = name;
    c.truth_source = "simulated unit";
    c.assumed_source = name;
    c.profiles = validate::measure_view_profiles(truth, cal, po);
    c.summary = validate::summarise(c.profiles);
    run.report.validation.push_back({name, c.summary.mean_separation, c.summary.mean_crosstalk});
    cases.push_back(std::move(c));
  }
  report::write_report(run.out / "validation", cases);
}

}  // namespace

std::filesystem::path run_demo(const DemoOptions& o) {
  namespace fs = std::filesystem;
  const fs::path data = lfd::data_dir();  // installed share/lfd, or the source tree's data/
  DemoRun run(o);
  run.unit_path =
      o.unit_calibration.empty() ? data / "calibrations/LKG-2K-04409.visual.json" : o.unit_calibration;
  run.scene_path = o.scene.empty() ? data / "scenes/playbot.sog" : o.scene;  // data/scenes/playbot.md
  run.out = o.out_dir;
  fs::create_directories(run.out);
  run.report.unit_source = run.unit_path.string();
  run.report.scene_source = run.scene_path.string();
  // CC-BY-4.0 asks that the author be credited wherever the scene is shown (data/scenes/playbot.md).
  if (o.scene.empty()) run.report.scene_source += " (\"PLAYBOT\" by Stephane Agullo, CC-BY-4.0)";

  simulate_unit(run);
  calibrate_unit(run);
  choose_views(run);
  const auto& d = run.unit.truth.display;
  run.aspect = double(d.screen_w) / d.screen_h;
  open_gpu(run);
  render_quilts(run);
  interlace_quilts(run);
  photograph_display(run);
  validate_views(run);
  return report::write_demo_report(run.out, run.report);
}

}  // namespace lfd::pipeline
