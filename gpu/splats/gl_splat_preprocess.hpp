#pragma once
// Pass 1 of the GL per-view renderer, per Gaussian, in a compute shader
// (gpu/splats/shaders/splat_preprocess.comp.glsl): exactly render::preprocess (render/preprocess.hpp;
// forward.cu preprocessCUDA): near cull z <= 0.2, 3D covariance from scale, rotation and
// scale_modifier, EWA projection with the 1.3 tan(fov/2) Jacobian clamp (shifted with the
// principal point), + RasterSettings::dilation_px2, conic, radius ceil(3 sqrt(lambda_max)), the
// 16x16 tile rectangle, SH colour (degree 0-3) seen from settings.sh_origin or the camera
// centre, +0.5 and clamped at 0. Also writes what the sort and the draw need, so nothing is read
// back on the CPU inside a frame:
//   records[i]  SplatRecord of Gaussian i (radius 0 when culled)
//   keys[i]     view-space depth as float bits (depth > 0.2, so the bits order as the floats);
//               0xFFFFFFFF when culled, so culled Gaussians sort after every visible one
//   values[i]   i
//   draw        a DrawArraysIndirectCommand {4, visible, 0, 0}: the visible count is counted with
//               an atomic, so after the sort the first `visible` values are the visible
//               Gaussians front to back and glDrawArraysIndirect draws exactly those.
#include <cstddef>
#include <cstdint>

#include <epoxy/gl.h>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_scene.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "gpu/splats/shaders/splat_record_io.h"
#include "render/camera.hpp"
#include "render/preprocess.hpp"

namespace lfd::gpu {

static_assert(sizeof(SplatRecord) == 64);  // std430 (gpu/splats/shaders/splat_record_io.h)

// DrawArraysIndirectCommand (GL 4.2): one triangle-strip quad per instance.
struct DrawArraysIndirect {
  uint32_t count, instance_count, first, base_instance;
};

// Per-Gaussian buffers of one view, reused from frame to frame.
struct SplatBuffers {
  Buffer records, keys, values, draw, depth_range;
  size_t capacity = 0;  // Gaussians
  void ensure(size_t gaussians);
  size_t bytes() const {
    return records.bytes() + keys.bytes() + values.bytes() + draw.bytes() + depth_range.bytes();
  }
};

class GlSplatPreprocess {
 public:
  GlSplatPreprocess();  // needs a current context; compiles the compute shader
  // Fills `buffers` (grown to the scene) for `camera`; resets draw to {4, 0, 0, 0} first.
  // The SH degree is min(settings.sh_degree or the scene's, the uploaded degree). Ends with the
  // memory barriers the sort, the indirect draw and buffer downloads need.
  void run(const GlScene& scene, const render::Camera& camera, const render::RasterSettings& settings,
           SplatBuffers& buffers) const;

 private:
  Program program_;
};

}  // namespace lfd::gpu
