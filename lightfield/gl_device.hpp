#pragma once
// A GL device: the context the GL renderers render in (a headless EGL context of its own, or
// the context current on this thread, such as the viewer's window), the scene they share
// uploaded once (so a per-view and a sweeping-plane renderer on one device hold one copy, as
// GPU memory figures assume), and the quilt texture they render into and read back on demand.
// GPU memory is what lfd's buffers and textures hold (gpu/gl/gl_objects.hpp).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

#include <epoxy/gl.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/voxels/gl_voxel_scene.hpp"
#include "scene/scene.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"

namespace lfd::lightfield {

class GlDevice {
 public:
  // A headless context of its own; throws gpu::GlUnavailable (exit 2, one line) without one.
  static std::shared_ptr<GlDevice> open_headless();
  // Takes over a context already made (`lfd render --backend auto` makes it to decide); null
  // for none (the CPU).
  static std::shared_ptr<GlDevice> adopt(std::unique_ptr<gpu::HeadlessContext> context);
  // The context current on this thread, which outlives the device; `info` describes it.
  static std::shared_ptr<GlDevice> on_current_context(const gpu::GlInfo& info);
  ~GlDevice();
  GlDevice(const GlDevice&) = delete;
  GlDevice& operator=(const GlDevice&) = delete;

  const gpu::GlInfo& info() const { return info_; }

  // The scene its renderers render: uploaded unless it is the one uploaded (scene::Scene::id).
  // The device lets go of the old scene before uploading (a lower peak); renderers still bound
  // to it keep it until they bind again.
  void upload(const scene::Scene& scene);
  // A Gaussian scene uploaded with `options` (the viewer's: a fitting SH degree, progress).
  void upload(const scene::GaussianScene& scene, const gpu::GlSceneOptions& options);
  void upload(const scene::VoxelScene& scene);
  // The uploaded scene of that kind (null if the device holds the other kind or none), and a
  // count that changes with every upload (renderers bind again when it does).
  std::shared_ptr<const gpu::GlScene> gaussians() const { return gaussians_; }
  std::shared_ptr<const gpu::GlVoxelScene> voxels() const { return voxels_; }
  uint64_t scene_generation() const { return generation_; }

  // The quilt texture, (re)allocated (cleared to 0) when the layout's size or the format change.
  gpu::Texture& quilt(const render::QuiltLayout& layout, GLenum format);
  // Reads the quilt back (RGB, top row first).
  const ImageF& read_quilt();

  static std::string memory_kind() { return "GPU memory (lfd's buffers and textures)"; }
  static void reset_peak_memory();
  static size_t peak_memory_bytes();

 private:
  GlDevice(std::unique_ptr<gpu::HeadlessContext> context, const gpu::GlInfo& info);
  void drop_scene();

  std::unique_ptr<gpu::HeadlessContext> context_;  // first: everything after it needs the context
  gpu::GlInfo info_;
  std::shared_ptr<const gpu::GlScene> gaussians_;
  std::shared_ptr<const gpu::GlVoxelScene> voxels_;
  uint64_t uploaded_id_ = 0;  // scene::Scene::id of the upload; 0: none or another source
  uint64_t generation_ = 0;
  gpu::Texture quilt_;
  ImageF image_;
};

}  // namespace lfd::lightfield
