#pragma once
// G2LF stage 2 on the GPU (paper Alg. 1 lines 4-5; the twin of render/sweeping_planes.hpp):
// every chunk rasterised from the reference camera into its plane, with GlSplatRaster's layered
// draw (gl_Layer = the splat's plane), zero background, so each layer holds (C_k, T_k).
//
// Two ways (GlG2lfOptions::plane_raster; docs/gpu.md "Planes"):
//   kLayered  one instanced indirect draw blends every chunk straight into the plane array in
//             its own format (the paper's way): RGBA32F, RGBA16F, or RGBA8 (which rounds C and
//             T at every blend step). No accumulation, no conversion, no per-batch barriers.
//   kBatched  the fallback for RGBA8 planes when RGBA16F planes exceed the memory budget: an
//             RGBA32F accumulation array of `batch_layers` layers; per batch of planes, a
//             compute pass copies the batch's splats (a contiguous run of the sorted list, found
//             on the GPU from the plane table) and writes its indirect draw, one layered draw
//             blends them in float, and a convert pass rounds each layer into its plane as the
//             CPU does (round(clamp(v, 0, 1) 255) for RGBA8) and resets the accumulation layer.
//             The batch count follows from N_chunk on the CPU; batches beyond the frame's planes
//             draw nothing.
// Both blend the splats of a plane in the sorted list's order, front to back, with the same
// blend equation: only the precision of the target differs.
#include <cstddef>

#include "gpu/gl/gl_objects.hpp"
#include "gpu/planes/gl_planes.hpp"
#include "gpu/splats/gl_splat_preprocess.hpp"
#include "gpu/splats/gl_splat_raster.hpp"
#include "gpu/splats/shaders/frame_io.h"

namespace lfd::gpu {

enum class PlaneRaster { kLayered, kBatched };
const char* plane_raster_name(PlaneRaster raster);  // "layered", "batched"

// Accumulation layers for `format` planes of `width` x `height` within `budget_bytes` (at least
// one, at most `max_planes`); 0 for RGBA32F (drawn into directly).
int plane_batch_layers(PlaneFormat format, int max_planes, int width, int height, size_t budget_bytes);
// GPU bytes of the accumulation array and the per-Gaussian batch buffers.
size_t plane_raster_bytes(PlaneFormat format, int batch_layers, int width, int height, size_t gaussians);

// The convert pass (gpu/splats/shaders/g2lf_plane_convert.comp.glsl) for planes of `format` ("rgba8",
// "rgba16f", "rgba32f"): an RGBA32F accumulation layer rounded into its plane as the CPU stores
// it (QUANTIZE_U8 for RGBA8). V2LF's planes go through it too (gpu/voxels/gl_v2lf.hpp).
Program plane_convert_program(const char* format, bool quantize_u8);

class GlPlaneRaster {
 public:
  GlPlaneRaster();  // needs a current context and GL_ARB_shader_viewport_layer_array

  // Rasterises the binned splats into `planes`: `records` (GlSplatPreprocess from the reference
  // camera), `sorted_ids` and `layers` (GlDepthBinning) and `draw` (its instance count = the
  // binned count) for `gaussians` Gaussians. `batch_layers`: 0 draws straight into the planes
  // (kLayered, any format), else plane_batch_layers(...) (kBatched, RGBA8 or RGBA16F planes).
  void run(const Buffer& records, const Buffer& sorted_ids, const Buffer& layers, const Buffer& draw,
           size_t gaussians, int batch_layers, GlPlanes& planes);

  size_t bytes() const;

 private:
  void ensure(const GlPlanes& planes, int batch_layers, size_t gaussians);

  GlSplatRaster raster_;
  Program batches_, copy_, convert_u8_, convert_f16_;
  Framebuffer direct_framebuffer_, accumulation_framebuffer_;
  bool direct_ready_ = false;
  Texture accumulation_;
  Buffer batch_commands_, batch_draw_, batch_ids_, batch_layers_;
};

}  // namespace lfd::gpu
