#include "voxel/voxel_rasterizer.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/spherical_harmonics.hpp"
#include "util/error.hpp"
#include "voxel/antialias_downsample.hpp"
#include "voxel/ray_order.hpp"

namespace lfd::voxel {

namespace {

constexpr int kTile = 16;

struct TileRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive tile range; empty if x1 < x0
};

// Stage 1 (per voxel): the tiles its projected box may cover. A box reaching behind the camera
// plane covers the whole image (the slab test sorts out the rays), one wholly behind none.
TileRect tile_rect(const scene::VoxelScene& scene, size_t i, const render::Camera& camera, int tiles_x, int tiles_y) {
  const glm::vec3 lo = scene.voxel_min(i);
  const float size = scene.voxel_size(i);
  glm::vec2 pmin(INFINITY), pmax(-INFINITY);
  int behind = 0;
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner = lo + size * glm::vec3((c >> 2) & 1, (c >> 1) & 1, c & 1);
    const glm::vec3 p = camera.to_camera(corner);
    if (p.z <= 1e-6f) {
      ++behind;
      continue;
    }
    const glm::vec2 px = camera.project_px(corner);
    pmin = glm::min(pmin, px);
    pmax = glm::max(pmax, px);
  }
  if (behind == 8) return {};
  if (behind > 0) return {0, 0, tiles_x - 1, tiles_y - 1};
  // Pixel centres sit at integer coordinates; a pixel is hit if its centre's ray meets the box.
  TileRect r;
  r.x0 = std::max(0, int(std::floor(pmin.x)) / kTile);
  r.y0 = std::max(0, int(std::floor(pmin.y)) / kTile);
  r.x1 = std::min(tiles_x - 1, int(std::ceil(pmax.x)) / kTile);
  r.y1 = std::min(tiles_y - 1, int(std::ceil(pmax.y)) / kTile);
  if (pmax.x < 0.0f || pmax.y < 0.0f) return {};
  return r;
}

}  // namespace

glm::vec3 pixel_ray(const render::Camera& camera, int x, int y) {
  const float ndc_x = (2.0f * float(x) + 1.0f) / float(camera.width) - 1.0f;
  const float ndc_y = (2.0f * float(y) + 1.0f) / float(camera.height) - 1.0f;
  const glm::vec3 d_cam((ndc_x - camera.shift_x_ndc) * camera.tan_half_fov_x(),
                        (ndc_y - camera.shift_y_ndc) * camera.tan_half_fov_y(), 1.0f);
  return glm::normalize(glm::transpose(camera.world_to_camera) * d_cam);
}

namespace {

// tau of one voxel along a ray: K midpoint samples over the slab test's chord.
float voxel_tau(const scene::VoxelScene& scene, size_t i, const glm::vec3& o, const glm::vec3& d) {
  const glm::vec3 lo = scene.voxel_min(i);
  const float size = scene.voxel_size(i);
  const glm::vec3 inv = 1.0f / d;
  const glm::vec3 ta = (lo - o) * inv, tb = (lo + size - o) * inv;
  const glm::vec3 tmin = glm::min(ta, tb), tmax = glm::max(ta, tb);
  const float t_in = std::max({tmin.x, tmin.y, tmin.z, 0.0f});
  const float t_out = std::min({tmax.x, tmax.y, tmax.z});
  if (!(t_out > t_in)) return 0.0f;
  const int k = scene.samples_per_voxel;
  const float dt = (t_out - t_in) / float(k);
  float tau = 0.0f;
  for (int s = 0; s < k; ++s) {
    const glm::vec3 p = o + (t_in + (float(s) + 0.5f) * dt) * d;
    const glm::vec3 local = glm::clamp((p - lo) / size, 0.0f, 1.0f);
    tau += kStepScale * dt * scene::exp_linear_11(scene::trilinear(scene.corner_density[i], local));
  }
  return tau;
}

float alpha_of_tau(float tau) { return std::min(kMaxAlpha, 1.0f - std::exp(-tau)); }

}  // namespace

float voxel_alpha(const scene::VoxelScene& scene, size_t voxel, const glm::vec3& origin, const glm::vec3& unit_direction) {
  return alpha_of_tau(voxel_tau(scene, voxel, origin, unit_direction));
}

render::RasterImage rasterize_voxels_exact(const scene::VoxelScene& scene, const render::Camera& camera,
                                           const glm::vec3& background, const std::vector<uint32_t>& subset,
                                           std::optional<glm::vec3> sh_origin) {
  return rasterize_voxels_exact(scene, RayOrder(scene), camera, background, subset, sh_origin);
}

render::RasterImage rasterize_voxels_exact(const scene::VoxelScene& scene, const RayOrder& order, const render::Camera& camera,
                                           const glm::vec3& background, const std::vector<uint32_t>& subset,
                                           std::optional<glm::vec3> sh_origin) {
  const int width = camera.width, height = camera.height;
  if (width < 1 || height < 1) throw_input_error("voxel rasterizer: image size {}x{} is empty", width, height);
  const int tiles_x = (width + kTile - 1) / kTile, tiles_y = (height + kTile - 1) / kTile;
  std::vector<uint32_t> all;
  if (subset.empty()) {
    all.resize(scene.size());
    std::iota(all.begin(), all.end(), 0u);
  }
  const std::vector<uint32_t>& voxels = subset.empty() ? all : subset;

  // Stage 1: per voxel its colour (SH once per view, camera to voxel centre) and tile range,
  // indexed by the position in `voxels` (a chunk's arrays are the chunk's size, not the scene's).
  std::vector<glm::vec3> colour(voxels.size());
  std::vector<TileRect> rects(voxels.size());
#pragma omp parallel for schedule(static)
  for (size_t n = 0; n < voxels.size(); ++n) {
    const size_t i = voxels[n];
    rects[n] = tile_rect(scene, i, camera, tiles_x, tiles_y);
    if (rects[n].x1 >= rects[n].x0 && rects[n].y1 >= rects[n].y0) {
      const glm::vec3 dir = glm::normalize(scene.voxel_center(i) - sh_origin.value_or(camera.position_world));
      colour[n] = render::eval_sh_color(scene.sh_degree, scene.voxel_sh(i), dir);
    }
  }
  // Stage 2: tile binning.
  std::vector<std::vector<uint32_t>> bins(size_t(tiles_x) * size_t(tiles_y));
  for (size_t n = 0; n < voxels.size(); ++n)
    for (int ty = rects[n].y0; ty <= rects[n].y1; ++ty)
      for (int tx = rects[n].x0; tx <= rects[n].x1; ++tx) bins[size_t(ty) * size_t(tiles_x) + size_t(tx)].push_back(uint32_t(n));

  // Stage 3 (per tile): one sorted list per sign octant its rays take, then per pixel the
  // front-to-back composite.
  render::RasterImage image;
  image.width = width;
  image.height = height;
  image.rgb.assign(size_t(width) * size_t(height) * 3, 0.0f);
  image.transmittance.assign(size_t(width) * size_t(height), 1.0f);
#pragma omp parallel for schedule(dynamic, 1)
  for (int tile = 0; tile < tiles_x * tiles_y; ++tile) {
    const std::vector<uint32_t>& bin = bins[size_t(tile)];
    const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
    const int x1 = std::min(width, x0 + kTile), y1 = std::min(height, y0 + kTile);
    std::array<std::vector<uint32_t>, 8> sorted;
    std::array<bool, 8> ready{};
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const glm::vec3 d = pixel_ray(camera, x, y);
        const int octant = direction_octant(d);
        if (!ready[size_t(octant)]) {
          sorted[size_t(octant)] = bin;
          std::sort(sorted[size_t(octant)].begin(), sorted[size_t(octant)].end(), [&](uint32_t a, uint32_t b) {
            const uint64_t ka = order.key(voxels[a], octant), kb = order.key(voxels[b], octant);
            return ka != kb ? ka < kb : voxels[a] < voxels[b];
          });
          ready[size_t(octant)] = true;
        }
        glm::vec3 c(0.0f);
        float t = 1.0f;
        for (uint32_t n : sorted[size_t(octant)]) {
          const float alpha = alpha_of_tau(voxel_tau(scene, voxels[n], camera.position_world, d));
          if (alpha < kMinAlpha) continue;
          c += t * alpha * colour[n];
          t *= 1.0f - alpha;
          if (t < kMinTransmittance) break;
        }
        const size_t p = size_t(y) * size_t(width) + size_t(x);
        for (int ch = 0; ch < 3; ++ch) image.rgb[p * 3 + size_t(ch)] = c[ch] + t * background[ch];
        image.transmittance[p] = t;
      }
  }
  return image;
}

render::RasterImage rasterize_voxels(const scene::VoxelScene& scene, const render::Camera& camera,
                                     const VoxelRenderSettings& settings) {
  const glm::vec3 background = settings.background.value_or(scene.background);
  const float ss = settings.supersampling.value_or(scene.supersampling);
  if (!(ss >= 1.0f && ss <= 4.0f)) throw_input_error("voxel rasterizer: supersampling {} must lie in [1, 4]", ss);
  const int width = std::max(1, int(std::lround(ss * float(camera.width))));
  const int height = std::max(1, int(std::lround(ss * float(camera.height))));
  if (width == camera.width && height == camera.height) return rasterize_voxels_exact(scene, camera, background);
  render::Camera big = camera;  // same frustum (fov and principal-point shift are in NDC)
  big.width = width;
  big.height = height;
  const render::RasterImage hi = rasterize_voxels_exact(scene, big, background);
  render::RasterImage out;
  out.width = camera.width;
  out.height = camera.height;
  out.rgb = antialias_downsample(hi.rgb, width, height, 3, camera.width, camera.height);
  out.transmittance = antialias_downsample(hi.transmittance, width, height, 1, camera.width, camera.height);
  return out;
}

}  // namespace lfd::voxel
