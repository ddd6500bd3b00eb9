#include "calib/solver/quality_gates.hpp"

#include <cmath>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::calib {

void QualityGates::check() const {
  const std::string where = "quality gates";
  for (auto [value, field] : {std::pair{max_residual_rms_periods, "max_residual_rms_periods"},
                              {max_camera_shift_sigmas, "max_camera_shift_sigmas"},
                              {max_position_rms_ratio, "max_position_rms_ratio"},
                              {max_pitch_sigma_rel, "max_pitch_sigma_rel"},
                              {max_slant_sigma_deg, "max_slant_sigma_deg"},
                              {max_center_sigma_periods, "max_center_sigma_periods"},
                              {max_view_cone_sigma_deg, "max_view_cone_sigma_deg"},
                              {max_correction_sigma_periods, "max_correction_sigma_periods"},
                              {max_cover_disagreement_sigmas, "max_cover_disagreement_sigmas"}})
    require_field(value > 0 && !std::isnan(value), where, field, "must be a positive bound");
  require_field(min_inlier_fraction >= 0 && min_inlier_fraction <= 1, where,
                "min_inlier_fraction", "must lie in [0, 1]");
}

std::vector<std::string> QualityGates::evaluate(const display::Calibration& c,
                                                const SolverResult& solve) const {
  std::vector<std::string> fails;
  const display::ResidualStats& r = solve.residuals;
  auto sigma = [&](const char* key) {
    auto it = solve.sigma.find(key);
    return it == solve.sigma.end() ? INFINITY : it->second;
  };
  auto position_name = [&](size_t i) {
    return i < solve.position_names.size() && !solve.position_names[i].empty()
               ? "position " + solve.position_names[i]
               : fmt::format("position {}", i + 1);
  };
  if (!solve.converged)
    fails.push_back(fmt::format("the solver did not converge ({}; CONVERGENCE needed): check "
                                "the display description and the photos, or raise "
                                "solver.max_iterations",
                                solve.termination.empty() ? "no final stage" : solve.termination));
  if (r.rms_periods > max_residual_rms_periods)
    fails.push_back(fmt::format("phase residual rms {:.3f} > {:.3f} lens periods (all samples, "
                                "robust): focus on the screen, avoid glare, check the exposure "
                                "and the display description",
                                r.rms_periods, max_residual_rms_periods));
  if (r.inlier_fraction < min_inlier_fraction)
    fails.push_back(fmt::format("only {:.0f} % of the phase samples fit the model (>= {:.0f} % "
                                "needed): glare, reflections or a wrong display description",
                                100 * r.inlier_fraction, 100 * min_inlier_fraction));
  for (size_t i = 0; i < solve.camera_shift_sigmas.size(); ++i)
    if (solve.camera_shift_sigmas[i] > max_camera_shift_sigmas)
      fails.push_back(fmt::format("{}: the solve moved the camera {:.1f} sigmas from its "
                                  "registered position (<= {:.1f}): the camera moved between the "
                                  "photos or the board is misregistered; photograph it again",
                                  position_name(i), solve.camera_shift_sigmas[i],
                                  max_camera_shift_sigmas));
  for (size_t i = 0; i < solve.position_rms_ratio.size(); ++i)
    if (solve.position_rms_ratio[i] > max_position_rms_ratio)
      fails.push_back(fmt::format("{}: residual rms {:.4f} lens periods is {:.1f} times that of "
                                  "the other positions (<= {:.1f}): its photos disagree with "
                                  "them (camera moved, glare, focus); photograph it again",
                                  position_name(i), solve.position_rms[i],
                                  solve.position_rms_ratio[i], max_position_rms_ratio));
  if (!solve.view_cone_fitted && !c.view_cone_measured_deg)
    fails.push_back("the view cone was neither measured nor known (one camera position): the "
                    "pitch absorbs its error; photograph from a second distance, or give the "
                    "cone (--view-cone, or a template whose view_cone_measured_deg is set)");
  if (sigma("pitch_lpi") / c.display.pitch_lpi > max_pitch_sigma_rel)
    fails.push_back(fmt::format("pitch uncertainty {:.1e} (relative) > {:.1e}: photograph the "
                                "whole screen from closer, or add positions",
                                sigma("pitch_lpi") / c.display.pitch_lpi, max_pitch_sigma_rel));
  if (auto it = c.uncertainty.find("slant_deg");
      it != c.uncertainty.end() && it->second > max_slant_sigma_deg)
    fails.push_back(fmt::format("slant uncertainty {:.4f} deg > {:.4f}: photograph the whole "
                                "screen, sharper",
                                it->second, max_slant_sigma_deg));
  if (sigma("center_periods") > max_center_sigma_periods)
    fails.push_back(fmt::format("center uncertainty {:.4f} > {:.4f} lens periods: add camera "
                                "positions and give an accurate --camera calibration",
                                sigma("center_periods"), max_center_sigma_periods));
  if (c.view_cone_measured_deg && sigma("view_cone_deg") > max_view_cone_sigma_deg)
    fails.push_back(fmt::format("view cone uncertainty {:.2f} deg > {:.2f}: photograph from "
                                "positions at clearly different distances (e.g. 0.8x and 1.25x)",
                                sigma("view_cone_deg"), max_view_cone_sigma_deg));
  if (sigma("correction_rms_periods") > max_correction_sigma_periods && !c.correction.empty())
    fails.push_back(fmt::format("correction field uncertainty {:.3f} > {:.3f} lens periods: "
                                "photograph the whole screen, in focus",
                                sigma("correction_rms_periods"), max_correction_sigma_periods));
  if (const CoverEstimate& cover = solve.cover;
      cover.free && cover.disagreement_sigmas > max_cover_disagreement_sigmas)
    fails.push_back(fmt::format(
        "the photos contradict the cover given ({:.1f} +- {:.1f} mm): they say {:.1f} +- {:.1f} "
        "mm, {:.1f} sigmas apart (<= {:.1f}); give the cover's thickness (--cover-thickness) or "
        "--cover-unknown",
        1e3 * cover.prior_m, 1e3 * cover.prior_sigma_m, 1e3 * cover.photos_m,
        1e3 * cover.photos_sigma_m, cover.disagreement_sigmas, max_cover_disagreement_sigmas));
  return fails;
}

}  // namespace lfd::calib
