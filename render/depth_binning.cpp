// Alg. 1 lines 1-3: CulledDepth, FindQuantile, Sort_and_Chunk (paper section "G2LF": quantile
// binning so each chunk holds about the same number of Gaussians; plane = median depth).
#include <algorithm>
#include <cmath>
#include <limits>

#include <parallel/algorithm>  // libstdc++'s OpenMP sort

#include "render/depth_binning.hpp"
#include "util/error.hpp"

namespace lfd::render {

DepthChunks bin_by_depth(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                         const ReferenceCamera& ref, int chunks, ChunkBinning binning) {
  const Camera& cam = ref.camera;
  const float lim_x = 1.3f * cam.tan_half_fov_x(), lim_y = 1.3f * cam.tan_half_fov_y();
  // Cull in parallel into a depth per Gaussian (NaN: outside), then gather in scene order.
  const long n_scene = long(scene.size());
  std::vector<float> depth(scene.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n_scene; ++i) {
    const auto& p = scene.positions[size_t(i)];
    const glm::vec3 t = cam.to_camera(glm::vec3(p[0], p[1], p[2]));
    const bool outside = !(t.z > 0.2f) || std::fabs(t.x) > lim_x * t.z || std::fabs(t.y) > lim_y * t.z;
    depth[size_t(i)] = outside ? std::numeric_limits<float>::quiet_NaN() : t.z;
  }
  std::vector<std::pair<float, uint32_t>> depth_index;
  depth_index.reserve(scene.size());
  for (uint32_t i = 0; i < scene.size(); ++i)
    if (!std::isnan(depth[i])) depth_index.emplace_back(depth[i], i);
  // (depth, index) pairs are unique, so the parallel sort's order is the serial one.
  __gnu_parallel::sort(depth_index.begin(), depth_index.end());
  return chunk_sorted_depths(depth_index, ref, chunks, binning);
}

DepthChunks chunk_sorted_depths(const std::vector<std::pair<float, uint32_t>>& depth_index,
                                const ReferenceCamera& ref, int chunks, ChunkBinning binning) {
  // Cuts: indices into the sorted list where a chunk begins.
  const size_t n = depth_index.size();
  std::vector<size_t> cuts;
  const int count_chunks = binning == ChunkBinning::kMixed ? chunks - chunks / 2 : chunks;
  for (int k = 0; k <= count_chunks; ++k) cuts.push_back(n * size_t(k) / size_t(count_chunks));
  if (binning == ChunkBinning::kMixed && n > 0 && chunks / 2 > 0) {
    const int disparity_chunks = chunks / 2;
    // Disparity = inverse *base-camera* depth: the parallax of a point drawn on a plane at the
    // wrong depth grows with |1/z - 1/d_k| in base depths, in the outer views (dx_j) and, when
    // the reference camera sits ahead of the base camera (D_shift < D_forward), in all views.
    const double fwd = ref.d_forward_eff;
    const double w_near = 1.0 / (depth_index.front().first + fwd), w_far = 1.0 / (depth_index.back().first + fwd);
    for (int k = 1; k < disparity_chunks; ++k) {
      const float z = float(1.0 / (w_near + (w_far - w_near) * double(k) / double(disparity_chunks)) - fwd);
      cuts.push_back(size_t(std::lower_bound(depth_index.begin(), depth_index.end(),
                                             std::pair<float, uint32_t>(z, 0)) - depth_index.begin()));
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  }

  // The non-empty chunks [begin, end) of the sorted list, front to back.
  std::vector<std::pair<size_t, size_t>> ranges;
  for (size_t c = 0; c + 1 < cuts.size(); ++c)
    if (cuts[c] != cuts[c + 1]) ranges.emplace_back(cuts[c], cuts[c + 1]);
  DepthChunks out;
  out.members.resize(ranges.size());
  out.plane_depth.resize(ranges.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long c = 0; c < long(ranges.size()); ++c) {
    const auto [b, e] = ranges[size_t(c)];
    std::vector<uint32_t>& ids = out.members[size_t(c)];
    ids.resize(e - b);
    for (size_t i = b; i < e; ++i) ids[i - b] = depth_index[i].second;
    // Keep scene order inside a chunk: the rasterizer sorts by depth itself, and scene order
    // makes its depth ties resolve as for the whole scene.
    std::sort(ids.begin(), ids.end());
    const size_t m = b + (e - b - 1) / 2;
    const float median = (e - b) % 2 ? depth_index[m].first
                                     : 0.5f * (depth_index[m].first + depth_index[m + 1].first);
    out.plane_depth[size_t(c)] = median + ref.d_forward_eff;  // reference depth -> base depth
  }
  return out;
}

}  // namespace lfd::render
