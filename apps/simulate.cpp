// lfd simulate: a synthetic photograph of a display showing a panel image (docs/validation.md "The
// forward model").
#include <iostream>

#include "apps/cli.hpp"
#include "apps/commands.hpp"
#include "display/calibration_file.hpp"
#include "sim/simulator.hpp"
#include "display/view_count.hpp"
#include "util/error.hpp"
#include "util/image.hpp"

namespace lfd::apps {

namespace {

Eigen::Vector3d vec3(const std::string& text, const std::string& option) {
  const auto v = parse_numbers(text, ',', 3, option);
  return {v[0], v[1], v[2]};
}

}  // namespace

int RunSimulate(int argc, char** argv) {
  CLI::App app{
      "Simulate what a camera sees of a lenticular display showing a panel image: the display\n"
      "follows the TRUE calibration (lens phase, correction field, lens point spread), the camera\n"
      "adds projection, lens distortion, defocus blur, exposure, vignetting, glare, noise, gamma\n"
      "and 8-bit quantisation. Display frame: panel at z = 0, x right, y up, metres, origin at\n"
      "the panel centre, camera at z > 0.\n"
      "\nExamples:\n"
      "  lfd simulate --calibration truth.json --panel panel.png --camera-pos 0,0,0.6 --out cap.png\n"
      "  lfd simulate --calibration visual.json --panel p.png --camera-pos 0.1,0.02,0.5 \\\n"
      "      --camera cam.yaml --blur 1.2 --noise 0.01 --gamma 2.2 --seed 7 --out cap.png",
      "simulate"};
  std::string calibration_path, panel_path, out_path, camera_yaml, position = "0,0,0.6",
      look_at = "0,0,0", up = "0,1,0", size = "1920x1080";
  double fov_deg = 40.0;
  sim::CaptureEffects fx;
  std::optional<double> psf;
  app.add_option("--calibration", calibration_path, "TRUE calibration.json or visual.json")
      ->required();
  app.add_option("--panel", panel_path, "panel image, exactly screenW x screenH")->required();
  app.add_option("--camera-pos", position, "camera position X,Y,Z in metres (Z > 0)")
      ->required();
  app.add_option("--look-at", look_at, "point the camera looks at, X,Y,Z metres")
      ->capture_default_str();
  app.add_option("--up", up, "camera up direction in the display frame")->capture_default_str();
  auto* yaml_opt = app.add_option("--camera", camera_yaml,
                                  "OpenCV YAML intrinsics (camera_matrix, distortion_coefficients, "
                                  "image_width, image_height)");
  app.add_option("--fov", fov_deg, "horizontal field of view in degrees (pinhole, no distortion)")
      ->capture_default_str()
      ->excludes(yaml_opt);
  app.add_option("--size", size, "image size WxH for --fov")->capture_default_str()->excludes(yaml_opt);
  app.add_option("--psf", psf,
                 "lens point spread sigma_A in lens periods (default: the calibration's, else "
                 "0.008)");
  app.add_option("--blur", fx.blur_px, "defocus blur sigma in camera pixels")->capture_default_str();
  app.add_option("--noise", fx.noise_sigma, "sensor noise sigma, fraction of full scale")
      ->capture_default_str();
  app.add_option("--vignetting", fx.vignetting, "relative fall-off at the image corner")
      ->capture_default_str();
  app.add_option("--gamma", fx.gamma, "camera response: out = in^(1/gamma)")->capture_default_str();
  app.add_option("--exposure", fx.exposure, "gain before clipping")->capture_default_str();
  app.add_option("--glare", fx.glare_fraction, "fraction of pixels saturated by glare blobs")
      ->capture_default_str();
  app.add_option("--supersample", fx.supersample, "samples per camera pixel per axis")
      ->capture_default_str();
  app.add_option("--seed", fx.seed, "seed of noise and glare")->capture_default_str();
  app.add_option("--out", out_path, "capture to write (PNG)")->required();
  if (auto code = parse(app, argc, argv)) return *code;

  const display::Calibration cal = display::read_calibration(calibration_path);
  fx.psf_sigma_phase = psf.value_or(cal.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma));
  sim::CameraIntrinsics intrinsics;
  if (!camera_yaml.empty()) {
    intrinsics = sim::CameraIntrinsics::read_yaml(camera_yaml);
  } else {
    const auto wh = parse_numbers(size, 'x', 2, "--size");
    intrinsics = sim::CameraIntrinsics::from_fov(fov_deg, int(wh[0]), int(wh[1]));
  }
  const sim::PhysicalCamera camera(
      intrinsics, sim::CameraPose{vec3(position, "--camera-pos"), vec3(look_at, "--look-at"),
                                    vec3(up, "--up")});
  const Image8 panel8 = read_image(panel_path, 3);
  if (panel8.width != cal.display.screen_w || panel8.height != cal.display.screen_h)
    throw_input_error("{}: size {}x{}, but {} needs a {}x{} panel image (interlace for this display)",
                      panel_path, panel8.width, panel8.height, calibration_path,
                      cal.display.screen_w, cal.display.screen_h);
  const sim::DisplaySimulator simulator{display::LensModel(cal.display, cal.correction)};
  const ImageF capture = simulator.capture(to_float(panel8), camera, fx);
  write_png(out_path, to_uint8(capture));
  std::cout << "wrote " << out_path << " (" << capture.width << "x" << capture.height
            << ", camera at " << position << " m, psf " << fx.psf_sigma_phase << " periods)\n";
  return 0;
}

}  // namespace lfd::apps
