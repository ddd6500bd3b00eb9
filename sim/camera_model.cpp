#include "sim/camera_model.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/persistence.hpp>

#include "util/atomic_file.hpp"
#include "util/error.hpp"

namespace lfd::sim {

namespace {

// Reads a numeric matrix node; a missing or non-numeric node is the user's file's fault.
cv::Mat read_matrix(const cv::FileStorage& fs, const std::string& file, const std::string& node) {
  const cv::FileNode n = fs[node];
  if (n.empty() || n.isNone()) throw_input_error("{}: {}: missing", file, node);
  // OpenCV allocates the declared rows x cols (sizes) before it reads the data, and a
  // non-numeric size reads as INT_MAX: bound them first (these matrices are 3x3 and 1x14).
  if (n.isMap()) {
    double elements = 1;
    for (const char* key : {"rows", "cols"})
      if (const cv::FileNode d = n[key]; !d.empty()) {
        if (!d.isInt()) throw_input_error("{}: {}.{}: not a whole number", file, node, key);
        elements *= std::abs(double(int(d)));
      }
    if (const cv::FileNode sizes = n["sizes"]; !sizes.empty()) {
      if (!sizes.isSeq() || sizes.size() > 4)
        throw_input_error("{}: {}.sizes: not a list of up to 4 sizes", file, node);
      for (const cv::FileNode& d : sizes) {
        if (!d.isInt()) throw_input_error("{}: {}.sizes: not a whole number", file, node);
        elements *= std::abs(double(int(d)));
      }
    }
    if (elements > 1024)
      throw_input_error("{}: {}: {} values is not a camera matrix", file, node, elements);
  }
  cv::Mat m;
  try {
    n >> m;
  } catch (const std::exception&) {  // cv::Exception, or std::bad_alloc for absurd sizes
    throw_input_error("{}: {}: not an OpenCV matrix", file, node);
  }
  if (m.empty() || m.channels() != 1) throw_input_error("{}: {}: not an OpenCV matrix", file, node);
  m.convertTo(m, CV_64F);
  for (auto it = m.begin<double>(); it != m.end<double>(); ++it)
    if (!std::isfinite(*it)) throw_input_error("{}: {}: non-finite value", file, node);
  return m;
}

// What OpenCV 4.6's FileStorage readers must not see (found by fuzz_camera_yaml): its XML
// reader dereferences null on a truncated declaration, and its YAML reader loops forever on a
// NUL byte and when, after a document, it meets a line that begins with '-' but not "---" (also
// one left over in its line buffer when a document whose root is indented ends on a short
// line). So camera files are YAML only (FileStorage picks the reader from the first bytes),
// one document with its top level in column 1, as FileStorage writes them.
void check_yaml_layout(const std::string& text, const std::string& file) {
  if (text.find('\0') != std::string::npos)
    throw_input_error("{}: not a text file (holds a NUL byte)", file);
  std::string_view rest(text);
  if (rest.starts_with("\xEF\xBB\xBF")) rest.remove_prefix(3);
  if (!rest.starts_with("%YAML"))
    throw_input_error("{}: not an OpenCV YAML file (the first line must be %YAML:1.0)", file);
  enum class State { kPreamble, kStarted, kRoot, kEnded } state = State::kPreamble;
  for (int number = 1; !rest.empty(); ++number) {
    const size_t eol = rest.find('\n');
    const std::string_view line = rest.substr(0, eol);
    rest.remove_prefix(eol == std::string_view::npos ? rest.size() : eol + 1);
    const size_t first = line.find_first_not_of(" \r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    const bool end_marker = line.starts_with("---") || line.starts_with("...");
    switch (state) {
      case State::kEnded:
        throw_input_error("{}: line {}: a camera file holds one YAML document", file, number);
      case State::kRoot:
        if (end_marker) state = State::kEnded;
        continue;
      case State::kPreamble:
        if (line.starts_with("%")) continue;
        if (line.starts_with("---")) {
          const size_t after = line.find_first_not_of(" \r", 3);
          if (after != std::string_view::npos && line[after] != '#')
            throw_input_error("{}: line {}: nothing may follow \"---\" on its line", file, number);
          state = State::kStarted;
          continue;
        }
        [[fallthrough]];
      case State::kStarted:
        if (end_marker) {
          state = State::kEnded;
          continue;
        }
        if (first > 0)
          throw_input_error("{}: line {}: the top level must start in column 1", file, number);
        state = State::kRoot;
    }
  }
}

int read_size(const cv::FileStorage& fs, const std::string& file, const std::string& node) {
  const cv::FileNode n = fs[node];
  if (n.empty() || n.isNone()) throw_input_error("{}: {}: missing", file, node);
  if (!n.isInt() && !n.isReal()) throw_input_error("{}: {}: not a number", file, node);
  const double v = n.real();
  if (!(v >= 1 && v <= 100000) || v != std::floor(v))
    throw_input_error("{}: {}: {} is not an image size in pixels", file, node, v);
  return int(v);
}

}  // namespace

CameraIntrinsics CameraIntrinsics::from_fov(double horizontal_fov_deg, int width, int height) {
  if (!(horizontal_fov_deg > 0 && horizontal_fov_deg < 180))
    throw_input_error("fov: {} degrees is not a field of view (0 < fov < 180)",
                      horizontal_fov_deg);
  if (width < 1 || height < 1) throw_input_error("size: {}x{} is not an image size", width, height);
  CameraIntrinsics k;
  k.width = width;
  k.height = height;
  const double f = 0.5 * width / std::tan(0.5 * horizontal_fov_deg * std::numbers::pi / 180.0);
  // OpenCV pixel centres are integers, so the optical axis of a centred camera hits
  // ((w - 1) / 2, (h - 1) / 2).
  k.camera_matrix = cv::Matx33d(f, 0, 0.5 * (width - 1), 0, f, 0.5 * (height - 1), 0, 0, 1);
  return k;
}

CameraIntrinsics CameraIntrinsics::read_yaml(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!std::filesystem::exists(path)) throw_input_error("{}: file not found", file);
  check_yaml_layout(read_text_file(path), file);
  cv::FileStorage fs;
  try {
    if (!fs.open(file, cv::FileStorage::READ)) throw_input_error("{}: cannot be read", file);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {  // cv::Exception, or std::length_error from its parser
    throw_input_error("{}: not an OpenCV YAML file", file);
  }
  // OpenCV asserts on what it did not expect (a top level that is not a map, a node of the
  // wrong kind): that is the file's fault too.
  try {
    CameraIntrinsics k;
    const cv::Mat K = read_matrix(fs, file, "camera_matrix");
    if (K.rows != 3 || K.cols != 3) throw_input_error("{}: camera_matrix: must be 3x3", file);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) k.camera_matrix(r, c) = K.at<double>(r, c);
    if (!(k.camera_matrix(0, 0) > 0 && k.camera_matrix(1, 1) > 0))
      throw_input_error("{}: camera_matrix: focal lengths must be positive", file);

    const cv::Mat D = read_matrix(fs, file, "distortion_coefficients");
    const size_t n = D.total();
    // cv::projectPoints accepts 4, 5, 8, 12 or 14 coefficients.
    if (n != 4 && n != 5 && n != 8 && n != 12 && n != 14)
      throw_input_error("{}: distortion_coefficients: {} values (expected 4, 5, 8, 12 or 14)",
                        file, n);
    k.distortion.assign(D.begin<double>(), D.end<double>());
    k.width = read_size(fs, file, "image_width");
    k.height = read_size(fs, file, "image_height");
    return k;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception&) {
    throw_input_error("{}: not an OpenCV camera file (camera_matrix, distortion_coefficients, "
                      "image_width, image_height at the top level)", file);
  }
}

void CameraIntrinsics::write_yaml(const std::filesystem::path& path) const {
  write_file_atomic(path, [&](const std::filesystem::path& tmp) {
    // FileStorage picks the format from the extension; keep the final one on the temp name.
    const std::filesystem::path named = tmp.string() + path.extension().string();
    {
      cv::FileStorage fs(named.string(), cv::FileStorage::WRITE);
      fs << "image_width" << width << "image_height" << height;
      fs << "camera_matrix" << cv::Mat(camera_matrix);
      cv::Mat d(1, int(distortion.size()), CV_64F);
      for (size_t i = 0; i < distortion.size(); ++i) d.at<double>(0, int(i)) = distortion[i];
      fs << "distortion_coefficients" << d;
    }
    std::filesystem::rename(named, tmp);
  });
}

PhysicalCamera::PhysicalCamera(CameraIntrinsics intrinsics, CameraPose pose)
    : intrinsics_(std::move(intrinsics)), pose_(std::move(pose)) {
  // OpenCV camera axes in the display frame: z forward (toward look_at), x right, y down.
  const Eigen::Vector3d forward = pose_.look_at_m - pose_.position_m;
  if (!(forward.norm() > 1e-12))
    throw_input_error("camera: look-at point coincides with the camera position");
  const Eigen::Vector3d z = forward.normalized();
  const Eigen::Vector3d x_raw = z.cross(pose_.up);
  if (!(x_raw.norm() > 1e-9)) throw_input_error("camera: up vector is parallel to the view direction");
  const Eigen::Vector3d x = x_raw.normalized();
  const Eigen::Vector3d y = z.cross(x);  // down
  rotation_.row(0) = x.transpose();
  rotation_.row(1) = y.transpose();
  rotation_.row(2) = z.transpose();
}

bool PhysicalCamera::project(const Eigen::Vector3d& world, Eigen::Vector2d& pixel) const {
  const Eigen::Vector3d pc = rotation_ * (world - pose_.position_m);
  if (pc.z() <= 1e-12) return false;
  if (intrinsics_.distortion.empty()) {
    const auto& K = intrinsics_.camera_matrix;
    const double xn = pc.x() / pc.z(), yn = pc.y() / pc.z();
    pixel = {K(0, 0) * xn + K(0, 1) * yn + K(0, 2), K(1, 1) * yn + K(1, 2)};
    return true;
  }
  // The same model as cv::projectPoints, so OpenCV calibration files mean what they say.
  const std::vector<cv::Point3d> in{{pc.x(), pc.y(), pc.z()}};
  std::vector<cv::Point2d> out;
  cv::projectPoints(in, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Mat(intrinsics_.camera_matrix),
                    intrinsics_.distortion, out);
  pixel = {out[0].x, out[0].y};
  return true;
}

bool PhysicalCamera::panel_point(const Eigen::Vector2d& pixel, Eigen::Vector3d& on_panel) const {
  const auto& K = intrinsics_.camera_matrix;
  double xn = 0, yn = 0;
  if (intrinsics_.distortion.empty()) {
    yn = (pixel.y() - K(1, 2)) / K(1, 1);
    xn = (pixel.x() - K(0, 2) - K(0, 1) * yn) / K(0, 0);
  } else {
    // More iterations than cv::undistortPoints' default 5, so strong distortion inverts
    // to well under a micro-pixel (project/panel_point round trip).
    const std::vector<cv::Point2d> in{{pixel.x(), pixel.y()}};
    std::vector<cv::Point2d> out;
    cv::undistortPoints(in, out, cv::Mat(K), intrinsics_.distortion, cv::noArray(), cv::noArray(),
                        cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100,
                                         1e-14));
    xn = out[0].x;
    yn = out[0].y;
  }
  const Eigen::Vector3d dir = rotation_.transpose() * Eigen::Vector3d(xn, yn, 1.0);
  const Eigen::Vector3d& c = pose_.position_m;
  // Ray-plane intersection with the panel plane z = 0, in front of the camera only.
  if (std::abs(dir.z()) < 1e-15) return false;
  const double t = -c.z() / dir.z();
  if (!(t > 0)) return false;
  on_panel = c + t * dir;
  on_panel.z() = 0.0;
  return true;
}

}  // namespace lfd::sim
