#include "calib/decoding/colour_order.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "display/lens_model.hpp"

namespace lfd::calib {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

double wrap_half(double x) { return x - std::floor(x + 0.5); }

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Robust sigma of the values about m: 1.4826 times the median absolute deviation.
double robust_sigma(const std::vector<double>& v, double m) {
  std::vector<double> dev;
  dev.reserve(v.size());
  for (double x : v) dev.push_back(std::abs(x - m));
  return 1.4826 * median(std::move(dev));
}

std::array<double, 2> differences(const std::array<double, 3>& o) {
  return {wrap_half(o[0] - o[1]), wrap_half(o[2] - o[1])};
}

double distance(const std::array<double, 2>& a, const std::array<double, 2>& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1]);
}

}  // namespace

std::string SubpixelLayout::describe(const display::DisplayCalibration& description) const {
  if (cells)
    return fmt::format("the description's subpixel cells (CellPatternMode {}, {} cells)",
                       description.cell_pattern_mode, description.subpixel_cells.size());
  return flip_subp ? "flipSubp 1 (BGR stripes)" : "flipSubp 0 (RGB stripes)";
}

std::string SubpixelLayout::option() const {
  if (cells) return "no --flip-subp (the description's subpixel cells)";
  return flip_subp ? "--flip-subp 1" : "--flip-subp 0";
}

display::DisplayCalibration SubpixelLayout::apply(const display::DisplayCalibration& description) const {
  display::DisplayCalibration d = description;
  if (!cells) {
    d.subpixel_cells.clear();
    d.cell_pattern_mode = 0;
    d.flip_subp = flip_subp;
  }
  return d;
}

std::vector<SubpixelLayout> candidate_layouts(const display::DisplayCalibration& description) {
  std::vector<SubpixelLayout> out{{false, false}, {false, true}};
  if (description.has_cells()) out.insert(out.begin(), {true, false});
  return out;
}

std::array<double, 3> predicted_channel_offsets(const display::DisplayCalibration& pattern,
                                                const SubpixelLayout& layout) {
  const display::LensModel drawn(pattern);
  const display::LensModel real(layout.apply(pattern));
  // psi is the view fraction, which runs against the phase under invView.
  const double sign = pattern.inv_view ? -1.0 : 1.0;
  std::array<double, 3> out{};
  for (int c = 0; c < 3; ++c) {
    // Every cell pattern repeats within 2 columns x 4 rows (docs/display-model.md "Vendor
    // interlacing rules"); a block of camera pixels sees all of them, so its phasor is their mean.
    std::complex<double> sum(0, 0);
    for (int row = 0; row < 4; ++row)
      for (int x = 0; x < 2; ++x) {
        const double d = drawn.phase(drawn.subpixel_uv(x, row, c)) -
                         drawn.phase(real.subpixel_uv(x, row, c));
        sum += std::polar(1.0, kTwoPi * sign * d);
      }
    out[size_t(c)] = std::arg(sum) / kTwoPi;
  }
  return out;
}

namespace {

using Candidate = ColourOrderCheck::Candidate;

// Measure: the medians of every position's R - G and B - G offsets and their standard errors;
// false when the photos hold too few samples to tell.
bool measure_channel_offsets(const std::vector<const DecodedPhase*>& positions, ColourOrderCheck& out) {
  std::array<std::vector<double>, 2> diff;
  std::array<std::vector<double>, 3> channel;
  for (const DecodedPhase* p : positions)
    for (const ChannelPhase& ch : p->channels) {
      std::array<double, 3> o{ch.offset_periods[0], ch.offset_periods[1], ch.offset_periods[2]};
      const auto d = differences(o);
      for (int i = 0; i < 2; ++i) diff[size_t(i)].push_back(d[size_t(i)]);
      for (int c = 0; c < 3; ++c) channel[size_t(c)].push_back(o[size_t(c)]);
    }
  out.samples = long(diff[0].size());
  if (out.samples < 100) {
    out.finding = "too few phase samples to check the colour order";
    return false;
  }
  for (int i = 0; i < 2; ++i) {
    out.measured_periods[size_t(i)] = median(diff[size_t(i)]);
    out.spread_periods[size_t(i)] = robust_sigma(diff[size_t(i)], out.measured_periods[size_t(i)]);
    // Standard error of a median: 1.2533 sigma / sqrt(n).
    out.sigma_periods[size_t(i)] =
        1.2533 * out.spread_periods[size_t(i)] / std::sqrt(double(out.samples));
  }
  for (int c = 0; c < 3; ++c) out.channel_offsets_periods[size_t(c)] = median(channel[size_t(c)]);
  return true;
}

// Rank: the pattern's own layout predicts no offsets; every other one its displacements. Each
// candidate's miss is its distance from the measured offsets.
void rank_layouts(const display::DisplayCalibration& pattern, const SubpixelLayout& given, ColourOrderCheck& out) {
  std::vector<SubpixelLayout> layouts = candidate_layouts(pattern);
  if (std::find(layouts.begin(), layouts.end(), given) == layouts.end()) layouts.push_back(given);
  for (const SubpixelLayout& l : layouts) {
    Candidate c;
    c.layout = l;
    c.predicted_periods = differences(predicted_channel_offsets(pattern, l));
    c.miss_periods = distance(out.measured_periods, c.predicted_periods);
    out.candidates.push_back(c);
  }
}

// The finding in words: agreement, a lean too weak to refuse, or a disagreement that refuses
// the calibration unless the best layout is adopted (options.estimate).
void word_finding(const display::DisplayCalibration& pattern, const SubpixelLayout& given,
                  const ColourOrderOptions& options, const Candidate& given_c,
                  const Candidate& best_c, ColourOrderCheck& out) {
  const std::string measured = fmt::format("R - G {:+.3f}, B - G {:+.3f} lens periods",
                                           out.measured_periods[0], out.measured_periods[1]);
  auto predicted = [](const Candidate& c) {
    return fmt::format("{:+.3f}, {:+.3f}", c.predicted_periods[0], c.predicted_periods[1]);
  };
  if (!out.photos_disagree && out.best == given) {
    out.finding = fmt::format("colour order: the photos agree with {} ({} measured, {} predicted)",
                              given.describe(pattern), measured, predicted(given_c));
    return;
  }
  if (!out.photos_disagree) {
    // Nearer, but not clearly (strong camera colour crosstalk dilutes the offsets): said, not
    // refused, since unmodelled channel differences must not refuse a right layout.
    out.finding = fmt::format(
        "colour order: the photos lean toward {} over the given {} ({} measured; predicted {} "
        "and {}), too little to refuse: check the panel's subpixel order",
        out.best.describe(pattern), given.describe(pattern), measured, predicted(best_c),
        predicted(given_c));
    return;
  }
  const bool both_classic = !given.cells && !out.best.cells;
  const std::string what =
      both_classic ? fmt::format("flipSubp is {}, the photos say {}", int(given.flip_subp),
                                 int(out.best.flip_subp))
                   : fmt::format("the subpixel layout is {}, the photos say {}",
                                 given.describe(pattern), out.best.describe(pattern));
  const std::string evidence = fmt::format("{} measured; {} predicts {}, {} predicts {}", measured,
                                           given.describe(pattern), predicted(given_c),
                                           out.best.describe(pattern), predicted(best_c));
  if (options.estimate) {
    out.adopted = out.best;
    out.finding = fmt::format("colour order: {}; adopted ({})", what, evidence);
  } else {
    out.finding = fmt::format("{}: rerun with {}, or with --estimate-colour-order ({})", what,
                              out.best.option(), evidence);
  }
}

}  // namespace

ColourOrderCheck compare_subpixel_layouts(const display::DisplayCalibration& pattern,
                                          const SubpixelLayout& given,
                                          const std::vector<const DecodedPhase*>& positions,
                                          const ColourOrderOptions& options) {
  ColourOrderCheck out;
  out.drawn = pattern;
  out.pattern = SubpixelLayout::of(pattern);
  out.given = out.best = out.adopted = given;
  if (!measure_channel_offsets(positions, out)) return out;
  rank_layouts(pattern, given, out);
  const Candidate* given_c = nullptr;
  const Candidate* best_c = nullptr;
  for (const auto& c : out.candidates) {
    if (c.layout == given) given_c = &c;
    if (!best_c || c.miss_periods < best_c->miss_periods) best_c = &c;
  }
  out.best = best_c->layout;
  // Decide: the photos disagree only when the given layout misses by many standard errors and
  // clearly more than the best one (ColourOrderOptions).
  const double sigma = std::hypot(out.sigma_periods[0], out.sigma_periods[1]);
  const double separation = distance(given_c->predicted_periods, best_c->predicted_periods);
  out.photos_disagree =
      !(out.best == given) && given_c->miss_periods > options.min_sigmas * sigma &&
      given_c->miss_periods - best_c->miss_periods > options.min_margin_fraction * separation;
  word_finding(pattern, given, options, *given_c, *best_c, out);
  return out;
}

void correct_for_layout(const ColourOrderCheck& check, const display::DisplayCalibration& pattern,
                        const DecodedPhase& phase, std::vector<PhaseSample>& samples) {
  if (check.adopted == check.pattern || phase.channels.size() != samples.size()) return;
  const std::array<double, 3> shift = predicted_channel_offsets(pattern, check.adopted);
  for (size_t i = 0; i < samples.size(); ++i)
    samples[i].psi = float(reweighted_phase(samples[i].psi, phase.channels[i], shift));
}

nlohmann::ordered_json to_json(const ColourOrderCheck& check) {
  const display::DisplayCalibration& pattern = check.drawn;
  nlohmann::ordered_json candidates = nlohmann::ordered_json::array();
  for (const auto& c : check.candidates)
    candidates.push_back({{"layout", c.layout.describe(pattern)},
                          {"predicted_r_minus_g_b_minus_g_periods", c.predicted_periods},
                          {"miss_periods", c.miss_periods}});
  return {{"samples", check.samples},
          {"measured_r_minus_g_b_minus_g_periods", check.measured_periods},
          {"sigma_periods", check.sigma_periods},
          {"spread_periods", check.spread_periods},
          {"channel_offsets_rgb_periods", check.channel_offsets_periods},
          {"candidates", candidates},
          {"patterns_drawn_for", check.pattern.describe(pattern)},
          {"given", check.given.describe(pattern)},
          {"best", check.best.describe(pattern)},
          {"photos_disagree", check.photos_disagree},
          {"adopted", check.adopted.describe(pattern)},
          {"finding", check.finding}};
}

}  // namespace lfd::calib
