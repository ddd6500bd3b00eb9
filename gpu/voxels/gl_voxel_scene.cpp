#include "gpu/voxels/gl_voxel_scene.hpp"

#include <algorithm>
#include <numeric>

#include "gpu/splats/gl_scene.hpp"
#include "util/error.hpp"
#include "voxel/ray_order.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::gpu {
namespace {

double mib(double bytes) { return bytes / 1048576.0; }

}  // namespace

size_t voxel_scene_bytes_per_voxel(int sh_degree) {
  return 16 /* box */ + 32 /* densities */ + size_t(sh_vec4_stride(sh_degree)) * 16 + 8 * 4 /* orders */;
}

void check_voxel_scene_fits(size_t voxels, int sh_degree, const GlInfo& info) {
  // The order buffer holds 8 v indices, all below 2^32.
  if (voxels > 0x1FFFFFFFull)
    throw_input_error("voxel scene of {} voxels is beyond the GL renderer's 32-bit indices (at most {})", voxels,
                      0x1FFFFFFFull);
  const double largest = double(voxels) * std::max<double>(32.0, std::max(sh_vec4_stride(sh_degree) * 16.0, 32.0));
  if (info.max_ssbo_bytes > 0 && largest > double(info.max_ssbo_bytes))
    throw_input_error("voxel scene of {} voxels at SH degree {} needs a {:.0f} MiB buffer, above this GPU's limit "
                      "of {:.0f} MiB per storage buffer (GL_MAX_SHADER_STORAGE_BLOCK_SIZE)",
                      voxels, sh_degree, mib(largest), mib(double(info.max_ssbo_bytes)));
  const double total = double(voxels) * double(voxel_scene_bytes_per_voxel(sh_degree));
  if (info.free_memory_bytes && total > double(*info.free_memory_bytes))
    throw_input_error("voxel scene of {} voxels needs {:.0f} MiB of GPU memory but {:.0f} MiB are free", voxels,
                      mib(total), mib(double(*info.free_memory_bytes)));
}

GlVoxelScene::GlVoxelScene(const scene::VoxelScene& scene, const GlInfo& info) : scene_(scene) {
  const size_t n = scene_.size();
  check_voxel_scene_fits(n, scene_.sh_degree, info);
  std::vector<glm::vec4> boxes(std::max<size_t>(n, 1));
  std::vector<glm::vec4> densities(2 * std::max<size_t>(n, 1));
  for (size_t i = 0; i < n; ++i) {
    boxes[i] = glm::vec4(scene_.voxel_min(i), scene_.voxel_size(i));
    const auto& d = scene_.corner_density[i];
    densities[2 * i] = glm::vec4(d[0], d[1], d[2], d[3]);
    densities[2 * i + 1] = glm::vec4(d[4], d[5], d[6], d[7]);
  }
  const int stride = sh_vec4_stride(scene_.sh_degree), coeffs = 3 * scene_.sh_coeffs();
  std::vector<float> sh(std::max<size_t>(n, 1) * size_t(stride) * 4, 0.0f);
  for (size_t i = 0; i < n; ++i) std::copy_n(scene_.voxel_sh(i), coeffs, sh.begin() + ptrdiff_t(i * size_t(stride) * 4));

  const voxel::RayOrder ray_order(scene_);
  std::vector<uint32_t> all(std::max<size_t>(8 * n, 1));
  for (int octant = 0; octant < 8; ++octant) {
    std::vector<uint32_t>& order = orders_[size_t(octant)];
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
    // Ties (equal keys) cannot happen between leaves; the index keeps the sort deterministic anyway.
    std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
      const uint64_t ka = ray_order.key(a, octant), kb = ray_order.key(b, octant);
      return ka != kb ? ka < kb : a < b;
    });
    std::copy(order.begin(), order.end(), all.begin() + ptrdiff_t(size_t(octant) * n));
  }
  boxes_ = Buffer(boxes.size() * sizeof(glm::vec4), boxes.data());
  densities_ = Buffer(densities.size() * sizeof(glm::vec4), densities.data());
  sh_ = Buffer(sh.size() * sizeof(float), sh.data());
  order_ = Buffer(all.size() * sizeof(uint32_t), all.data());
  check_gl("uploading a voxel scene");
}

size_t GlVoxelScene::bytes() const { return boxes_.bytes() + densities_.bytes() + sh_.bytes() + order_.bytes(); }

uint32_t octants_in_view(const render::Camera& camera) {
  // Before normalising, the direction is linear in the pixel position; normalising keeps signs.
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (int corner = 0; corner < 4; ++corner) {
    const int x = (corner & 1) ? camera.width - 1 : 0, y = (corner & 2) ? camera.height - 1 : 0;
    const glm::vec3 d = voxel::pixel_ray(camera, x, y);
    lo = glm::min(lo, d);
    hi = glm::max(hi, d);
  }
  uint32_t mask = 0;
  for (int octant = 0; octant < 8; ++octant) {
    bool possible = true;
    for (int axis = 0; axis < 3; ++axis) {
      const bool negative = (octant >> (2 - axis)) & 1;  // bit 2 = x, 1 = y, 0 = z
      possible = possible && (negative ? lo[axis] < 0.0f : hi[axis] >= 0.0f);
    }
    if (possible) mask |= 1u << octant;
  }
  return mask;
}

}  // namespace lfd::gpu
