// One projected Gaussian, std430, 64 bytes: what the preprocess passes write per Gaussian (or per
// view and Gaussian) and the raster, binning and tile passes read (docs/gpu.md "Per-view
// renderer"). Declared once, read by C++ and GLSL (gpu/gl/shaders/shader_io.h): vec4 and ivec4
// are glm's in C++, 16 bytes each with 4-byte alignment, so the C++ struct is the std430 one.
#ifndef LFD_GPU_SPLATS_SHADERS_SPLAT_RECORD_IO_H
#define LFD_GPU_SPLATS_SHADERS_SPLAT_RECORD_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

struct SplatRecord {
  vec4 mean_depth_opacity;  // mean_px.xy (pixel (i, j) centred at (i, j), row 0 = top), view z, opacity
  vec4 conic_radius;        // conic (xx, xy, yy), radius_px (0: culled)
  vec4 color;               // rgb (not clamped above), w unused
  ivec4 rect;               // tile rectangle: min.xy, max.xy (exclusive)
};

LFD_IO_END

#endif
