#include "gpu/gl_raster_probe.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl_context.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_scene.hpp"
#include "render/camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/scene_generator.hpp"

namespace lfd::gpu {
namespace {

std::optional<RasterProbe>& cached() {
  static std::optional<RasterProbe> probe;
  return probe;
}

double median_quilt_seconds(GlPerViewRenderer& renderer, const render::QuiltGeometry& geometry,
                            const render::QuiltLayout& layout, Texture& quilt) {
  std::vector<double> seconds;
  for (int run = 0; run < 4; ++run) {  // the first is the warm-up
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    renderer.render_quilt(geometry, layout, {}, quilt);
    glFinish();
    if (run > 0) seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

}  // namespace

RasterProbe probe_raster_paths() {
  render::SceneGeneratorOptions g;
  g.count = 10000;
  g.seed = 5;
  const scene::GaussianScene scene = render::generate_scene(g);
  const GlScene gl_scene(scene, query_gl_info("current context"));
  const render::Camera base = render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.8f, 128, 128);
  const render::QuiltGeometry geometry = render::make_quilt_geometry(base, 5.1f, 40.0f, 4);
  const render::QuiltLayout layout = render::make_quilt_layout(geometry, 2, 2);
  Texture quilt(GL_RGBA8, layout.width, layout.height);
  RasterProbe probe;
  {
    GlPerViewRenderer hardware(gl_scene);
    probe.hardware_s = median_quilt_seconds(hardware, geometry, layout, quilt);
  }
  {
    GlPerViewOptions o;
    o.raster = RasterPath::kCompute;
    GlPerViewRenderer compute(gl_scene, o);
    probe.compute_s = median_quilt_seconds(compute, geometry, layout, quilt);
  }
  probe.faster = probe.compute_s <= probe.hardware_s ? RasterPath::kCompute : RasterPath::kHardware;
  cached() = probe;
  return probe;
}

RasterPath resolve_raster_path(RasterPath requested) {
  if (requested != RasterPath::kAuto) return requested;
  if (!cached()) probe_raster_paths();
  return cached()->faster;
}

std::optional<RasterProbe> last_raster_probe() { return cached(); }

}  // namespace lfd::gpu
