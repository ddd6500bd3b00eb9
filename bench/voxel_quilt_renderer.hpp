#pragma once
// The backend hook of `lfd bench voxels`, as QuiltRenderer is `lfd bench render`'s: the per-view
// voxel quilt and V2LF on the CPU (voxel/) or on the GL voxel path (gpu/gl_voxel_views.hpp,
// gpu/gl_v2lf.hpp) of a headless EGL context. A frame call returns when the quilt is complete
// (GL: glFinish), so its wall time is the frame; the quilt is read back in read_quilt, untimed.
#include <memory>
#include <string>

#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "util/image.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_scene.hpp"

namespace lfd::bench {

class VoxelQuiltRenderer {
 public:
  virtual ~VoxelQuiltRenderer() = default;
  virtual std::string name() const = 0;    // "cpu", "gl"
  virtual std::string device() const = 0;  // for the report
  virtual int default_runs() const = 0;

  // The scene of the following frames (a GPU backend uploads it here, untimed); it outlives them.
  virtual void set_scene(const voxel::VoxelScene& scene) = 0;
  virtual void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) = 0;
  virtual voxel::V2lfStats render_v2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                       const voxel::V2lfOptions& options) = 0;
  // The last frame's quilt (RGB, rows top-down).
  virtual const ImageF& read_quilt() = 0;

  virtual std::string memory_kind() const = 0;  // what peak_memory_bytes counts
  virtual void reset_peak_memory() = 0;
  virtual size_t peak_memory_bytes() const = 0;
};

std::unique_ptr<VoxelQuiltRenderer> make_cpu_voxel_renderer();
// Throws gpu::GlUnavailable (exit 2, one line) when no OpenGL 4.5 core context can be made.
std::unique_ptr<VoxelQuiltRenderer> make_gl_voxel_renderer();

}  // namespace lfd::bench
