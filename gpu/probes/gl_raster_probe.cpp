#include "gpu/probes/gl_raster_probe.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_fault.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "gpu/voxels/gl_voxel_views.hpp"
#include "render/camera.hpp"
#include "render/per_view_quilt.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/scene_generator.hpp"
#include "voxel/voxel_generator.hpp"

namespace lfd::gpu {
namespace {

std::optional<RasterProbe>& cached(RasterSubject subject) {
  static std::array<std::optional<RasterProbe>, 2> probes;
  return probes[size_t(subject)];
}

// The median seconds of three frames after a warm-up, each frame bracketed by glFinish.
double median_frame_seconds(const std::function<void()>& frame) {
  std::vector<double> seconds;
  for (int run = 0; run < 4; ++run) {  // the first is the warm-up
    glFinish();
    const auto t0 = std::chrono::steady_clock::now();
    frame();
    glFinish();
    if (run > 0) seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

// Both paths' median quilt time; `make(path)` builds a renderer for `path` and returns the
// function that renders one probe quilt with it. A path that fails (cannot be built, a GL error,
// out of memory: docs/gpu.md "Drivers and limits") is recorded and the other one chosen; when both
// fail, GlPathFailed names both.
RasterProbe time_both_paths(RasterSubject subject,
                            const std::function<std::function<void()>(RasterPath)>& make) {
  RasterProbe probe;
  probe.subject = subject;
  const auto time = [&](RasterPath path, double& seconds, std::string& failure) {
    try {
      const std::function<void()> frame = make(path);
      seconds = median_frame_seconds(frame);
      check_gl("the raster probe");
    } catch (const std::exception& e) {
      failure = e.what();
      take_gl_debug_error();  // the failure is reported here, not by the next pass's check
      while (glGetError() != GL_NO_ERROR) {
      }
    }
  };
  time(RasterPath::kHardware, probe.hardware_s, probe.hardware_failure);
  time(RasterPath::kCompute, probe.compute_s, probe.compute_failure);
  if (!probe.hardware_failure.empty() && !probe.compute_failure.empty())
    throw GlPathFailed(fmt::format("--raster auto: neither raster path draws {} on this device (compute: {}; "
                                   "hardware: {})",
                                   raster_subject_name(subject), probe.compute_failure, probe.hardware_failure));
  if (!probe.compute_failure.empty()) probe.faster = RasterPath::kHardware;
  else if (!probe.hardware_failure.empty()) probe.faster = RasterPath::kCompute;
  else probe.faster = probe.compute_s <= probe.hardware_s ? RasterPath::kCompute : RasterPath::kHardware;
  const std::string& failure = probe.compute_failure.empty() ? probe.hardware_failure : probe.compute_failure;
  if (!failure.empty())
    std::fprintf(stderr, "notice: --raster auto: the %s path failed on this device (%s); drawing %s with %s\n",
                 raster_path_name(probe.faster == RasterPath::kCompute ? RasterPath::kHardware : RasterPath::kCompute),
                 failure.c_str(), raster_subject_name(subject), raster_path_name(probe.faster));
  return probe;
}

// A probe's quilt: 4 views of `base` (view cone 40 deg, focused at `focus`) in 2 x 2 tiles, RGBA8
// as a display's.
struct ProbeQuilt {
  render::QuiltGeometry geometry;
  render::QuiltLayout layout;
  Texture texture;
  ProbeQuilt(const render::Camera& base, float focus)
      : geometry(render::make_quilt_geometry(base, focus, 40.0f, 4)),
        layout(render::make_quilt_layout(geometry, 2, 2)),
        texture(GL_RGBA8, layout.width, layout.height) {}
};

RasterProbe probe_gaussians() {
  render::SceneGeneratorOptions g;
  g.count = 10000;
  g.seed = 5;
  const scene::GaussianScene scene = render::generate_scene(g);
  const GlScene gl_scene(scene, query_gl_info("current context"));
  ProbeQuilt q(render::make_look_at_camera({0, -1, -5}, {0, 0, 0}, {0, -1, 0}, 0.8f, 128, 128), 5.1f);
  std::optional<GlPerViewRenderer> renderer;
  return time_both_paths(RasterSubject::kGaussians, [&](RasterPath path) -> std::function<void()> {
    GlPerViewOptions options;
    options.raster = path;
    renderer.reset();
    renderer.emplace(gl_scene, options);
    return [&] { renderer->render_quilt(q.geometry, q.layout, {}, q.texture); };
  });
}

RasterProbe probe_voxels() {
  voxel::VoxelGeneratorOptions g;
  g.detail_level = 5;
  const scene::VoxelScene scene = voxel::generate_voxel_scene(g);
  const GlVoxelScene gl_scene(scene, query_gl_info("current context"));
  ProbeQuilt q(render::make_look_at_camera({0, -1.5f, -5.5f}, {0, 0.5f, 0}, {0, -1, 0}, 0.8f, 96, 96), 5.85f);
  std::optional<GlVoxelViews> views;
  return time_both_paths(RasterSubject::kVoxels, [&](RasterPath path) -> std::function<void()> {
    views.reset();
    views.emplace(gl_scene, path);
    return [&] { views->render_quilt(q.geometry, q.layout, {}, q.texture); };
  });
}

}  // namespace

const char* raster_subject_name(RasterSubject subject) {
  return subject == RasterSubject::kVoxels ? "voxels" : "Gaussians";
}

RasterSubject raster_subject_of(scene::SceneKind kind) {
  return kind == scene::SceneKind::kVoxels ? RasterSubject::kVoxels : RasterSubject::kGaussians;
}

RasterProbe probe_raster_paths(RasterSubject subject) {
  const RasterProbe probe = subject == RasterSubject::kVoxels ? probe_voxels() : probe_gaussians();
  cached(subject) = probe;
  return probe;
}

RasterPath resolve_raster_path(RasterPath requested, RasterSubject subject) {
  if (requested != RasterPath::kAuto) return requested;
  if (!cached(subject)) probe_raster_paths(subject);
  return cached(subject)->faster;
}

std::optional<RasterProbe> last_raster_probe(RasterSubject subject) { return cached(subject); }

}  // namespace lfd::gpu
