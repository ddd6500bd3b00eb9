#pragma once
// The GL per-view tests' comparison with the CPU rasterizer, shared by the hardware path's tests
// (gl_per_view_test.cpp) and the compute path's (gl_splat_tile_raster_test.cpp): the bar (docs/gpu.md "Per-view renderer":
// >= 40 dB colour and transmittance), the generated scene and camera they use, and one view
// compared with the PSNR printed (the figures docs/gpu.md quotes), and the quilt both compare
// with the CPU's.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "gpu/splats/gl_per_view_renderer.hpp"
#include "render/image_metrics.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
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

// The generated scene's views both paths are checked on: centre, off-axis, a background, SH
// degrees 0 and 3, and a size that is neither square nor a multiple of the 16-pixel tiles.
inline void compare_generated_views(GlPerViewRenderer& renderer, const scene::GaussianScene& scene,
                                    const std::string& prefix) {
  const auto base = tabletop_camera();
  const auto geometry = render::make_quilt_geometry(base, 5.1f, 40.0f, 9);
  for (int degree : {0, 3}) {
    render::RasterSettings settings;
    settings.sh_degree = degree;
    const std::string d = " sh" + std::to_string(degree);
    compare_view(renderer, scene, base, settings, prefix + "generated centre" + d);
    compare_view(renderer, scene, geometry.view_camera(0), settings, prefix + "generated off-axis view 0/9" + d);
    settings.background = {1.0f, 0.5f, 0.25f};
    compare_view(renderer, scene, geometry.view_camera(8), settings,
                 prefix + "generated off-axis view 8/9, background" + d);
  }
  compare_view(renderer, scene, tabletop_camera(100, 77), {}, prefix + "generated 100x77");
}

// The quilt both paths' quilt tests draw, laid out as render::render_quilt_per_view lays it (9
// views in a 4x3 grid, so the last row is partly empty and a wrong row order would show), with
// the CPU's quilt.
struct QuiltCase {
  scene::GaussianScene scene = generated_scene(2, 3000);
  render::QuiltGeometry geometry = render::make_quilt_geometry(tabletop_camera(96, 80), 5.1f, 40.0f, 9);
  render::QuiltLayout layout = render::make_quilt_layout(geometry, 4, 3);
  ImageF cpu = render::render_quilt_per_view(scene, geometry, layout);
};

// `renderer`'s quilt of the case in a `format` texture, compared with the CPU's as a whole and
// view by view (each >= the bar, the whole PSNR printed); returns it, top-down.
inline ImageF compare_quilt_with_cpu(GlPerViewRenderer& renderer, const QuiltCase& c, GLenum format,
                                     const std::string& what) {
  Texture quilt(format, c.layout.width, c.layout.height);
  renderer.render_quilt(c.geometry, c.layout, {}, quilt);
  const ImageF gl = read_image_top_down(quilt);
  const double whole = render::psnr(gl, c.cpu);
  std::printf("[ psnr ] %s: %.1f dB\n", what.c_str(), whole);
  EXPECT_GE(whole, kMinPsnrDb) << what;
  for (int view = 0; view < c.geometry.views; ++view)
    EXPECT_GE(render::psnr(render::extract_view(gl, c.layout, view), render::extract_view(c.cpu, c.layout, view)),
              kMinPsnrDb)
        << what << " view " << view;
  EXPECT_EQ(renderer.stats().views, c.geometry.views) << what;
  return gl;
}

}  // namespace lfd::gpu::testing
