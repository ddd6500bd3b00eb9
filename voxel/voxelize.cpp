// Gaussians to sparse voxels: the adaptive octree, the densities at its grid points and the
// SH per leaf (the method and its reasons are in voxelize.hpp and docs/voxels.md).
#include "voxel/voxelize.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include "scene/scene_bounds.hpp"
#include "util/error.hpp"
#include "voxel/corner_density_fit.hpp"
#include "voxel/gaussian_density_field.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::voxel {

namespace {

constexpr float kMinRawDensity = -10.0f;  // activates to 4.6e-5: clear, as the generator's empty side

struct Cell {
  glm::u32vec3 index{0u};
  float mass = 0.0f;                 // of the density field inside the cell
  float detail_mass = 0.0f;          // of the Gaussians thinner than the cell (6 sigma < edge)
  std::vector<uint32_t> gaussians;   // whose 3-sigma box overlaps the cell
};

struct Root {
  glm::vec3 min{0.0f};
  float extent = 1.0f;
  int outside_levels = 0;  // root = the inside cube doubled this many times
  glm::vec3 cell_min(const glm::u32vec3& index, int level) const {
    return min + glm::vec3(index) * std::ldexp(extent, -level);
  }
};

// SVRaster's layout: an inside cube (here the centres' 0.5-99.5% quantiles plus a 10% margin,
// so floaters do not decide the resolution), doubled about its centre until every centre is in
// (at most kMaxOutsideLevels times), so a background (a sky dome, distant walls) gets the
// coarser outer levels.
constexpr int kMaxOutsideLevels = 4;
Root root_cube(const scene::GaussianScene& scene) {
  const scene::SceneBounds b = scene::robust_bounds(scene, 0.005, 0.995);
  const auto e = b.extent();
  const auto c = b.center();
  const glm::vec3 center(c[0], c[1], c[2]);
  Root root;
  root.extent = std::max(1.1f * std::max({e[0], e[1], e[2]}), 1e-3f);
  const scene::SceneBounds all = scene::exact_bounds(scene);
  float reach = 0.0f;  // largest distance of a centre from the inside cube's centre, per axis
  for (int a = 0; a < 3; ++a) reach = std::max({reach, center[a] - all.min[a], all.max[a] - center[a]});
  while (root.outside_levels < kMaxOutsideLevels && 0.5f * root.extent < reach) {
    root.extent *= 2.0f;
    ++root.outside_levels;
  }
  root.min = center - 0.5f * root.extent;
  return root;
}

// The share of Gaussian g's mass inside the box, from its axis-aligned marginals (exact for an
// axis-aligned Gaussian, close enough for a subdivision criterion otherwise).
float mass_inside(const GaussianDensityField& field, uint32_t g, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 s = glm::max(field.axis_sigma(g), glm::vec3(1e-12f)) * std::sqrt(2.0f);
  const glm::vec3 m = field.mean(g);
  float share = 1.0f;
  for (int a = 0; a < 3; ++a) share *= 0.5f * (std::erf((hi[a] - m[a]) / s[a]) - std::erf((lo[a] - m[a]) / s[a]));
  return field.mass(g) * share;
}

bool overlaps(const GaussianDensityField& field, uint32_t g, const glm::vec3& lo, const glm::vec3& hi) {
  const glm::vec3 a = field.mean(g) - field.support(g), b = field.mean(g) + field.support(g);
  return glm::all(glm::lessThanEqual(a, hi)) && glm::all(glm::greaterThanEqual(b, lo));
}

std::vector<Cell> children_of(const Cell& parent, int parent_level, const Root& root, const GaussianDensityField& field) {
  std::vector<Cell> children(8);
  const float size = std::ldexp(root.extent, -(parent_level + 1));
  for (uint32_t c = 0; c < 8; ++c) {
    Cell& child = children[c];
    child.index = 2u * parent.index + glm::u32vec3(c >> 2 & 1u, c >> 1 & 1u, c & 1u);
    const glm::vec3 lo = root.cell_min(child.index, parent_level + 1), hi = lo + size;
    for (uint32_t g : parent.gaussians)
      if (overlaps(field, g, lo, hi)) {
        child.gaussians.push_back(g);
        const float m = mass_inside(field, g, lo, hi);
        child.mass += m;
        if (6.0f * field.min_scale(g) < size) child.detail_mass += m;
      }
  }
  return children;
}

struct Leaf {
  glm::u32vec3 index;
  int level;
  float mass;  // of the density field inside it
};

// Breadth-first: each level's cells either split (enough mass, level below the cap, and with a
// voxel budget the heaviest first while the count fits) or stay as leaves if not empty.
std::vector<Leaf> build_octree(const Root& root, const GaussianDensityField& field, const VoxelizeOptions& options) {
  const auto optical_depth = [&](const Cell& c, int level) {
    const float size = std::ldexp(root.extent, -level);
    return c.mass / (size * size);
  };
  Cell top;
  for (uint32_t g = 0; g < field.size(); ++g)
    if (overlaps(field, g, root.min, root.min + root.extent)) {
      top.gaussians.push_back(g);
      const float m = mass_inside(field, g, root.min, root.min + root.extent);
      top.mass += m;
      if (6.0f * field.min_scale(g) < root.extent) top.detail_mass += m;
    }
  std::vector<Leaf> leaves;
  std::vector<Cell> cells{std::move(top)};
  for (int level = 0; !cells.empty(); ++level) {
    const auto kept = [&](const Cell& c, int l) { return optical_depth(c, l) >= options.keep_optical_depth; };
    // Split while a cell holds, in Gaussians thinner than itself, the mass of a finest voxel of
    // optical depth split_optical_depth: judged against the finest cross-section, not the
    // cell's own, so a small dense object in a large cell is found (the cell's own optical
    // depth shrinks with its size squared); Gaussians thicker than the cell are smooth at its
    // scale, so a cell of fog alone stays coarse.
    const float finest_area = std::ldexp(root.extent * root.extent, -2 * options.max_level);
    std::vector<size_t> candidates;
    if (level < options.max_level)
      for (size_t i = 0; i < cells.size(); ++i)
        if (cells[i].detail_mass > options.split_optical_depth * finest_area) candidates.push_back(i);
    std::vector<std::vector<Cell>> children(candidates.size());
#pragma omp parallel for schedule(dynamic, 4)
    for (ptrdiff_t k = 0; k < ptrdiff_t(candidates.size()); ++k)
      children[size_t(k)] = children_of(cells[candidates[size_t(k)]], level, root, field);
    // Heaviest first, so a voxel budget goes where the mass is.
    std::vector<size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return cells[candidates[a]].mass > cells[candidates[b]].mass; });
    size_t count = leaves.size();
    for (const Cell& c : cells) count += kept(c, level) ? 1 : 0;
    std::vector<bool> split(cells.size(), false);
    std::vector<Cell> next;
    for (size_t k : order) {
      const Cell& parent = cells[candidates[k]];
      size_t kept_children = 0;
      for (const Cell& child : children[k]) kept_children += kept(child, level + 1) ? 1 : 0;
      const size_t after = count - (kept(parent, level) ? 1 : 0) + kept_children;
      if (options.max_voxels && after > options.max_voxels) continue;
      count = after;
      split[candidates[k]] = true;
      for (Cell& child : children[k])
        if (kept(child, level + 1) || !child.gaussians.empty()) next.push_back(std::move(child));
    }
    for (size_t i = 0; i < cells.size(); ++i)
      if (!split[i] && kept(cells[i], level)) leaves.push_back({cells[i].index, level, cells[i].mass});
    cells = std::move(next);
  }
  return leaves;
}

// A grid point's key: its integer position at the deepest level (17 bits per axis).
uint64_t grid_key(const Leaf& leaf, int corner) {
  const int shift = scene::kMaxOctreeLevel - leaf.level;
  const glm::u32vec3 p = (leaf.index + glm::u32vec3(corner >> 2 & 1, corner >> 1 & 1, corner & 1)) << uint32_t(shift);
  return uint64_t(p.x) | uint64_t(p.y) << 17 | uint64_t(p.z) << 34;
}

void fill_densities(scene::VoxelScene& out, const std::vector<Leaf>& leaves, const Root& root,
                    const GaussianDensityField& field, VoxelizeReport& report) {
  // One entry per grid point, smoothed at the finest leaf touching it: neighbours share it.
  std::unordered_map<uint64_t, uint32_t> slot;
  std::vector<uint64_t> keys;
  std::vector<int> finest;
  std::vector<std::array<uint32_t, 8>> corner_slot(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i)
    for (int c = 0; c < 8; ++c) {
      const uint64_t k = grid_key(leaves[i], c);
      const auto [it, inserted] = slot.try_emplace(k, uint32_t(keys.size()));
      if (inserted) {
        keys.push_back(k);
        finest.push_back(leaves[i].level);
      }
      finest[it->second] = std::max(finest[it->second], leaves[i].level);
      corner_slot[i][size_t(c)] = it->second;
    }
  report.grid_points = keys.size();
  std::vector<float> raw(keys.size());
  const float unit = std::ldexp(root.extent, -scene::kMaxOctreeLevel);
#pragma omp parallel for schedule(dynamic, 256)
  for (ptrdiff_t p = 0; p < ptrdiff_t(keys.size()); ++p) {
    const uint64_t k = keys[size_t(p)];
    const glm::vec3 x = root.min + unit * glm::vec3(float(k & 0x1FFFF), float(k >> 17 & 0x1FFFF), float(k >> 34 & 0x1FFFF));
    // SVRaster's tau = 100 dt sigma: its sigma is the extinction per scene unit over 100.
    const float sigma = field.density(x, std::ldexp(root.extent, -finest[size_t(p)])) / kStepScale;
    raw[size_t(p)] = sigma > 0.0f ? std::max(scene::inverse_exp_linear_11(sigma), kMinRawDensity) : kMinRawDensity;
  }
  // Each voxel's target: the raw value of its mean density (mass over volume), which its centre
  // sample should see (corner_density_fit.hpp says why the point values alone fall short).
  std::vector<float> target(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) {
    const float size = std::ldexp(root.extent, -leaves[i].level);
    const float sigma = leaves[i].mass / (size * size * size) / kStepScale;
    target[i] = sigma > 0.0f ? std::max(scene::inverse_exp_linear_11(sigma), kMinRawDensity) : kMinRawDensity;
  }
  const std::vector<float> fitted = fit_corner_densities(corner_slot, target, raw);
  for (size_t i = 0; i < leaves.size(); ++i)
    for (size_t c = 0; c < 8; ++c) out.corner_density[i][c] = fitted[corner_slot[i][c]];
}

void fill_colours(scene::VoxelScene& out, const scene::GaussianScene& scene, const GaussianDensityField& field) {
  const int in_coeffs = scene.sh_coeffs(), out_coeffs = out.sh_coeffs();
  const int shared = std::min(in_coeffs, out_coeffs) * 3;
#pragma omp parallel for schedule(dynamic, 256)
  for (ptrdiff_t i = 0; i < ptrdiff_t(out.size()); ++i) {
    float* sh = out.voxel_sh(size_t(i));
    std::vector<double> sum(size_t(shared), 0.0);
    double total = 0.0;
    // A leaf is kept for mass near a face that may not reach its centre within 3 sigma: widen
    // the smoothing until some Gaussian does.
    for (float smoothing = out.voxel_size(size_t(i)); total == 0.0 && smoothing <= 4.0f * out.voxel_size(size_t(i));
         smoothing *= 2.0f)
      field.for_each_contribution(out.voxel_center(size_t(i)), smoothing, [&](uint32_t g, float w) {
        const float* src = scene.sh_of(g);
        for (int k = 0; k < shared; ++k) sum[size_t(k)] += double(w) * src[k];
        total += w;
      });
    for (int k = 0; k < out_coeffs * 3; ++k) sh[k] = 0.0f;  // no Gaussian reaches: grey (0.5)
    if (total > 0.0)
      for (int k = 0; k < shared; ++k) sh[k] = float(sum[size_t(k)] / total);
  }
}

}  // namespace

void VoxelizeOptions::check() const {
  if (max_level < 1 || max_level > scene::kMaxOctreeLevel)
    throw_input_error("voxelize options: level: {} is outside 1..{}", max_level, scene::kMaxOctreeLevel);
  if (sh_degree < -1 || sh_degree > 3) throw_input_error("voxelize options: sh_degree: {} is not 0-3", sh_degree);
  if (!(split_optical_depth > 0.0f) || !(keep_optical_depth >= 0.0f))
    throw_input_error("voxelize options: optical depth thresholds must be positive");
}

scene::VoxelScene voxelize(const scene::GaussianScene& scene, const VoxelizeOptions& options, VoxelizeReport* report_out) {
  options.check();
  if (scene.size() == 0) throw_input_error("voxelize: the scene has no Gaussians");
  const Root root = root_cube(scene);
  VoxelizeReport report;
  for (const auto& p : scene.positions) {
    const glm::vec3 x(p[0], p[1], p[2]);
    if (glm::any(glm::lessThan(x, root.min)) || glm::any(glm::greaterThan(x, root.min + root.extent)))
      ++report.gaussians_outside;
  }
  // Hash cells of two finest voxels: a query spans a few, a small Gaussian sits in one.
  // --level counts inside the inside cube; the outer levels come on top.
  VoxelizeOptions octree = options;
  octree.max_level = std::min(options.max_level + root.outside_levels, scene::kMaxOctreeLevel);
  report.outside_levels = root.outside_levels;
  const GaussianDensityField field(scene, 2.0f * std::ldexp(root.extent, -std::min(octree.max_level, 12)));
  const std::vector<Leaf> leaves = build_octree(root, field, octree);

  scene::VoxelScene out;
  out.scene_center = root.min + 0.5f * root.extent;
  out.scene_extent = root.extent;
  out.sh_degree = options.sh_degree < 0 ? scene.sh_degree : options.sh_degree;
  out.resize(leaves.size());
  for (size_t i = 0; i < leaves.size(); ++i) {
    out.octree_index[i] = leaves[i].index;
    out.level[i] = uint8_t(leaves[i].level);
    report.finest_level = std::max(report.finest_level, leaves[i].level);
  }
  fill_densities(out, leaves, root, field, report);
  fill_colours(out, scene, field);
  scene::check_voxel_scene(out, "voxelized scene");
  if (report_out) *report_out = report;
  return out;
}

}  // namespace lfd::voxel
