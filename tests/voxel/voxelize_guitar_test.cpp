// lfd scene voxelize on a real trained scene (the guitar under ../shared/data; skipped without
// it): its centre view, voxelized at level 6, still looks like the Gaussians' render.
#include <gtest/gtest.h>

#include <algorithm>

#include "render/camera.hpp"
#include "render/image_metrics.hpp"
#include "render/rasterizer_cpu.hpp"
#include "scene/gaussian_io.hpp"
#include "tests/test_data.hpp"
#include "voxel/voxel_rasterizer.hpp"
#include "voxel/voxelize.hpp"

namespace lfd::voxel {
namespace {

ImageF to_image(const render::RasterImage& r) {
  ImageF image(r.width, r.height, 3);
  for (size_t k = 0; k < image.pixels.size(); ++k) image.pixels[k] = std::clamp(r.rgb[k], 0.0f, 1.0f);
  return image;
}

TEST(VoxelizeGuitar, TheCentreViewKeepsItsStructure) {
  LFD_REQUIRE_SHARED_FILE("scenes/guitar.compressed.ply");
  const scene::GaussianScene gaussians = scene::load_gaussian_scene(test::shared_data() / "scenes/guitar.compressed.ply");
  VoxelizeOptions options;
  options.max_level = 6;
  const scene::VoxelScene voxels = voxelize(gaussians, options);
  // The camera of docs/voxels.md's measurements (gcam.json), at 64x64.
  const render::Camera camera = render::make_look_at_camera({0.07f, -2.1f, -5.0f}, {0.07f, -2.1f, 0.2f}, {0, -1, 0},
                                                            glm::radians(40.0f), 64, 64);
  const ImageF truth = to_image(render::rasterize(gaussians, camera));
  const ImageF voxel_view = to_image(rasterize_voxels(voxels, camera));
  const ImageF black(64, 64, 3, 0.0f);
  // 29.7 dB measured; the bar is meaningful only above the black background's own score.
  const double bar = 26.0;
  EXPECT_LT(render::psnr(truth, black), bar - 3.0);
  EXPECT_GT(render::psnr(truth, voxel_view), bar);
  EXPECT_GT(render::ssim(truth, voxel_view), 0.8);
}

}  // namespace
}  // namespace lfd::voxel
