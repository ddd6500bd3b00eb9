// The procedural voxel scene: valid, sparse, several levels with a coarse shell, deterministic,
// and something a default camera sees.
#include <gtest/gtest.h>

#include <set>

#include "render/camera_json.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_rasterizer.hpp"

namespace lfd::voxel {
namespace {

scene::VoxelScene small_scene() {
  VoxelGeneratorOptions o;
  o.detail_level = 6;
  return generate_voxel_scene(o);
}

TEST(VoxelGenerator, MakesSparseLeavesAtSeveralLevelsWithACoarseOuterShell) {
  const scene::VoxelScene s = small_scene();
  ASSERT_GT(s.size(), 1000u);
  EXPECT_LT(s.size(), size_t(1) << 18);  // 64^3 = 262144 if it were dense at level 6
  std::set<int> levels(s.level.begin(), s.level.end());
  EXPECT_GE(levels.size(), 2u);
  EXPECT_EQ(*levels.rbegin(), 6);
  // The shell (radius 7) is made of voxels coarser than the objects near the centre.
  int shell_level = 99;
  for (size_t i = 0; i < s.size(); ++i)
    if (glm::length(s.voxel_center(i)) > 6.0f) shell_level = std::min(shell_level, int(s.level[i]));
  EXPECT_LT(shell_level, 6);
  scene::check_voxel_scene(s, "generated");
}

TEST(VoxelGenerator, SameSeedSameSceneOtherSeedOtherScene) {
  VoxelGeneratorOptions o;
  o.detail_level = 5;
  const scene::VoxelScene a = generate_voxel_scene(o), b = generate_voxel_scene(o);
  EXPECT_EQ(a.octree_index, b.octree_index);
  EXPECT_EQ(a.sh, b.sh);
  o.seed = 2;
  EXPECT_NE(generate_voxel_scene(o).sh, a.sh);
}

TEST(VoxelGenerator, TheDefaultCameraSeesOpaqueContent) {
  const scene::VoxelScene s = small_scene();
  const render::CameraSpec spec = frame_voxel_scene(s);
  const render::Camera camera = render::camera_from_spec(spec, 48, 32);
  VoxelRenderSettings settings;
  settings.supersampling = 1.0f;
  const render::RasterImage img = rasterize_voxels(s, camera, settings);
  size_t opaque = 0;
  for (float t : img.transmittance) opaque += t < 0.01f;
  // Inside the shell every ray ends on a surface.
  EXPECT_EQ(opaque, img.transmittance.size());
}

}  // namespace
}  // namespace lfd::voxel
