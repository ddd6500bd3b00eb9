#include "display/correction_field.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "util/error.hpp"

namespace lfd::display {

BSplineWeights bspline_weights(int n, double t) {
  // n control points span n - 3 uniform segments over [0, 1]; outside it the end segment
  // extrapolates smoothly.
  const int segments = n - 3;
  const double s = std::clamp(t, 0.0, 1.0) * segments;
  const int i = std::clamp(int(std::floor(s)), 0, segments - 1);
  const double x = s - i;
  const double x2 = x * x, x3 = x2 * x;
  BSplineWeights w;
  w.i0 = i;
  w.w = {(1 - x) * (1 - x) * (1 - x) / 6.0, (3 * x3 - 6 * x2 + 4) / 6.0,
         (-3 * x3 + 3 * x2 + 3 * x + 1) / 6.0, x3 / 6.0};
  return w;
}

CorrectionField::CorrectionField(int nx, int ny, std::vector<double> coefficients)
    : nx_(nx), ny_(ny), coefficients_(std::move(coefficients)) {
  if (nx < 4 || ny < 4 || coefficients_.size() != size_t(nx) * size_t(ny))
    throw std::invalid_argument("CorrectionField: needs >= 4x4 control points and nx*ny values");
}

CorrectionField CorrectionField::zeros(int nx, int ny) {
  return CorrectionField(nx, ny, std::vector<double>(size_t(nx) * ny, 0.0));
}

double CorrectionField::operator()(double u, double v) const {
  if (empty()) return 0.0;
  return evaluate(coefficients_.data(), nx_, ny_, u, v);
}

std::array<double, 2> CorrectionField::range() const {
  if (empty()) return {0.0, 0.0};
  double lo = 1e300, hi = -1e300;
  const int n = 64;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double w = (*this)(double(i) / n, double(j) / n);
      lo = std::min(lo, w);
      hi = std::max(hi, w);
    }
  return {lo, hi};
}

nlohmann::ordered_json CorrectionField::to_json() const {
  return {{"model", "uniform cubic B-spline over screen (u, v), v up, lens periods"},
          {"nx", nx_},
          {"ny", ny_},
          {"coefficients", coefficients_}};
}

CorrectionField CorrectionField::from_json(const nlohmann::ordered_json& j,
                                           const std::string& where) {
  require_field(j.is_object(), where, "correction", "is not an object");
  for (const char* key : {"nx", "ny"}) {
    require_field(j.contains(key) && j[key].is_number_integer(), where,
                  std::string("correction.") + key, "must be an integer");
  }
  const long nx = j["nx"].get<long>(), ny = j["ny"].get<long>();
  require_field(nx >= 4 && ny >= 4 && nx <= 256 && ny <= 256, where, "correction.nx/ny",
                "grid must be between 4x4 and 256x256 control points");
  require_field(j.contains("coefficients") && j["coefficients"].is_array(), where,
                "correction.coefficients", "must be an array");
  const auto& c = j["coefficients"];
  require_field(c.size() == size_t(nx * ny), where, "correction.coefficients",
                "has " + std::to_string(c.size()) + " values, expected nx*ny = " +
                    std::to_string(nx * ny));
  std::vector<double> values;
  values.reserve(c.size());
  for (const auto& v : c) {
    require_field(v.is_number() && std::isfinite(v.get<double>()), where,
                  "correction.coefficients", "holds a value that is not a finite number");
    values.push_back(v.get<double>());
  }
  return CorrectionField(int(nx), int(ny), std::move(values));
}

CorrectionField remove_gauge(const CorrectionField& field) {
  if (field.empty()) return field;
  // The LS plane from dense samples, then subtract it exactly: uniform cubic B-splines
  // reproduce 1 and t with coefficients 1 and the Greville abscissae (i - 1) / (n - 3).
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  const int n = 64;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      const Eigen::Vector3d row(1, u, v);
      ata += row * row.transpose();
      atb += row * field(u, v);
    }
  const Eigen::Vector3d plane = ata.ldlt().solve(atb);
  std::vector<double> c = field.coefficients();
  for (int iy = 0; iy < field.ny(); ++iy)
    for (int ix = 0; ix < field.nx(); ++ix) {
      const double gu = (ix - 1.0) / (field.nx() - 3), gv = (iy - 1.0) / (field.ny() - 3);
      c[size_t(iy) * field.nx() + ix] -= plane[0] + plane[1] * gu + plane[2] * gv;
    }
  return CorrectionField(field.nx(), field.ny(), std::move(c));
}

}  // namespace lfd::display
