#include "display/correction_field.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "util/error.hpp"

namespace lfd::display {
namespace {

TEST(BSpline, WeightsArePositiveAndSumToOne) {
  for (int n : {4, 5, 9})
    for (double t = 0; t <= 1.0; t += 0.01) {
      const auto w = bspline_weights(n, t);
      EXPECT_GE(w.i0, 0);
      EXPECT_LE(w.i0 + 3, n - 1);
      double sum = 0;
      for (double x : w.w) {
        EXPECT_GE(x, 0);
        sum += x;
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
    }
}

TEST(BSpline, ReproducesLinearFunctionsExactly) {
  // Uniform cubic B-splines reproduce affine functions when control points sample them at
  // the Greville abscissae.
  const int nx = 7, ny = 6;
  std::vector<double> c(nx * ny);
  auto greville = [](int i, int n) { return (i - 1.0) / (n - 3.0); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) c[j * nx + i] = 0.2 * greville(i, nx) - 0.1 * greville(j, ny) + 0.03;
  const CorrectionField w(nx, ny, c);
  for (double u : {0.0, 0.13, 0.5, 0.91, 1.0})
    for (double v : {0.0, 0.4, 1.0}) EXPECT_NEAR(w(u, v), 0.2 * u - 0.1 * v + 0.03, 1e-12);
}

TEST(CorrectionField, EmptyFieldIsZero) {
  const CorrectionField w;
  EXPECT_EQ(w(0.3, 0.4), 0.0);
  EXPECT_EQ(w.range()[0], 0.0);
}

TEST(CorrectionField, JsonRoundTrip) {
  std::vector<double> c(16);
  for (int i = 0; i < 16; ++i) c[i] = std::sin(i);
  const CorrectionField w(4, 4, c);
  const CorrectionField r = CorrectionField::from_json(w.to_json(), "x");
  EXPECT_EQ(r.coefficients(), c);
  EXPECT_DOUBLE_EQ(r(0.31, 0.77), w(0.31, 0.77));
}

TEST(CorrectionField, RejectsNonFiniteCoefficients) {
  auto j = CorrectionField::zeros(4, 4).to_json();
  j["coefficients"][3] = "nan";
  EXPECT_THROW(CorrectionField::from_json(j, "f.json"), InputError);
}

}  // namespace
}  // namespace lfd::display
