#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "render/image_metrics.hpp"
#include "util/error.hpp"

namespace lfd::render {
namespace {

ImageF noise_image(int w, int h, uint32_t seed) {
  ImageF img(w, h, 3);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (auto& v : img.pixels) v = u(rng);
  return img;
}

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnrAndUnitSsim) {
  const ImageF a = noise_image(32, 24, 1);
  EXPECT_TRUE(std::isinf(psnr(a, a)));
  EXPECT_NEAR(ssim(a, a), 1.0, 1e-12);
}

TEST(ImageMetrics, ConstantOffsetGivesKnownPsnrAndSsim) {
  const ImageF a(20, 20, 3, 0.5f), b(20, 20, 3, 0.6f);
  EXPECT_NEAR(psnr(a, b), 20.0, 1e-4);  // MSE = 0.01
  // Flat images: only the luminance term, (2 mu_x mu_y + C1) / (mu_x^2 + mu_y^2 + C1).
  const double c1 = 1e-4;
  EXPECT_NEAR(ssim(a, b), (2 * 0.5 * 0.6 + c1) / (0.25 + 0.36 + c1), 1e-6);
}

TEST(ImageMetrics, SsimDropsWithNoiseAndIsSymmetric) {
  const ImageF a = noise_image(40, 40, 2);
  ImageF b = a;
  std::mt19937 rng(3);
  std::normal_distribution<float> n(0.0f, 0.05f);
  for (auto& v : b.pixels) v += n(rng);
  const double s = ssim(a, b);
  EXPECT_LT(s, 0.99);
  EXPECT_GT(s, 0.5);
  EXPECT_NEAR(s, ssim(b, a), 1e-12);
  EXPECT_NEAR(psnr(a, b), 10.0 * std::log10(1.0 / (0.05 * 0.05)), 0.3);
}

TEST(ImageMetrics, SizeMismatchIsAnInputError) {
  EXPECT_THROW(psnr(ImageF(4, 4, 3), ImageF(4, 5, 3)), InputError);
  EXPECT_THROW(ssim(ImageF(4, 4, 3), ImageF(4, 4, 1)), InputError);
}

}  // namespace
}  // namespace lfd::render
