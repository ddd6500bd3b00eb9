// The plane table's contract: the buffer the depth binning writes on the GPU and every plane
// pass reads (gpu/planes/gl_planes.hpp GlPlaneTable; gpu/planes/shaders/plane_table.glsl, the binning passes,
// the plane raster, the swizzle, the direct panel): its binding point in every pass that binds
// it, and its std430 layout. Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_PLANE_TABLE_IO_H
#define LFD_GPU_SHADERS_PLANE_TABLE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

// One binding point in every pass, so a pass that reads the table after the binning wrote it
// needs no rebinding rule of its own (the swizzle and the direct panel used 0 before).
LFD_IO_INT(kPlaneTableBinding, 9)

// The header, then one PlaneTableEntry per plane and one past the last: entry k holds d_k and
// the first sorted splat of plane k; entry plane_count holds begin = splats_binned (the end of
// the last plane). std430: uints and floats, tightly packed; the entries start at byte 16.
struct PlaneTableHeader {
  uint plane_count LFD_IO_ZERO;
  uint splats_binned LFD_IO_ZERO;  // primitives whose centre lies in the reference frustum
  uint pad0 LFD_IO_ZERO;
  uint pad1 LFD_IO_ZERO;
};
struct PlaneTableEntry {
  float depth LFD_IO_ZERO;  // d_k, base-camera depth (Eq. u_prime)
  uint begin LFD_IO_ZERO;   // first sorted splat of the plane
};

LFD_IO_END

#endif
