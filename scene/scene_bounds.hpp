#pragma once
// A robust axis-aligned box around a scene: per-axis quantiles of the Gaussian centres, so a
// few far-away floaters (common in trained scenes) or a background shell do not decide how a
// default camera frames the scene.
#include <array>

#include "scene/gaussian_scene.hpp"

namespace lfd::scene {

struct SceneBounds {
  std::array<float, 3> min{0, 0, 0};
  std::array<float, 3> max{0, 0, 0};

  std::array<float, 3> center() const;
  std::array<float, 3> extent() const;  // max - min per axis
  float radius() const;                 // half the diagonal
};

// Per-axis [lower_quantile, upper_quantile] of the positions (defaults: 1st-99th percentile).
// Large scenes are subsampled deterministically (at most ~1M centres). An empty scene gives
// an all-zero box.
SceneBounds robust_bounds(const GaussianScene& scene, double lower_quantile = 0.01,
                          double upper_quantile = 0.99);

// The box of the content a viewer looks at: per-axis opacity-weighted quantiles (default
// 5-95% of the opacity) of the centres of the Gaussians with opacity at least `min_opacity`.
// Faint haze, floaters and a backdrop that holds a small share of the opacity fall outside it.
// Subsampled like robust_bounds; an empty scene (or one without such Gaussians) gives a zero box.
SceneBounds content_bounds(const GaussianScene& scene, double lower_quantile = 0.05,
                           double upper_quantile = 0.95, float min_opacity = 0.1f);

// The exact min/max of all centres (not subsampled).
SceneBounds exact_bounds(const GaussianScene& scene);

}  // namespace lfd::scene
