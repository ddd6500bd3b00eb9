#pragma once
// Pass 3 of the GL per-view renderer: the sorted visible splats as instanced quads
// (gpu/splats/shaders/splat_raster.{vert,frag}.glsl), drawn with glDrawArraysIndirect so the visible
// count never comes back to the CPU, blended front to back into a float target that holds the
// premultiplied colour C and the transmittance T.
//
// Blending. The target starts at (C, T) = (0, 0, 0, 1). The fragment shader outputs
// (c alpha, alpha) with the reference's rules (power = -0.5 (a dx^2 + c dy^2) - b dx dy with pixel
// centres at integer coordinates, skip power > 0, alpha = min(0.99, o exp(power)), skip
// alpha < 1/255), and glBlendFuncSeparate(GL_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE_MINUS_SRC_ALPHA)
// gives C += c alpha T and T *= (1 - alpha): the reference composite C = sum c_i a_i T_i, with T
// itself kept (not 1 - T, which would lose T's relative precision once it is small).
// Not exact: the reference stops a pixel before the splat that would take T below 1e-4 (at
// some T_s, T_s (1 - alpha) < 1e-4, so T_s < 1e-4 / 0.01 = 0.01); fixed blending cannot read T,
// so GL blends that splat and the later ones too. They add at most T_s max(colour) and remove
// at most T_s bg: on such a pixel the difference is below T_s max(colour, background), usually
// ~1e-4 and at worst 0.01 (a 0.99-opaque splat arriving at T just under 0.01). Everywhere else
// the results agree to float rounding with an RGBA32F target (RGBA16F rounds each blend step
// to 2^-11 relative). The measured PSNR against the CPU reference is in docs/gpu.md.
// The background comes last (composite_*): out = C + T bg.
//
// Targets. A SplatRasterTarget is a framebuffer region: the view's pixel size and the window
// position of its bottom-left corner, so a view can be drawn straight into its quilt tile;
// image row 0 (the top) lands at the region's top row. Layered: a per-sorted-splat layer
// buffer (binding kSplatLayersBinding) routes each splat to a layer of a 2D array texture through
// gl_Layer in the vertex shader (GL_ARB_shader_viewport_layer_array), so G2LF draws all chunk
// planes in one instanced draw; with a zero background the planes hold (C, T).
#include <glm/glm.hpp>

#include "gpu/compute/gl_tile_keys.hpp"
#include "gpu/gl/gl_objects.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"

namespace lfd::gpu {

struct SplatRasterTarget {
  GLuint framebuffer = 0;            // colour attachment 0 holds (C, T)
  glm::ivec2 image_size{0};          // the view's size in pixels (its camera's)
  glm::ivec2 viewport_origin{0};     // window coordinates of the view's bottom-left pixel
  // Window region drawn into (x, y, width, height); width 0: the whole view. A quilt tile
  // smaller than the view crops it, as render::place_view does.
  glm::ivec4 scissor{0};
};

// The render state every front-to-back pass into a SplatRasterTarget shares: the framebuffer,
// viewport and scissor of the target's region, no depth, stencil or culling (begin), and back
// to the default framebuffer (end). The voxel raster draws into the same targets.
void begin_raster_target(const SplatRasterTarget& target);
void end_raster_target();
// The front-to-back blend on a (C, T) target for premultiplied (c alpha, alpha) fragments:
// C += c alpha T, T *= 1 - alpha.
void enable_front_to_back_blend();

class GlSplatRaster {
 public:
  GlSplatRaster();  // needs a current context; the layered program needs the extension

  // Sets the target region (every layer of a layered target) to C = 0, T = 1.
  void clear(const SplatRasterTarget& target) const;

  // Draws sorted splats front to back: instance i is Gaussian sorted_ids[i] (its SplatRecord in
  // `records`), the instance count is read from `indirect` (a DrawArraysIndirect, as written by
  // GlSplatPreprocess). `layers` (optional): layer of instance i, for a layered target.
  void draw(const Buffer& records, const Buffer& sorted_ids, const Buffer& indirect,
            const SplatRasterTarget& target, const Buffer* layers = nullptr) const;
  // The same with the buffers of GlSplatPreprocess::run after GlRadixSort::sort(keys, values).
  void draw(const SplatBuffers& buffers, const SplatRasterTarget& target, const Buffer* layers = nullptr) const;

  // In place: rgb = C + T bg; alpha stays T (TargetAlpha::kTransmittance) or becomes 1.
  void composite_background(const SplatRasterTarget& target, const glm::vec3& background,
                            TargetAlpha alpha) const;
  // From an accumulation texture (C, T) of target.image_size into the target region (e.g. an
  // RGBA8 quilt tile): rgb = C + T bg, alpha 1.
  void composite_from(const Texture& accumulation, const SplatRasterTarget& target,
                      const glm::vec3& background) const;

 private:
  void begin(const SplatRasterTarget& target) const;  // begin_raster_target + the vertex array
  void end() const;
  Program splats_, splats_layered_, composite_blend_, composite_copy_;
  VertexArray vertex_array_;
};

}  // namespace lfd::gpu
