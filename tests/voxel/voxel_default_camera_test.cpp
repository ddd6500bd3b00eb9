// The default camera of a generated scene sits in empty space, so per-view and V2LF quilts of it
// agree (docs/voxels.md, "Rendering": it sat within the sky shell's thickness, and the per-view
// quilt showed only the shell from behind, 13 dB from V2LF's).
#include <gtest/gtest.h>

#include <cmath>

#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::voxel {
namespace {

bool inside_a_voxel(const scene::VoxelScene& s, const glm::vec3& p) {
  for (size_t i = 0; i < s.size(); ++i) {
    const glm::vec3 lo = s.voxel_min(i), hi = lo + s.voxel_size(i);
    if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z) return true;
  }
  return false;
}

TEST(VoxelDefaultCamera, EveryViewCameraOfTheDefaultCameraIsOutsideEveryVoxel) {
  for (int level : {6, 8}) {
    VoxelGeneratorOptions o;
    o.detail_level = level;
    const scene::VoxelScene s = generate_voxel_scene(o);
    const render::CameraSpec spec = frame_voxel_scene(s);
    EXPECT_FALSE(inside_a_voxel(s, spec.position)) << "level " << level;
    const render::Camera base = render::camera_from_spec(spec, 32, 32);
    const render::QuiltGeometry g =
        render::make_quilt_geometry(base, glm::length(spec.look_at - spec.position), 40.0f, 4);
    for (int v = 0; v < 4; ++v)
      EXPECT_FALSE(inside_a_voxel(s, g.view_camera(v).position_world)) << "level " << level << " view " << v;
  }
}

TEST(VoxelDefaultCamera, PerViewAndV2lfQuiltsOfTheDefaultCameraAgree) {
  VoxelGeneratorOptions o;  // level 8: its old default camera sat within the shell's thickness
  o.sh_degree = 0;
  scene::VoxelScene s = generate_voxel_scene(o);
  s.supersampling = 1.0f;
  const render::CameraSpec spec = frame_voxel_scene(s);
  const render::Camera base = render::camera_from_spec(spec, 64, 64);
  const render::QuiltGeometry g =
      render::make_quilt_geometry(base, glm::length(spec.look_at - spec.position), 40.0f, 4);
  const render::QuiltLayout layout = render::make_quilt_layout(g, 2, 2);
  const ImageF truth = render_voxel_quilt_per_view(s, g, layout);
  render::G2lfOptions options;
  options.chunks = 64;
  options.precision = render::PlanePrecision::kF32;
  const ImageF v2lf = render_quilt_v2lf(s, g, layout, options, s.background);
  EXPECT_GE(render::psnr(v2lf, truth), 20.0);
}

}  // namespace
}  // namespace lfd::voxel
