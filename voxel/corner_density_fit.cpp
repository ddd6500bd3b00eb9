// The corner fit as an overdetermined sparse system A x = b: one row per voxel (the mean of its
// 8 corners = its target), one per grid point (weight * x = weight * point value).
#include "voxel/corner_density_fit.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

namespace lfd::voxel {

std::vector<float> fit_corner_densities(const std::vector<std::array<uint32_t, 8>>& corner_point,
                                        const std::vector<float>& voxel_target_raw,
                                        const std::vector<float>& point_raw, const CornerFitOptions& options) {
  const Eigen::Index voxels = Eigen::Index(corner_point.size()), points = Eigen::Index(point_raw.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(size_t(voxels) * 8 + size_t(points));
  Eigen::VectorXd b(voxels + points), guess(points);
  for (Eigen::Index v = 0; v < voxels; ++v) {
    for (uint32_t p : corner_point[size_t(v)]) entries.emplace_back(v, Eigen::Index(p), 0.125);
    b[v] = voxel_target_raw[size_t(v)];
  }
  for (Eigen::Index p = 0; p < points; ++p) {
    entries.emplace_back(voxels + p, p, options.point_weight);
    b[voxels + p] = double(options.point_weight) * point_raw[size_t(p)];
    guess[p] = point_raw[size_t(p)];
  }
  Eigen::SparseMatrix<double> a(voxels + points, points);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::LeastSquaresConjugateGradient<Eigen::SparseMatrix<double>> solver;
  solver.setMaxIterations(options.max_iterations);
  solver.setTolerance(options.tolerance);
  solver.compute(a);
  const Eigen::VectorXd x = solver.solveWithGuess(b, guess);
  std::vector<float> out(static_cast<size_t>(points));
  for (Eigen::Index p = 0; p < points; ++p) out[size_t(p)] = float(x[p]);
  return out;
}

}  // namespace lfd::voxel
