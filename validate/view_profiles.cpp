#include "validate/view_profiles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "sim/simulator.hpp"
#include "display/view_count.hpp"
#include "interlace/interlacer.hpp"
#include "render/quilt_layout.hpp"
#include "util/error.hpp"

namespace lfd::validate {

namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
// Encoding of a view in the index quilt: view j -> (j + 1) / 255, 0 stays black.
constexpr int kMaxViews = 254;

// A quilt whose tile j holds the constant (j + 1) / 255: interlacing it once tells, for every
// subpixel, which view the interlacer shows there. With nearest-view interlacing the panel of
// "tile j white, others black" is exactly the set of subpixels showing j, so one pass through
// the interlacer replaces V + 1 passes with identical results.
render::QuiltLayout index_layout(int views, double aspect) {
  render::QuiltLayout layout;
  layout.cols = int(std::ceil(std::sqrt(double(views))));
  layout.rows = (views + layout.cols - 1) / layout.cols;
  layout.views = views;
  layout.aspect = aspect;
  layout.width = layout.cols * 8;  // uniform tiles: a few texels are enough
  layout.height = layout.rows * 8;
  return layout;
}

std::vector<uint8_t> interlaced_views(const display::Calibration& assumed, int views) {
  display::DisplayCalibration display = assumed.display;
  display.fringe = 0.0;  // row darkening would corrupt the encoding; it is 0 on real units
  const display::LensModel lens(display, assumed.correction);
  const render::QuiltLayout layout =
      index_layout(views, double(display.screen_w) / display.screen_h);
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  for (int v = 0; v < views; ++v)
    for (int y = 0; y < layout.tile_height(); ++y)
      for (int x = 0; x < layout.tile_width(); ++x)
        for (int c = 0; c < 3; ++c)
          quilt.at(layout.tile_x(v) + x, layout.tile_y_top_down(v) + y, c) = float(v + 1) / 255.0f;
  const ImageF panel = interlace::interlace(quilt, layout, lens);  // nearest view
  std::vector<uint8_t> index(panel.pixels.size());
  for (size_t i = 0; i < index.size(); ++i)
    index[i] = uint8_t(std::clamp(panel.pixels[i] * 255.0f + 0.5f, 0.0f, 255.0f));
  return index;
}

// Linear view blending splits a subpixel between views a and b: the interlacer's own
// per-subpixel choice (Interlacer::sample_for), applied to "tile j white, others black".
struct BlendedViews {
  std::vector<uint8_t> a, b;  // view + 1; 0 = black (outside the quilt area)
  std::vector<float> weight_b;
};

BlendedViews blended_views(const display::Calibration& assumed, int views) {
  const auto& d = assumed.display;
  const display::LensModel lens(d, assumed.correction);
  interlace::InterlaceOptions options;
  options.blend = interlace::ViewBlend::kLinear;
  const interlace::Interlacer interlacer(
      lens, index_layout(views, double(d.screen_w) / d.screen_h), options);
  const size_t n = size_t(d.screen_w) * d.screen_h * 3;
  BlendedViews out{std::vector<uint8_t>(n, 0), std::vector<uint8_t>(n, 0), std::vector<float>(n, 0)};
#pragma omp parallel for schedule(dynamic, 8)
  for (int row = 0; row < d.screen_h; ++row)
    for (int x = 0; x < d.screen_w; ++x)
      for (int c = 0; c < 3; ++c) {
        const interlace::SubpixelSample s = interlacer.sample_for(x, row, c);
        if (!s.inside) continue;
        const size_t i = (size_t(row) * d.screen_w + x) * 3 + c;
        out.a[i] = uint8_t(s.view_a + 1);
        out.b[i] = uint8_t(s.view_b + 1);
        out.weight_b[i] = s.weight_b;
      }
  return out;
}

// Jittered grid over the central `fraction` of the panel, in metres (display frame).
std::vector<Eigen::Vector3d> panel_points(const display::DisplayCalibration& d, int count,
                                          double fraction, uint64_t seed) {
  const double aspect = d.width_m() / d.height_m();
  const int nx = std::max(1, int(std::lround(std::sqrt(count * aspect))));
  const int ny = std::max(1, (count + nx - 1) / nx);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> jitter(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int iy = 0; iy < ny; ++iy)
    for (int ix = 0; ix < nx; ++ix) {
      const double u = (ix + jitter(rng)) / nx, v = (iy + jitter(rng)) / ny;
      points.emplace_back((u - 0.5) * fraction * d.width_m(), (v - 0.5) * fraction * d.height_m(),
                          0.0);
    }
  return points;
}

// The subpixels of each view, so a pass switches on only its own (a panel is 25M values).
std::vector<std::vector<uint32_t>> subpixels_of_views(const std::vector<uint8_t>& index, int views) {
  std::vector<std::vector<uint32_t>> subpixels_of(views);
  for (auto& list : subpixels_of) list.reserve(index.size() / views + 1024);
  for (size_t i = 0; i < index.size(); ++i)
    if (index[i] >= 1 && index[i] <= views) subpixels_of[index[i] - 1].push_back(uint32_t(i));
  return subpixels_of;
}

// One pass's profile: the luminance an eye in each direction sees, averaged over the panel
// points.
std::vector<double> mean_luminance_profile(const sim::DisplaySimulator& simulator, const ImageF& panel,
                                           const std::vector<Eigen::Vector3d>& points,
                                           const std::vector<Eigen::Vector3d>& offsets,
                                           const std::optional<double>& eye_height_m,
                                           double psf_sigma_phase) {
  const int angles = int(offsets.size());
  std::vector<double> profile(angles, 0.0);
#pragma omp parallel
  {
    std::vector<double> local(angles, 0.0);
#pragma omp for schedule(dynamic, 8)
    for (long p = 0; p < long(points.size()); ++p)
      for (int k = 0; k < angles; ++k) {
        Eigen::Vector3d eye = points[p] + offsets[k];
        if (eye_height_m) eye.y() = *eye_height_m;
        const auto r = simulator.radiance(panel, points[p], eye, psf_sigma_phase);
        // Luminance (Rec. 709 luma of linear RGB): a white panel reads 1.
        local[k] += 0.2126 * r[0] + 0.7152 * r[1] + 0.0722 * r[2];
      }
#pragma omp critical
    for (int k = 0; k < angles; ++k) profile[k] += local[k];
  }
  for (double& l : profile) l /= double(points.size());
  return profile;
}

}  // namespace

void ProfileOptions::check() const {
  if (views != 0 && (views < 2 || views > kMaxViews))
    throw_input_error("views: {} (expected 2 to {})", views, kMaxViews);
  if (!(distance_m > 0.01 && distance_m < 100))
    throw_input_error("distance: {} m (expected 0.01 to 100)", distance_m);
  if (eye_height_m && !(std::abs(*eye_height_m) < 100))
    throw_input_error("eye height: {} m (expected -100 to 100)", *eye_height_m);
  if (angles_per_view < 1 || angles_per_view > 100)
    throw_input_error("angles per view: {} (expected 1 to 100)", angles_per_view);
  if (panel_points < 1 || panel_points > 1000000)
    throw_input_error("panel points: {} (expected 1 to 1000000)", panel_points);
  if (!(region_fraction > 0 && region_fraction <= 1))
    throw_input_error("region: {} (expected a fraction in (0, 1])", region_fraction);
  if (!(psf_sigma_phase < 1)) throw_input_error("psf: {} lens periods (expected < 1)", psf_sigma_phase);
}

ViewProfiles measure_view_profiles(const display::Calibration& truth,
                                   const display::Calibration& assumed,
                                   const ProfileOptions& options, Progress* progress) {
  options.check();
  const auto& d = truth.display;
  const auto& a = assumed.display;
  if (a.screen_w != d.screen_w || a.screen_h != d.screen_h)
    throw_input_error("assumed calibration: screen size {}x{} differs from the true {}x{}",
                      a.screen_w, a.screen_h, d.screen_w, d.screen_h);
  ViewProfiles out;
  out.views = options.views > 0
                  ? options.views
                  : std::min(kMaxViews, display::recommend_view_count(truth).views);
  out.distance_m = options.distance_m;
  out.eye_height_m = options.eye_height_m;
  out.psf_sigma_phase = options.psf_sigma_phase >= 0
                            ? options.psf_sigma_phase
                            : truth.phase_blur_sigma.value_or(display::kDefaultPhaseBlurSigma);

  // Directions uniformly across the cone (its edges excluded: there the views wrap).
  const int angles = out.views * options.angles_per_view;
  const double half_cone = 0.5 * d.view_cone_deg;
  for (int k = 0; k < angles; ++k)
    out.theta_deg.push_back(-half_cone + d.view_cone_deg * (k + 0.5) / angles);

  out.blend = options.blend;
  const bool linear = options.blend == interlace::ViewBlend::kLinear;
  const std::vector<uint8_t> index = linear ? std::vector<uint8_t>{}
                                            : interlaced_views(assumed, out.views);
  const BlendedViews blended = linear ? blended_views(assumed, out.views) : BlendedViews{};
  const sim::DisplaySimulator simulator{display::LensModel(d, truth.correction)};
  const auto points = panel_points(d, options.panel_points, options.region_fraction, options.seed);
  out.panel_points = int(points.size());

  // Eyes at distance D from each point in direction theta, level with it unless a height is
  // given.
  std::vector<Eigen::Vector3d> offsets;
  for (double t : out.theta_deg)
    offsets.emplace_back(options.distance_m * std::sin(t * kDegToRad), 0.0,
                         options.distance_m * std::cos(t * kDegToRad));

  const std::vector<std::vector<uint32_t>> subpixels_of = subpixels_of_views(index, out.views);

  ImageF panel(d.screen_w, d.screen_h, 3, 0.0f);
  out.view.assign(out.views, std::vector<double>(angles, 0.0));
  // Pass j < views: tile j white; pass `views`: the all-black quilt (L_K).
  for (int pass = 0; pass <= out.views; ++pass) {
    if (linear) {
      const uint8_t lit = uint8_t(pass + 1);  // matches nothing on the black pass
#pragma omp parallel for schedule(static)
      for (long i = 0; i < long(panel.pixels.size()); ++i)
        panel.pixels[i] = (blended.a[i] == lit ? 1.0f - blended.weight_b[i] : 0.0f) +
                          (blended.b[i] == lit ? blended.weight_b[i] : 0.0f);
    } else {
      if (pass > 0)
        for (uint32_t i : subpixels_of[pass - 1]) panel.pixels[i] = 0.0f;
      if (pass < out.views)
        for (uint32_t i : subpixels_of[pass]) panel.pixels[i] = 1.0f;
    }
    std::vector<double> profile =
        mean_luminance_profile(simulator, panel, points, offsets, options.eye_height_m, out.psf_sigma_phase);
    if (pass < out.views)
      out.view[pass] = std::move(profile);
    else
      out.black = std::move(profile);
    if (progress) progress->advance();
  }
  return out;
}

}  // namespace lfd::validate
