#include "gpu/probes/gl_raster_probe.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <vector>

#include <epoxy/gl.h>

#include "gpu/gl/gl_context.hpp"
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

// Both paths' median quilt time; `frame(path)` renders one probe quilt by `path`.
RasterProbe time_both_paths(RasterSubject subject, const std::function<void(RasterPath)>& frame) {
  RasterProbe probe;
  probe.subject = subject;
  probe.hardware_s = median_frame_seconds([&] { frame(RasterPath::kHardware); });
  probe.compute_s = median_frame_seconds([&] { frame(RasterPath::kCompute); });
  probe.faster = probe.compute_s <= probe.hardware_s ? RasterPath::kCompute : RasterPath::kHardware;
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
  GlPerViewOptions compute;
  compute.raster = RasterPath::kCompute;
  GlPerViewRenderer renderers[2] = {GlPerViewRenderer(gl_scene), GlPerViewRenderer(gl_scene, compute)};
  return time_both_paths(RasterSubject::kGaussians, [&](RasterPath path) {
    renderers[path == RasterPath::kCompute ? 1 : 0].render_quilt(q.geometry, q.layout, {}, q.texture);
  });
}

RasterProbe probe_voxels() {
  voxel::VoxelGeneratorOptions g;
  g.detail_level = 5;
  const scene::VoxelScene scene = voxel::generate_voxel_scene(g);
  const GlVoxelScene gl_scene(scene, query_gl_info("current context"));
  ProbeQuilt q(render::make_look_at_camera({0, -1.5f, -5.5f}, {0, 0.5f, 0}, {0, -1, 0}, 0.8f, 96, 96), 5.85f);
  GlVoxelViews views[2] = {GlVoxelViews(gl_scene, RasterPath::kHardware), GlVoxelViews(gl_scene, RasterPath::kCompute)};
  return time_both_paths(RasterSubject::kVoxels, [&](RasterPath path) {
    views[path == RasterPath::kCompute ? 1 : 0].render_quilt(q.geometry, q.layout, {}, q.texture);
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
