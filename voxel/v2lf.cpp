#include "voxel/v2lf.hpp"

#include <algorithm>
#include <numeric>

#include "voxel/voxel_rasterizer.hpp"

namespace lfd::voxel {

render::DepthChunks bin_voxels_by_depth(const VoxelScene& scene, const render::QuiltGeometry& geometry,
                                        const render::ReferenceCamera& ref, int chunks) {
  std::vector<uint32_t> kept;
  std::vector<float> depth(scene.size());
  for (uint32_t i = 0; i < scene.size(); ++i) {
    depth[i] = ref.camera.to_camera(scene.voxel_center(i)).z;
    // The nearest corner's depth is at least centre depth - half diagonal.
    if (depth[i] + 0.87f * scene.voxel_size(i) > 0.0f) kept.push_back(i);
  }
  std::stable_sort(kept.begin(), kept.end(), [&](uint32_t a, uint32_t b) { return depth[a] < depth[b]; });
  render::DepthChunks out;
  const size_t n = kept.size(), k = std::min<size_t>(size_t(std::max(chunks, 1)), n);
  for (size_t c = 0; c < k; ++c) {
    const size_t first = c * n / k, last = (c + 1) * n / k;
    std::vector<uint32_t> members(kept.begin() + ptrdiff_t(first), kept.begin() + ptrdiff_t(last));
    const glm::vec3 median = scene.voxel_center(members[members.size() / 2]);
    out.plane_depth.push_back(glm::dot(median - geometry.base.position_world, geometry.base.forward()));
    out.members.push_back(std::move(members));
  }
  return out;
}

ImageF render_quilt_v2lf(const VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const render::G2lfOptions& options,
                         const glm::vec3& background) {
  options.check(geometry);
  const float d_shift = options.d_shift >= 0.0f ? options.d_shift
                                                : render::make_reference_camera(geometry, 0.0f, 1).d_forward;
  const render::ReferenceCamera ref = render::make_reference_camera(geometry, d_shift, options.plane_scale);
  const render::DepthChunks chunks = bin_voxels_by_depth(scene, geometry, ref, options.chunks);
  const render::SweepingPlanes planes = render::make_sweeping_planes(
      ref, chunks.plane_depth, options.precision, [&](int k) {
        return rasterize_voxels_exact(scene, ref.camera, glm::vec3(0.0f), chunks.members[size_t(k)],
                                      geometry.base.position_world);
      });
  ImageF quilt(layout.width, layout.height, 3, 0.0f);
  render::swizzle_blend(planes, geometry, ref, layout, options.filter, background, quilt);
  return quilt;
}

}  // namespace lfd::voxel
