// The tabletop as signed distance fields, carved into an octree. Densities come from the signed
// distance at each corner, so neighbouring leaves agree on the corners they share (as SVRaster's
// shared grid points do) and every surface is opaque within about half a voxel.
#include "voxel/voxel_generator.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "render/default_camera.hpp"
#include "scene/gaussian_scene.hpp"
#include "render/spherical_harmonics.hpp"
#include "util/error.hpp"

namespace lfd::voxel {

namespace {

constexpr float kRootExtent = 16.0f;  // root cell [-8, 8]^3
constexpr float kShellRadius = 7.0f;
constexpr float kDetailRadius = 4.0f;  // L-inf distance within which leaves are at detail_level

float sd_box(const glm::vec3& p, const glm::vec3& center, const glm::vec3& half) {
  const glm::vec3 q = glm::abs(p - center) - half;
  return glm::length(glm::max(q, 0.0f)) + std::min(std::max({q.x, q.y, q.z}), 0.0f);
}
float sd_sphere(const glm::vec3& p, const glm::vec3& center, float r) { return glm::length(p - center) - r; }

struct Part {
  enum class Kind { Box, Sphere, Shell } kind;
  glm::vec3 center, half;  // sphere: radius in half.x; shell: radius, thickness in half.x, half.y
  glm::vec3 colour, alt_colour;
  float checker = 0.0f;  // period of a checker between the two colours; 0 = plain
  float distance(const glm::vec3& p) const {
    switch (kind) {
      case Kind::Box: return sd_box(p, center, half);
      case Kind::Sphere: return sd_sphere(p, center, half.x);
      case Kind::Shell: return std::abs(glm::length(p - center) - half.x) - half.y;
    }
    return INFINITY;
  }
  glm::vec3 paint(const glm::vec3& p) const {
    if (checker <= 0.0f) return colour;
    const int parity = int(std::floor(p.x / checker) + std::floor(p.z / checker) + std::floor(p.y / checker)) & 1;
    return parity ? alt_colour : colour;
  }
};

glm::vec3 hsv(float h, float s, float v) {
  const glm::vec3 k = glm::mod(glm::vec3(5.0f, 3.0f, 1.0f) + h * 6.0f, 6.0f);
  return v - v * s * glm::clamp(glm::min(k, 4.0f - k), 0.0f, 1.0f);
}

std::vector<Part> tabletop(uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const auto jitter = [&](float s) { return (u(rng) - 0.5f) * 2.0f * s; };
  using K = Part::Kind;
  std::vector<Part> parts;
  // Ground slab (y down: the top face at y = +1), checkered.
  parts.push_back({K::Box, {0, 1.25f, 0}, {3.5f, 0.25f, 4.0f}, {0.55f, 0.5f, 0.42f}, {0.35f, 0.32f, 0.28f}, 0.5f});
  // Objects in three rows at z = -1.5, 0.5, 2.5 resting on the ground.
  const float rows[3] = {-1.5f, 0.5f, 2.5f};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const float x = -2.0f + 2.0f * float(c) + jitter(0.3f), z = rows[r] + jitter(0.3f);
      const glm::vec3 colour = hsv(u(rng), 0.6f, 0.85f);
      if ((r + c + int(seed)) % 2 == 0) {
        const float radius = 0.35f + 0.25f * u(rng);
        parts.push_back({K::Sphere, {x, 1.0f - radius, z}, {radius, 0, 0}, colour, colour, 0.0f});
      } else {
        const glm::vec3 half(0.3f + 0.2f * u(rng), 0.3f + 0.5f * u(rng), 0.3f + 0.2f * u(rng));
        parts.push_back({K::Box, {x, 1.0f - half.y, z}, half, colour, 0.6f * colour, 0.25f});
      }
    }
  // The coarse outer shell: a sky dome all around.
  parts.push_back({K::Shell, {0, 0, 0}, {kShellRadius, 0.6f, 0}, {0.45f, 0.6f, 0.85f}, {0.45f, 0.6f, 0.85f}, 0.0f});
  return parts;
}

struct Nearest {
  float distance = INFINITY;
  const Part* part = nullptr;
};
Nearest nearest(const std::vector<Part>& parts, const glm::vec3& p) {
  Nearest n;
  for (const Part& part : parts) {
    const float d = part.distance(p);
    if (d < n.distance) n = {d, &part};
  }
  return n;
}

// The level of a leaf on `part`: objects at detail_level; the ground one level coarser (two
// beyond kDetailRadius), so the objects, not the ground, decide the default framing; the outer
// shell two levels coarser, like SVRaster's background.
int target_level(const glm::vec3& center, float size, int detail_level, Part::Kind kind, bool ground) {
  if (kind == Part::Kind::Shell) return detail_level - 2;
  if (!ground) return detail_level;
  const float d = std::max({std::abs(center.x), std::abs(center.y), std::abs(center.z)}) - 0.5f * size;
  return detail_level - (d > kDetailRadius ? 2 : 1);
}

struct Carver {
  const std::vector<Part>& parts;
  const VoxelGeneratorOptions& options;
  scene::VoxelScene& scene;

  void visit(glm::u32vec3 index, int level) {
    const float size = std::ldexp(kRootExtent, -level);
    const glm::vec3 lo = scene.scene_center - 0.5f * kRootExtent + glm::vec3(index) * size;
    const glm::vec3 center = lo + 0.5f * size;
    const Nearest n = nearest(parts, center);
    if (std::abs(n.distance) > 0.87f * size) return;  // no surface crosses this cell
    if (level < target_level(center, size, options.detail_level, n.part->kind, n.part == &parts.front())) {
      for (uint32_t child = 0; child < 8; ++child)
        visit(2u * index + glm::u32vec3(child >> 2 & 1u, child >> 1 & 1u, child & 1u), level + 1);
      return;
    }
    const size_t i = scene.size();
    scene.resize(i + 1);
    scene.octree_index[i] = index;
    scene.level[i] = uint8_t(level);
    for (int c = 0; c < 8; ++c) {
      const glm::vec3 corner = lo + size * glm::vec3((c >> 2) & 1, (c >> 1) & 1, c & 1);
      // Raw density 1.5 at the surface, rising by 16 per voxel inside and falling outside:
      // opaque half a voxel in, clear (sigma ~ 1e-3) half a voxel out.
      scene.corner_density[i][size_t(c)] = std::clamp(1.5f - 16.0f * nearest(parts, corner).distance / size, -10.0f, 60.0f);
    }
    const glm::vec3 rgb = n.part->paint(center);
    float* sh = scene.voxel_sh(i);
    for (int c = 0; c < 3; ++c) sh[c] = scene::color_to_sh_dc(rgb[c]);
    // A view-dependent sheen for degree >= 1 (3DGS signs: -y and -x multiply these terms).
    if (scene.sh_degree >= 1)
      for (int c = 0; c < 3; ++c) {
        sh[3 + c] = 0.15f * rgb[c];   // Y_1^-1 multiplies -y
        sh[9 + c] = -0.1f * rgb[c];   // Y_1^1 multiplies -x
      }
  }
};

}  // namespace

void VoxelGeneratorOptions::check() const {
  if (detail_level < 4 || detail_level > 11)
    throw_input_error("voxel generator options: detail_level: {} is outside 4..11", detail_level);
  if (sh_degree < 0 || sh_degree > 3)
    throw_input_error("voxel generator options: sh_degree: {} is not 0-3", sh_degree);
}

scene::VoxelScene generate_voxel_scene(const VoxelGeneratorOptions& options) {
  options.check();
  scene::VoxelScene scene;
  scene.scene_center = glm::vec3(0.0f);
  scene.scene_extent = kRootExtent;
  scene.sh_degree = options.sh_degree;
  const std::vector<Part> parts = tabletop(options.seed);
  Carver{parts, options, scene}.visit({0, 0, 0}, 0);
  scene::check_voxel_scene(scene, "generated voxel scene");
  return scene;
}

render::CameraSpec frame_voxel_scene(const scene::VoxelScene& scene, float fov_y_deg, float orbit_deg) {
  // Framed on the fine voxels (the content; SVRaster's background is coarse), kept inside the
  // outer shell: at most 85% of the distance within which 99% of all voxel centres lie, less the
  // largest voxel's edge (a coarse shell voxel's density reaches that far).
  const int finest = scene.size() ? *std::max_element(scene.level.begin(), scene.level.end()) : 0;
  const int coarsest = scene.size() ? *std::min_element(scene.level.begin(), scene.level.end()) : 0;
  scene::GaussianScene content;
  for (size_t i = 0; i < scene.size(); ++i)
    if (scene.level[i] + 2 >= finest) {
      const glm::vec3 c = scene.voxel_center(i);
      content.positions.push_back({c.x, c.y, c.z});
      content.opacities.push_back(1.0f);  // every content voxel counts (scene::content_bounds)
    }
  render::CameraSpec spec = render::frame_scene(content, fov_y_deg, orbit_deg);
  std::vector<float> distance(scene.size());
  for (size_t i = 0; i < scene.size(); ++i) distance[i] = glm::length(scene.voxel_center(i) - spec.look_at);
  if (distance.empty()) return spec;
  const auto r99 = distance.begin() + ptrdiff_t(0.99 * double(distance.size() - 1));
  std::nth_element(distance.begin(), r99, distance.end());
  const float limit = 0.85f * std::max(*r99 - std::ldexp(scene.scene_extent, -coarsest), 1e-3f);
  const glm::vec3 back = spec.position - spec.look_at;
  if (glm::length(back) > limit) spec.position = spec.look_at + limit * glm::normalize(back);
  // The 99% rule does not know where the shell is: the camera could sit within the shell's
  // thickness, in a gap between its inner and outer surface voxels, or inside a voxel; per view it
  // then sees the shell from behind (only sky) while V2LF's reference camera, further in on the
  // axis, sees the content (docs/voxels.md, "Rendering"). Move in until the camera and the
  // outermost views of the default 40-degree cone lie outside every voxel and see look_at past no
  // voxel of the coarsest level (the background).
  const glm::vec3 right = glm::normalize(glm::cross(spec.look_at - spec.position, spec.up));
  const float cone_half_tan = std::tan(glm::radians(20.0f));
  const auto blocked = [&](const glm::vec3& p) {
    const glm::vec3 d = spec.look_at - p;
    for (size_t i = 0; i < scene.size(); ++i) {
      const glm::vec3 lo = scene.voxel_min(i), hi = lo + scene.voxel_size(i);
      if (glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi))) return true;
      if (scene.level[i] != coarsest) continue;
      // Slab test of the segment p -> look_at (t in [0, 1]) against the box.
      const glm::vec3 ta = (lo - p) / d, tb = (hi - p) / d;
      const glm::vec3 tmin = glm::min(ta, tb), tmax = glm::max(ta, tb);
      const float t_in = std::max({tmin.x, tmin.y, tmin.z, 0.0f}), t_out = std::min({tmax.x, tmax.y, tmax.z, 1.0f});
      if (t_out >= t_in) return true;
    }
    return false;
  };
  const float start = glm::length(back);
  for (float dist = std::min(start, limit); dist > 0.05f * start; dist *= 0.97f) {
    const glm::vec3 p = spec.look_at + dist * glm::normalize(back);
    const glm::vec3 side = dist * cone_half_tan * right;
    if (!blocked(p) && !blocked(p + side) && !blocked(p - side)) {
      spec.position = p;
      break;
    }
  }
  return spec;
}

}  // namespace lfd::voxel
