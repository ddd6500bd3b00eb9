#pragma once
// The G2LF configurations `lfd bench render` measures: the paper's Table 1 (N_chunk 64 and
// 512, P_s 1-3, nearest or bilinear, 8-bit planes), the chunk counts between them and 32-bit
// planes (the paper's Figs. perf_g2lf and perf_uint8), and G2LF at equal plane density.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/g2lf.hpp"
#include "render/quilt_geometry.hpp"

namespace lfd::bench {

struct G2lfConfig {
  std::string name;  // as the paper's table: "G2LF (N=512, Ps=2, Bi.)"
  std::string set;   // table1 | chunks | f32 | density
  int chunks = 64;
  int plane_scale = 1;  // 0: equal density (equal_density_plane_scale)
  render::PlaneFilter filter = render::PlaneFilter::kNearest;
  render::PlanePrecision precision = render::PlanePrecision::kU8;
};

// Every configuration, Table 1 first.
const std::vector<G2lfConfig>& g2lf_configs();

// The configuration sets by name ("table1", "chunks", "f32", "density"); InputError naming
// `field` for an unknown one.
std::vector<G2lfConfig> g2lf_configs_in(const std::vector<std::string>& sets, const std::string& field);

// The smallest P_s (1..8) whose plane texel, seen on the focal plane, is no larger than a view
// pixel in x and y: with the reference camera at the base camera (D_shift = D_forward) its
// wider angle theta' spreads the same texel count over a wider field, so P_s = 1 is coarser
// than the views.
int equal_density_plane_scale(const render::QuiltGeometry& geometry, float d_shift);

// The name of a configuration with its binning, and the P_s it resolved to for density ones:
// "G2LF (N=64, Ps=2 = view density)".
std::string config_label(const G2lfConfig& config, int plane_scale);

// Adds a configuration's fields to its JSON row (config_set, chunks, plane_scale as resolved,
// filter, precision): the same fields in `lfd bench render` and `lfd bench voxels`.
void add_config_fields(nlohmann::ordered_json& row, const G2lfConfig& config, int plane_scale);

}  // namespace lfd::bench
