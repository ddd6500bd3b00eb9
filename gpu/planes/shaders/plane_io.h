// The per-plane image passes' contract (gpu/splats/gl_plane_raster.hpp, gpu/voxels/gl_v2lf.hpp,
// gpu/voxels/gl_voxel_views.hpp; gpu/splats/shaders/g2lf_plane_convert.comp.glsl, voxel_plane_lowpass.comp.glsl,
// voxel_downsample.comp.glsl): their image and texture units and their work-group size, one
// invocation per texel of a 16 x 8 tile (the per-plane indirect dispatches the V2LF binning
// writes count these tiles). Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_PLANE_IO_H
#define LFD_GPU_SHADERS_PLANE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kPlaneAccumulationImage, 0)  // image unit: the float accumulation (C, T), RGBA32F
LFD_IO_INT(kPlaneTexelsImage, 1)        // image unit: the planes' array, written by the convert
LFD_IO_INT(kPlaneLowpassScratchImage, 2)  // image unit: the lowpass's horizontal pass
LFD_IO_INT(kDownsampleSourceUnit, 0)    // texture unit: the supersampled view
LFD_IO_INT(kDownsampleTargetImage, 1)   // image unit: the view written

// The low-pass's largest radius (texels): its 2 r + 1 weights are a uniform array.
LFD_IO_INT(kLowpassMaxRadius, 64)
LFD_IO_INT(kLowpassMaxTaps, 2 * kLowpassMaxRadius + 1)

LFD_IO_UINT(kPlaneGroupWidth, 16u)
LFD_IO_UINT(kPlaneGroupHeight, 8u)

LFD_IO_END

#endif
