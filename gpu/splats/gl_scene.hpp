#pragma once
// A Gaussian scene uploaded once into shader storage buffers (docs/gpu.md "Per-view renderer"),
// read by every GL pass (the per-view preprocess, G2LF). Layouts are std430 and vec4-packed so
// a Gaussian's data is whole 16-byte loads:
//   binding kScenePositionsBinding  vec4 positions[]  (x, y, z, opacity)
//   binding kSceneScalesBinding     vec4 scales[]     (linear scale x, y, z, 0)
//   binding kSceneRotationsBinding  vec4 rotations[]  (unit quaternion w, x, y, z)
//   binding kSceneShBinding         vec4 sh[]         per Gaussian sh_vec4_stride() vec4s holding the
//                            (degree+1)^2 RGB triples coefficient-major (as GaussianScene::sh),
//                            zero-padded to a whole vec4.
// Scale and rotation are kept (not the 3D covariance) so RasterSettings::scale_modifier applies
// per frame, as in the reference's computeCov3D; the covariance costs ~30 flops per Gaussian.
#include <cstddef>
#include <functional>

#include <epoxy/gl.h>

#include "gpu/gl/gl_context.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/shaders/frame_io.h"
#include "scene/gaussian_scene.hpp"

namespace lfd::gpu {

// vec4s of SH per Gaussian at `sh_degree`: ceil(3 (degree+1)^2 / 4) = 1, 3, 7, 12.
int sh_vec4_stride(int sh_degree);

// GPU bytes per Gaussian: the scene buffers, and the per-view renderer's per-Gaussian scratch
// (splat records, sort keys and values with their ping-pong copies).
size_t scene_bytes_per_gaussian(int sh_degree);
size_t per_view_scratch_bytes_per_gaussian();

// Throws InputError (one line: the numbers and what lowers them) when `gaussians` at
// `sh_degree` need a buffer above GL_MAX_SHADER_STORAGE_BLOCK_SIZE, more than the free GPU
// memory the driver reports, or more than 2^32 - 1 Gaussians (32-bit indices).
void check_scene_fits(size_t gaussians, int sh_degree, const GlInfo& info);

// The largest SH degree <= `scene_degree` (3 -> 2 -> 1 -> 0) at which `gaussians` pass
// check_scene_fits: a viewer shows a big scene with fewer colour coefficients rather than not at
// all. When even degree 0 does not fit, throws check_scene_fits' refusal at degree 0.
int fitting_sh_degree(size_t gaussians, int scene_degree, const GlInfo& info);

struct GlSceneOptions {
  int max_sh_degree = -1;  // -1: the scene's degree; lower to upload fewer coefficients
  // Called after each uploaded chunk with (Gaussians uploaded, total); may be empty. A viewer
  // draws its progress bar there (the upload is GL calls on the caller's thread).
  std::function<void(size_t done, size_t total)> progress;
  // Gaussians packed and uploaded per step: smaller steps, finer progress; same buffers.
  size_t chunk_gaussians = size_t(1) << 20;
};

class GlScene {
 public:
  // Needs a current context; `info` its limits (HeadlessContext::info() or query_gl_info).
  GlScene(const scene::GaussianScene& scene, const GlInfo& info, const GlSceneOptions& options = {});

  size_t size() const { return count_; }
  int sh_degree() const { return sh_degree_; }  // the uploaded degree
  int sh_vec4_stride() const { return gpu::sh_vec4_stride(sh_degree_); }
  size_t bytes() const;

  const Buffer& positions() const { return positions_; }
  const Buffer& scales() const { return scales_; }
  const Buffer& rotations() const { return rotations_; }
  const Buffer& sh() const { return sh_; }

 private:
  size_t count_ = 0;
  int sh_degree_ = 0;
  Buffer positions_, scales_, rotations_, sh_;
};

}  // namespace lfd::gpu
