// The swizzle's contract (gpu/planes/gl_swizzle.hpp; gpu/planes/shaders/swizzle.comp.glsl and
// swizzle_table.comp.glsl): the planes' texture unit, the quilt's image unit, the storage
// buffers beside the plane table (gpu/planes/shaders/plane_table_io.h) and the work-group sizes. Read by
// C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_SWIZZLE_IO_H
#define LFD_GPU_SHADERS_SWIZZLE_IO_H
#include "gpu/planes/shaders/plane_table_io.h"
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kSwizzlePlanesUnit, 0)  // texture unit (and its sampler): the planes' array texture
LFD_IO_INT(kSwizzleQuiltImage, 0)  // image unit: the quilt written
LFD_IO_INT(kSwizzleViewOffsetsBinding, 1)        // dx_j per view
LFD_IO_INT(kSwizzlePlaneFactorsBinding, 2)       // the table pass's per-plane scale_y, beta
LFD_IO_INT(kSwizzleViewPlaneColumnsBinding, 3)   // and its column per view and plane [k V + j]

// The swizzle: an invocation per quilt pixel of a view tile (and VIEWS views along z).
LFD_IO_UINT(kSwizzleGroupWidth, 16u)
LFD_IO_UINT(kSwizzleGroupHeight, 8u)
// The table pass: an invocation per view (x), a work group row per plane (y).
LFD_IO_UINT(kSwizzleTableGroupSize, 64u)

LFD_IO_END

#endif
