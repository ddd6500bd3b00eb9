// Work groups past the 65535 a dimension of glDispatchCompute takes (docs/gpu.md "The compute
// tile rasterizer"): a pass of N groups is dispatched as min(N, kMaxWorkGroupsX) x rows
// (gpu/gl/gl_work_groups.hpp, or on the GPU: gpu/compute/shaders/tile_dispatch.comp.glsl), and its
// shader reads the flat index (gpu/gl/shaders/flat_group.glsl) and skips those past N. Read by
// C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_WORK_GROUPS_IO_H
#define LFD_GPU_SHADERS_WORK_GROUPS_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_UINT(kMaxWorkGroupsX, 65535u)  // GL's guaranteed GL_MAX_COMPUTE_WORK_GROUP_COUNT

LFD_IO_END

#endif
