#pragma once
// G2LF stage 3 on the GPU (paper section "Swizzle blending", Alg. 1 lines 6-12): the twin of
// render/swizzle_blend.hpp. A compute pass composites the sweeping planes of a GlPlanes front to
// back into every view's tile of a quilt texture, reading the plane count and depths from the
// plane table on the GPU (so it follows the binning pass without a read-back).
//
// Quilt textures are GL_TEXTURE_2D with rows bottom-up (GL's convention): view 0's tile is at
// the bottom left, as in the quilt file seen upright (render/quilt_layout.hpp). Texels outside
// the tiles are left as they are (the caller clears them once; the CPU's are 0).
#include <map>
#include <utility>

#include <glm/glm.hpp>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/swizzle_blend.hpp"

namespace lfd::gpu {

// Views one invocation composites (they share the per-plane factors and the plane rows they
// read; docs/gpu.md "Swizzle"). 1 is one invocation per view pixel, as before.
inline constexpr int kSwizzleViewsPerInvocation = 8;

struct SwizzleOptions {
  int views_per_invocation = kSwizzleViewsPerInvocation;  // 1-64
  // The sample positions from a views x planes table a compute pass writes each frame from
  // the plane depths on the GPU (gpu/planes/shaders/swizzle_table.comp.glsl: the same floats), instead
  // of per pixel and plane.
  bool factor_table = true;
  // Bilinear planes sampled by the texture unit (its own weights, one fetch) instead of four
  // texelFetches with the CPU's weights: within the tests' tolerance of the CPU's filter, not
  // bit for bit (docs/gpu.md "Swizzle"; 134-144 dB on llvmpipe, swizzle 2.5x faster there).
  bool hardware_bilinear = true;
  bool operator==(const SwizzleOptions&) const = default;
};

class GlSwizzle {
 public:
  explicit GlSwizzle(int views_per_invocation = kSwizzleViewsPerInvocation);
  explicit GlSwizzle(const SwizzleOptions& options);
  const SwizzleOptions& options() const { return options_; }

  // Writes every view of `geometry` into `quilt` (GL_RGBA8, GL_RGBA16F or GL_RGBA32F; the
  // layout's size). Enqueues GPU work only.
  void run(const GlPlanes& planes, const render::QuiltGeometry& geometry,
           const render::ReferenceCamera& ref, const render::QuiltLayout& layout,
           render::PlaneFilter filter, const glm::vec3& background, const Texture& quilt);

 private:
  const Program& program(render::PlaneFilter filter, GLenum quilt_format);
  void write_table(const GlPlanes& planes, const render::QuiltGeometry& geometry, const render::ReferenceCamera& ref);
  SwizzleOptions options_;
  std::map<std::pair<int, GLenum>, Program> programs_;
  Program table_;
  Sampler linear_;  // hardware_bilinear's
  Buffer view_offsets_, plane_factors_, view_plane_columns_;
};

// A quilt texture of the layout's size, cleared to 0 (as the CPU's quilt image).
Texture make_quilt_texture(const render::QuiltLayout& layout, GLenum internal_format = GL_RGBA8);
// Read back as the CPU's top-down image: read_image_top_down (gpu/splats/gl_per_view_renderer.hpp).

}  // namespace lfd::gpu
