#pragma once
// The GL per-view tests' comparison with the CPU rasterizer, shared by the hardware path's tests
// (gl_per_view_test.cpp) and the compute path's (gl_tile_splats_test.cpp): the bar (issue #9:
// >= 40 dB colour and transmittance), the generated scene and camera they use, and one view
// compared with the PSNR printed (the figures docs/gpu.md quotes).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "gpu/gl_per_view_renderer.hpp"
#include "render/image_metrics.hpp"
#include "render/rasterizer_cpu.hpp"
#include "render/scene_generator.hpp"

namespace lfd::gpu::testing {

constexpr double kMinPsnrDb = 40.0;

inline ImageF to_image(const std::vector<float>& values, int width, int height, int channels) {
  ImageF image(width, height, channels);
  image.pixels = values;
  return image;
}

inline ImageF rgb_of(const render::RasterImage& r) { return to_image(r.rgb, r.width, r.height, 3); }

inline scene::GaussianScene generated_scene(int sh_degree, size_t count = 4000) {
  render::SceneGeneratorOptions options;
  options.count = count;
  options.sh_degree = sh_degree;
  options.seed = 3;
  return render::generate_scene(options);
}

inline render::Camera tabletop_camera(int width = 128, int height = 128) {
  return render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.8f, width, height);
}

// GL and CPU images of one view; PSNR of the colour and the transmittance, both >= the bar.
inline double compare_view(GlPerViewRenderer& renderer, const scene::GaussianScene& scene,
                           const render::Camera& camera, const render::RasterSettings& settings,
                           const std::string& what) {
  const render::RasterImage cpu = render::rasterize(scene, camera, settings);
  const render::RasterImage gl = renderer.render_view_image(camera, settings);
  EXPECT_EQ(gl.width, cpu.width);
  EXPECT_EQ(gl.height, cpu.height);
  const double colour = render::psnr(rgb_of(gl), rgb_of(cpu));
  const double transmittance = render::psnr(to_image(gl.transmittance, gl.width, gl.height, 1),
                                            to_image(cpu.transmittance, cpu.width, cpu.height, 1));
  std::printf("[ psnr ] %s: colour %.1f dB, transmittance %.1f dB\n", what.c_str(), colour, transmittance);
  EXPECT_GE(colour, kMinPsnrDb) << what;
  EXPECT_GE(transmittance, kMinPsnrDb) << what;
  return colour;
}

}  // namespace lfd::gpu::testing
