// Alg. 1 lines 1-3: CulledDepth, FindQuantile, Sort_and_Chunk (paper section "G2LF": quantile
// binning so each chunk holds about the same number of Gaussians; plane = median depth).
#include <algorithm>
#include <cmath>

#include "render/g2lf.hpp"
#include "util/error.hpp"

namespace lfd::render {

DepthChunks bin_by_depth(const GaussianScene& scene, const QuiltGeometry& geometry,
                         const ReferenceCamera& ref, int chunks) {
  const Camera& cam = ref.camera;
  const float lim_x = 1.3f * cam.tan_half_fov_x(), lim_y = 1.3f * cam.tan_half_fov_y();
  std::vector<std::pair<float, uint32_t>> depth_index;
  depth_index.reserve(scene.size());
  for (uint32_t i = 0; i < scene.size(); ++i) {
    const auto& p = scene.positions[i];
    const glm::vec3 t = cam.to_camera(glm::vec3(p[0], p[1], p[2]));
    if (!(t.z > 0.2f) || std::fabs(t.x) > lim_x * t.z || std::fabs(t.y) > lim_y * t.z) continue;
    depth_index.emplace_back(t.z, i);
  }
  std::sort(depth_index.begin(), depth_index.end());

  DepthChunks out;
  const size_t n = depth_index.size();
  for (int k = 0; k < chunks; ++k) {
    const size_t b = n * size_t(k) / size_t(chunks), e = n * size_t(k + 1) / size_t(chunks);
    if (b == e) continue;
    std::vector<uint32_t> ids(e - b);
    for (size_t i = b; i < e; ++i) ids[i - b] = depth_index[i].second;
    // Keep scene order inside a chunk: the rasterizer sorts by depth itself, and scene order
    // makes its depth ties resolve as for the whole scene.
    std::sort(ids.begin(), ids.end());
    const size_t m = b + (e - b - 1) / 2;
    const float median = (e - b) % 2 ? depth_index[m].first
                                     : 0.5f * (depth_index[m].first + depth_index[m + 1].first);
    out.members.push_back(std::move(ids));
    out.plane_depth.push_back(median + ref.d_forward_eff);  // reference depth -> base depth
  }
  return out;
}

}  // namespace lfd::render
