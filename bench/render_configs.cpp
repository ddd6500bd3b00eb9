#include "bench/render_configs.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::bench {

using render::PlaneFilter;
using render::PlanePrecision;

const std::vector<G2lfConfig>& g2lf_configs() {
  static const std::vector<G2lfConfig> configs = {
      {"G2LF (N=64)", "table1", 64, 1, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=64, Ps=2)", "table1", 64, 2, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=512)", "table1", 512, 1, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=512, Bi.)", "table1", 512, 1, PlaneFilter::kBilinear, PlanePrecision::kU8},
      {"G2LF (N=512, Ps=2)", "table1", 512, 2, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=512, Ps=2, Bi.)", "table1", 512, 2, PlaneFilter::kBilinear, PlanePrecision::kU8},
      {"G2LF (N=512, Ps=3, Bi.)", "table1", 512, 3, PlaneFilter::kBilinear, PlanePrecision::kU8},
      {"G2LF (N=128)", "chunks", 128, 1, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=256)", "chunks", 256, 1, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=64, f32)", "f32", 64, 1, PlaneFilter::kNearest, PlanePrecision::kF32},
      {"G2LF (N=512, Bi., f32)", "f32", 512, 1, PlaneFilter::kBilinear, PlanePrecision::kF32},
      {"G2LF (N=64, view density)", "density", 64, 0, PlaneFilter::kNearest, PlanePrecision::kU8},
      {"G2LF (N=512, view density, Bi.)", "density", 512, 0, PlaneFilter::kBilinear, PlanePrecision::kU8},
  };
  return configs;
}

std::vector<G2lfConfig> g2lf_configs_in(const std::vector<std::string>& sets, const std::string& field) {
  for (const std::string& s : sets)
    if (s != "table1" && s != "chunks" && s != "f32" && s != "density")
      throw_input_error("{}: '{}' is not table1, chunks, f32 or density", field, s);
  std::vector<G2lfConfig> out;
  for (const G2lfConfig& c : g2lf_configs())
    if (std::find(sets.begin(), sets.end(), c.set) != sets.end()) out.push_back(c);
  return out;
}

int equal_density_plane_scale(const render::QuiltGeometry& geometry, float d_shift) {
  const render::ReferenceCamera ref = render::make_reference_camera(geometry, d_shift, 1);
  // View pixel / plane texel on the focal plane (the ratio of Eq. gs_prefilter_fix), per axis.
  const float df = geometry.focal_distance, ahead = df - ref.d_forward_eff;
  const float ratio_x = df * geometry.base.tan_half_fov_x() / (ahead * ref.camera.tan_half_fov_x());
  const float ratio_y = df * geometry.base.tan_half_fov_y() / (ahead * ref.camera.tan_half_fov_y());
  const float needed = 1.0f / std::min(ratio_x, ratio_y);
  return std::clamp(int(std::ceil(needed - 1e-4f)), 1, 8);
}

std::string config_label(const G2lfConfig& config, int plane_scale) {
  if (config.plane_scale != 0) return config.name;
  std::string name = config.name;
  const std::string token = "view density";
  name.replace(name.find(token), token.size(), fmt::format("Ps={} = view density", plane_scale));
  return name;
}

void add_config_fields(nlohmann::ordered_json& row, const G2lfConfig& config, int plane_scale) {
  row["config_set"] = config.set;
  row["chunks"] = config.chunks;
  row["plane_scale"] = plane_scale;
  row["filter"] = config.filter == render::PlaneFilter::kBilinear ? "bilinear" : "nearest";
  row["precision"] = config.precision == render::PlanePrecision::kF32 ? "f32" : "u8";
}

}  // namespace lfd::bench
