// The RGB-D view synthesis passes' contract (rgbd/gl_rgbd_views.hpp; rgbd/shaders/
// rgbd_resample.frag.glsl, rgbd_warp.frag.glsl, rgbd_fill.frag.glsl): their texture units.
// Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_RGBD_SHADERS_RGBD_IO_H
#define LFD_RGBD_SHADERS_RGBD_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(rgbd)

LFD_IO_INT(kRgbdFrameUnit, 0)       // resample: the decoded RGB-D frame
LFD_IO_INT(kRgbdSourceUnit, 0)      // warp: the tile-size colour and depth
LFD_IO_INT(kRgbdShiftPerZUnit, 1)   // warp: per view, the shift per unit of depth
LFD_IO_INT(kRgbdWarpedUnit, 0)      // fill: the warped quilt (colour, landed depth)
LFD_IO_UINT(kRgbdSampledUnits, 2u)  // units 0 and 1 get the passes' sampler

LFD_IO_END

#endif
