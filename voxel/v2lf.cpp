#include "voxel/v2lf.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "util/error.hpp"
#include "voxel/plane_lowpass.hpp"
#include "voxel/voxel_rasterizer.hpp"
#include "voxel/voxel_split.hpp"

namespace lfd::voxel {

void V2lfOptions::check(const render::QuiltGeometry& geometry) const {
  planes.check(geometry);
  if (split_levels < 0 || split_levels > 4)
    throw_input_error("V2LF options: split_levels: {} is outside 0..4", split_levels);
}

namespace {

// Reference-camera depth of a voxel's centre and half its depth extent (a box's extent along a
// unit axis f is its edge times |f.x| + |f.y| + |f.z|).
struct DepthSpan {
  float centre, half;
};

DepthSpan depth_span(const scene::VoxelScene& scene, size_t i, const render::Camera& camera) {
  const glm::vec3 f = glm::abs(camera.forward());
  return {camera.to_camera(scene.voxel_center(i)).z, 0.5f * scene.voxel_size(i) * (f.x + f.y + f.z)};
}

// Any corner in front of the camera.
bool in_front(const DepthSpan& s) { return s.centre + s.half > 0.0f; }

// Chunk boundaries: boundary k is where chunk k + 1 begins (a centre at or beyond it belongs
// to chunk k + 1 or later).
class Boundaries {
 public:
  explicit Boundaries(std::vector<float> starts) : b_(std::move(starts)) {}
  int chunk_of(float depth) const { return int(std::upper_bound(b_.begin(), b_.end(), depth) - b_.begin()); }
  // A boundary lies strictly inside the depth extent.
  bool straddles(const DepthSpan& s) const {
    const auto it = std::upper_bound(b_.begin(), b_.end(), s.centre - s.half);
    return it != b_.end() && *it < s.centre + s.half;
  }

 private:
  std::vector<float> b_;
};

}  // namespace

VoxelChunks bin_voxels_by_depth(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                                const render::ReferenceCamera& ref, int chunks,
                                render::ChunkBinning binning, int split_levels) {
  (void)geometry;
  std::vector<float> depth(scene.size());
  std::vector<std::pair<float, uint32_t>> depth_index;
  for (uint32_t i = 0; i < scene.size(); ++i) {
    const DepthSpan s = depth_span(scene, i, ref.camera);
    depth[i] = s.centre;
    if (in_front(s)) depth_index.emplace_back(s.centre, i);
  }
  std::sort(depth_index.begin(), depth_index.end());
  VoxelChunks out;
  out.chunks = render::chunk_sorted_depths(depth_index, ref, chunks, binning);
  if (split_levels <= 0 || out.chunks.members.size() < 2) {
    out.scene = scene;
    return out;
  }
  std::vector<float> starts;
  for (size_t k = 1; k < out.chunks.members.size(); ++k) {
    float first = depth[out.chunks.members[k].front()];
    for (uint32_t i : out.chunks.members[k]) first = std::min(first, depth[i]);
    starts.push_back(first);
  }
  const Boundaries boundaries(std::move(starts));

  out.scene = scene;
  scene::VoxelScene& s = out.scene;
  const size_t input_size = scene.size();
  // Replace a straddling voxel by its children, recursively; each ends in its centre's chunk.
  const auto place = [&](auto&& self, size_t i, int extra) -> void {
    const DepthSpan span = depth_span(s, i, ref.camera);
    if (!in_front(span)) return;
    if (extra < split_levels && s.level[i] < scene::kMaxOctreeLevel && boundaries.straddles(span)) {
      if (i < input_size) ++out.voxels_split;
      const size_t first = append_children(s, i, s);
      for (size_t c = 0; c < 8; ++c) self(self, first + c, extra + 1);
      return;
    }
    out.chunks.members[size_t(boundaries.chunk_of(span.centre))].push_back(uint32_t(i));
    if (i >= input_size) ++out.children;
  };
  std::vector<std::vector<uint32_t>> original = std::move(out.chunks.members);
  out.chunks.members.assign(original.size(), {});
  for (size_t k = 0; k < original.size(); ++k)
    for (uint32_t i : original[k]) {
      if (!boundaries.straddles(depth_span(s, i, ref.camera))) {
        out.chunks.members[k].push_back(i);  // stays in its own chunk (ties at a boundary too)
        continue;
      }
      place(place, i, 0);
    }
  // A chunk whose members all moved to neighbours is dropped (an empty subset would mean every
  // voxel to the rasterizer).
  render::DepthChunks kept;
  for (size_t k = 0; k < out.chunks.members.size(); ++k) {
    if (out.chunks.members[k].empty()) continue;
    std::sort(out.chunks.members[k].begin(), out.chunks.members[k].end());
    kept.members.push_back(std::move(out.chunks.members[k]));
    kept.plane_depth.push_back(out.chunks.plane_depth[k]);
  }
  out.chunks = std::move(kept);
  return out;
}

namespace {

// Alg. 1 lines 4-5 for voxels: every chunk through the exact voxel rasterizer from the reference
// camera (zero background, SH from the base camera), low-pass filtered in place of
// supersampling. `lowpass_scene` is the input scene (the filter's voxel sizes).
render::SweepingPlanes render_voxel_planes(const VoxelChunks& binned, const scene::VoxelScene& lowpass_scene,
                                           const render::QuiltGeometry& geometry,
                                           const render::ReferenceCamera& ref, const render::G2lfOptions& o) {
  const float lowpass = o.adaptive_filter ? plane_lowpass_variance(lowpass_scene, geometry, ref, o.plane_scale) : 0.0f;
  const RayOrder order(binned.scene);  // once per frame, not per chunk
  return render::make_sweeping_planes(ref, binned.chunks.plane_depth, o.precision, [&](int k) {
    render::RasterImage image = rasterize_voxels_exact(binned.scene, order, ref.camera, glm::vec3(0.0f),
                                                       binned.chunks.members[size_t(k)],
                                                       geometry.base.position_world);
    gaussian_lowpass(image, lowpass);
    return image;
  });
}

}  // namespace

void render_planes_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                        const V2lfOptions& options, const render::PlaneConsumer& consume, V2lfStats* stats) {
  options.check(geometry);
  const render::G2lfOptions& o = options.planes;
  VoxelChunks binned;
  render::SweepingPlaneStages stages;
  stages.bin = [&](const render::ReferenceCamera& ref) -> const render::DepthChunks& {
    binned = bin_voxels_by_depth(scene, geometry, ref, o.chunks, o.binning, options.split_levels);
    return binned.chunks;
  };
  stages.render_planes = [&](const render::ReferenceCamera& ref, const render::DepthChunks&) {
    return render_voxel_planes(binned, scene, geometry, ref, o);
  };
  render::SweepingPlaneStats frame;
  render::run_sweeping_planes(stages, geometry, o, consume, stats ? &frame : nullptr);
  if (stats) {
    render::copy_plane_stats(frame, *stats);
    stats->voxels_binned = frame.binned;
    stats->voxels_split = binned.voxels_split;
  }
}

ImageF render_quilt_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const V2lfOptions& options,
                         const glm::vec3& background, V2lfStats* stats) {
  ImageF quilt;
  render_planes_v2lf(
      scene, geometry, options,
      [&](const render::SweepingPlanes& planes, const render::ReferenceCamera& ref) {
        quilt = ImageF(layout.width, layout.height, 3, 0.0f);
        render::swizzle_blend(planes, geometry, ref, layout, options.planes.filter, background, quilt);
      },
      stats);
  return quilt;
}

ImageF render_quilt_v2lf(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                         const render::QuiltLayout& layout, const render::G2lfOptions& options,
                         const glm::vec3& background) {
  V2lfOptions o;
  o.planes = options;
  return render_quilt_v2lf(scene, geometry, layout, o, background);
}

}  // namespace lfd::voxel
