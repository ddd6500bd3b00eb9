// lfd camera calibrate: camera.yaml from photos of the printed board. Thin: the work is
// calib::calibrate_camera_from_photos.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <set>

#include "apps/camera.hpp"
#include "apps/cli.hpp"
#include "util/error.hpp"

namespace lfd::apps {

namespace {

// The photos named, a folder standing for the images in it (sorted by name).
std::vector<std::filesystem::path> expand_photos(const std::vector<std::string>& args) {
  static const std::set<std::string> kImageExtensions = {".png", ".jpg", ".jpeg", ".tif",
                                                         ".tiff", ".bmp", ".webp"};
  std::vector<std::filesystem::path> out;
  for (const auto& arg : args) {
    if (!std::filesystem::is_directory(arg)) {
      out.emplace_back(arg);
      continue;
    }
    std::vector<std::filesystem::path> in_folder;
    for (const auto& entry : std::filesystem::directory_iterator(arg)) {
      std::string ext = entry.path().extension().string();
      std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
      if (entry.is_regular_file() && kImageExtensions.count(ext)) in_folder.push_back(entry.path());
    }
    if (in_folder.empty()) throw_input_error("{}: a folder with no images", arg);
    std::sort(in_folder.begin(), in_folder.end());
    out.insert(out.end(), in_folder.begin(), in_folder.end());
  }
  return out;
}

void print_result(const calib::CameraCalibration& c, const calib::CameraCalibrationOptions& o) {
  std::vector<double> errors;
  for (const auto& p : c.photos)
    if (p.usable) errors.push_back(p.rms_px);
  std::nth_element(errors.begin(), errors.begin() + long(errors.size() / 2), errors.end());
  const double median = errors[errors.size() / 2];
  std::printf("%-32s %7s %8s %9s %14s %8s\n", "photo", "corners", "error px", "tilt deg",
              "(up/dn, l/r)", "dist mm");
  for (const auto& p : c.photos) {
    const std::string name = std::filesystem::path(p.name).filename().string();
    if (!p.usable) {
      std::printf("%-32s %7d  not used (fewer than %d corners)\n", name.c_str(), p.corners,
                  o.min_corners);
      continue;
    }
    // A photo far worse than the rest was blurred, or the board bent or moved.
    const bool outlier = p.rms_px > 3 * median && p.rms_px > 0.5;
    std::printf("%-32s %7d %8.3f %9.1f %6.1f, %6.1f %8.0f%s\n", name.c_str(), p.corners, p.rms_px,
                p.tilt_deg, p.tilt_about_x_deg, p.tilt_about_y_deg, p.distance_mm,
                outlier ? "  <- check: blurred, bent or moved?" : "");
  }
  const auto& K = c.intrinsics.camera_matrix;
  std::printf("usable photos: %d of %zu (>= %d board corners each)\n", c.usable, c.photos.size(),
              o.min_corners);
  std::printf("reprojection error: %.3f px RMS\n", c.rms_px);
  std::printf("focal length: fx %.2f, fy %.2f px (1-sigma %.2f %%)\n", K(0, 0), K(1, 1),
              100 * c.focal_sigma_rel);
  std::printf("principal point: (%.2f, %.2f) px (1-sigma %.2f px) in %dx%d\n", K(0, 2), K(1, 2),
              c.principal_sigma_px, c.intrinsics.width, c.intrinsics.height);
  std::printf("distortion:");
  for (double d : c.intrinsics.distortion) std::printf(" %.5f", d);
  std::printf("  (k1 k2 p1 p2%s)\n", c.intrinsics.distortion.size() > 4 ? " k3" : "");
  std::printf("tilt spread: %.0f deg up/down, %.0f deg left/right: %s\n", c.tilt_range_x_deg,
              c.tilt_range_y_deg, c.pose_advice.empty() ? "varied enough" : "NOT varied enough");
  if (!c.pose_advice.empty()) std::printf("advice: %s\n", c.pose_advice.c_str());
}

}  // namespace

int RunCameraCalibrate(int argc, char** argv) {
  CLI::App app{
      "Calibrate a camera from photos of the board `lfd camera board` prints: writes the\n"
      "OpenCV YAML (camera_matrix, distortion_coefficients, image_width, image_height) that\n"
      "`lfd calibrate --camera` reads. Take the photos at the resolution, zoom and focus you\n"
      "will photograph the display with; tilt the board 20-40 deg left, right, up and down.\n"
      "\nExamples:\n"
      "  lfd camera calibrate photos/ --out camera.yaml\n"
      "  lfd camera calibrate IMG_*.jpg --square-mm 29.7 --out camera.yaml --force\n"
      "  lfd camera calibrate shots/ --squares 12x8 --square-mm 20 --fix-k3 --out camera.yaml",
      "calibrate"};
  std::vector<std::string> photo_args;
  std::string out_path;
  CameraBoardFlags board_flags;
  calib::CameraCalibrationOptions options;
  bool force = false;
  app.add_option("PHOTOS", photo_args, "photos of the board, or folders of them")->required();
  app.add_option("--out", out_path, "camera.yaml to write")->required();
  board_flags.add(app);
  app.add_option("--min-photos", options.min_photos, "usable photos needed")
      ->capture_default_str()
      ->check(CLI::Range(3, 1000));
  app.add_option("--min-corners", options.min_corners, "board corners a photo needs to be used")
      ->capture_default_str()
      ->check(CLI::Range(6, 10000));
  app.add_flag("--fix-k3", options.fix_k3,
               "estimate k1 k2 p1 p2 only (narrow lenses, or when k3 comes out large)");
  app.add_flag("--force", force, "replace an existing camera file");
  if (auto code = parse(app, argc, argv)) return *code;

  options.board = board_flags.parse();
  if (std::filesystem::exists(out_path) && !force)
    throw_input_error("{}: exists; pass --force to replace it", out_path);
  const calib::CameraCalibration result =
      calib::calibrate_camera_from_photos(expand_photos(photo_args), options);
  print_result(result, options);
  result.intrinsics.write_yaml(out_path);
  std::printf("wrote %s\n", out_path.c_str());
  return 0;
}

}  // namespace lfd::apps
