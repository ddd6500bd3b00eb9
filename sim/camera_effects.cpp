#include "sim/camera_effects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <opencv2/imgproc.hpp>

#include "util/error.hpp"

namespace lfd::sim {

namespace {

// cos^4-like fall-off: factor(r) = cos^4(atan(r * t)) with t chosen so that the image
// corner keeps 1 - vignetting.
void apply_vignetting(ImageF& image, const CameraIntrinsics& k, double vignetting) {
  if (vignetting <= 0) return;
  const double cx = k.camera_matrix(0, 2), cy = k.camera_matrix(1, 2);
  const double corner = std::hypot(std::max(cx, image.width - 1 - cx),
                                   std::max(cy, image.height - 1 - cy));
  const double t = std::sqrt(1.0 / std::sqrt(1.0 - vignetting) - 1.0) / std::max(corner, 1.0);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < image.height; ++y) {
    float* row = image.row(y);
    for (int x = 0; x < image.width; ++x) {
      const double r2 = (std::pow(x - cx, 2) + std::pow(y - cy, 2)) * t * t;
      const auto f = float(1.0 / ((1.0 + r2) * (1.0 + r2)));  // cos^4(atan(r t))
      for (int c = 0; c < image.channels; ++c) row[x * image.channels + c] *= f;
    }
  }
}

// Specular reflections of room lights: saturated discs with soft edges at random places,
// until `fraction` of the pixels is saturated.
void apply_glare(ImageF& image, double fraction, uint64_t seed) {
  if (fraction <= 0) return;
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  const double short_side = std::min(image.width, image.height);
  std::uniform_real_distribution<double> ux(0, image.width), uy(0, image.height),
      ur(0.01 * short_side, 0.05 * short_side);
  const long target = long(std::ceil(fraction * double(image.width) * image.height));
  std::vector<uint8_t> saturated(size_t(image.width) * image.height, 0);
  long count = 0;
  for (int blob = 0; blob < 100000 && count < target; ++blob) {
    const double bx = ux(rng), by = uy(rng), r = std::max(1.0, ur(rng));
    const int x0 = std::max(0, int(bx - 2 * r)), x1 = std::min(image.width - 1, int(bx + 2 * r));
    const int y0 = std::max(0, int(by - 2 * r)), y1 = std::min(image.height - 1, int(by + 2 * r));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double d = std::hypot(x - bx, y - by) / r;
        // Core far above full scale (clips to white), Gaussian halo around it.
        const auto g = float(4.0 * std::exp(-0.5 * d * d * 4.0));
        for (int c = 0; c < image.channels; ++c) {
          float& p = image.at(x, y, c);
          p = std::max(p, p + g);
        }
        if (g >= 1.0f && !saturated[size_t(y) * image.width + x]) {
          saturated[size_t(y) * image.width + x] = 1;
          ++count;
        }
      }
  }
}

// Rolling-shutter banding: each row's gain, with the photo's own phase of the flicker.
void apply_flicker(ImageF& image, double amplitude, double bands, uint64_t seed) {
  if (amplitude <= 0) return;
  std::mt19937_64 rng(seed ^ 0x94d049bb133111ebULL);
  const double phase = std::uniform_real_distribution<double>(0, 1)(rng);
  const double two_pi = 2.0 * std::numbers::pi;
  for (int y = 0; y < image.height; ++y) {
    const auto g = float(1.0 + amplitude * std::sin(two_pi * (bands * y / image.height + phase)));
    float* row = image.row(y);
    for (int i = 0; i < image.width * image.channels; ++i) row[i] *= g;
  }
}

// Gaussian read/shot noise; each row has its own generator seeded from (seed, row), so the
// result does not depend on the number of threads.
void apply_noise(ImageF& image, double sigma, uint64_t seed) {
  if (sigma <= 0) return;
#pragma omp parallel for schedule(static)
  for (int y = 0; y < image.height; ++y) {
    std::mt19937_64 rng(seed * 0x100000001b3ULL + uint64_t(y) * 0xbf58476d1ce4e5b9ULL + 1);
    std::normal_distribution<float> noise(0.0f, float(sigma));
    float* row = image.row(y);
    for (int i = 0; i < image.width * image.channels; ++i) row[i] += noise(rng);
  }
}

}  // namespace

void check_effects(const CaptureEffects& e) {
  auto bad = [](bool ok, const char* field, double v, const char* need) {
    if (!ok) throw_input_error("capture effects: {}: {} ({})", field, v, need);
  };
  bad(std::isfinite(e.psf_sigma_phase) && e.psf_sigma_phase >= 0 && e.psf_sigma_phase < 1,
      "psf", e.psf_sigma_phase, "lens periods, 0 <= psf < 1");
  bad(std::isfinite(e.blur_px) && e.blur_px >= 0 && e.blur_px <= 100, "blur", e.blur_px,
      "pixels, 0 to 100");
  bad(std::isfinite(e.noise_sigma) && e.noise_sigma >= 0 && e.noise_sigma <= 1, "noise",
      e.noise_sigma, "fraction of full scale, 0 to 1");
  bad(std::isfinite(e.vignetting) && e.vignetting >= 0 && e.vignetting < 1, "vignetting",
      e.vignetting, "0 <= vignetting < 1");
  bad(std::isfinite(e.gamma) && e.gamma > 0 && e.gamma <= 10, "gamma", e.gamma, "0 < gamma <= 10");
  bad(std::isfinite(e.exposure) && e.exposure > 0, "exposure", e.exposure, "must be > 0");
  bad(std::isfinite(e.exposure_drift) && e.exposure_drift >= 0 && e.exposure_drift <= 0.2,
      "exposure drift", e.exposure_drift, "relative 1-sigma, 0 to 0.2");
  bad(std::isfinite(e.flicker_amplitude) && e.flicker_amplitude >= 0 && e.flicker_amplitude <= 0.2,
      "flicker amplitude", e.flicker_amplitude, "relative, 0 to 0.2");
  bad(std::isfinite(e.flicker_bands) && e.flicker_bands > 0 && e.flicker_bands <= 100,
      "flicker bands", e.flicker_bands, "bands over the image height, 0 < bands <= 100");
  bad(std::isfinite(e.glare_fraction) && e.glare_fraction >= 0 && e.glare_fraction <= 0.5,
      "glare", e.glare_fraction, "fraction of pixels, 0 to 0.5");
  bad(std::isfinite(e.colour_crosstalk) && e.colour_crosstalk >= 0 && e.colour_crosstalk < 0.25,
      "colour crosstalk", e.colour_crosstalk, "fraction per other channel, 0 to 0.25");
  bad(e.supersample >= 1 && e.supersample <= 16, "supersample", e.supersample, "1 to 16");
}

void apply_camera_effects(ImageF& image, const CameraIntrinsics& intrinsics,
                          const CaptureEffects& e) {
  if (e.exposure != 1.0)
    for (float& p : image.pixels) p *= float(e.exposure);
  if (e.colour_crosstalk > 0 && image.channels == 3) {
    const float x = float(e.colour_crosstalk), d = 1.0f - 2.0f * x;
    cv::Mat m(image.height, image.width, CV_32FC3, image.pixels.data());
    cv::transform(m, m, cv::Matx33f(d, x, x, x, d, x, x, x, d));
  }
  if (e.blur_px > 0) {
    cv::Mat m(image.height, image.width, CV_32FC(image.channels), image.pixels.data());
    cv::GaussianBlur(m, m, cv::Size(0, 0), e.blur_px, e.blur_px, cv::BORDER_REFLECT);
  }
  apply_vignetting(image, intrinsics, e.vignetting);
  apply_glare(image, e.glare_fraction, e.glare_seed ? e.glare_seed : e.seed);
  // A drifting exposure scales all the light the sensor gathers, the glare's too.
  if (e.exposure_drift > 0) {
    std::mt19937_64 rng(e.seed ^ 0xd1b54a32d192ed03ULL);
    const double drift =
        std::max(0.2, 1.0 + e.exposure_drift * std::normal_distribution<double>()(rng));
    for (float& p : image.pixels) p *= float(drift);
  }
  apply_flicker(image, e.flicker_amplitude, e.flicker_bands, e.seed);
  apply_noise(image, e.noise_sigma, e.seed);
  const float inv_gamma = float(1.0 / e.gamma);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < long(image.pixels.size()); ++i) {
    float p = std::max(image.pixels[i], 0.0f);
    if (inv_gamma != 1.0f) p = std::pow(p, inv_gamma);
    // The sensor clips and the file stores 8 bits.
    image.pixels[i] = std::round(std::min(p, 1.0f) * 255.0f) / 255.0f;
  }
}

}  // namespace lfd::sim
