// The lens view's contract (gpu/panel/gl_lens_view.hpp and the passes that read the lens model per
// panel subpixel: the interlacer, the direct panel pass, the lens probe; gpu/panel/shaders/
// lens_view.glsl): their texture units and storage buffers and the subpixel table's shape. The
// direct panel's plane table is gpu/planes/shaders/plane_table_io.h. Read by C++ and GLSL
// (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_LENS_VIEW_IO_H
#define LFD_GPU_SHADERS_LENS_VIEW_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_INT(kInterlaceQuiltUnit, 0)      // texture unit: the quilt the interlacer samples
LFD_IO_INT(kDirectPanelPlanesUnit, 0)   // texture unit (and its sampler): the direct pass's planes
LFD_IO_INT(kLensCorrectionUnit, 1)      // texture unit: the correction field w(u, v), R32F
LFD_IO_INT(kLensPhasePartsBinding, 3)   // storage buffer: the phase parts per row and column
LFD_IO_INT(kInterlacePanelImage, 0)     // image unit: the panel the compute interlacer writes
LFD_IO_INT(kDirectPanelImage, 0)        // image unit: the panel the compute direct pass writes

// The compute interlacer: an invocation per panel pixel, work groups of this many pixels.
LFD_IO_UINT(kInterlaceGroupWidth, 16u)
LFD_IO_UINT(kInterlaceGroupHeight, 8u)
// The compute direct pass: a work group per tile of the panel, an invocation per pixel; the
// group computes the factors of this many planes at a time (at most the group's size).
LFD_IO_UINT(kDirectPanelTileWidth, 16u)
LFD_IO_UINT(kDirectPanelTileHeight, 8u)
LFD_IO_UINT(kDirectPanelPlaneBatch, 128u)

// Subpixel offsets and phases repeat every kLensPixelClassesX x kLensPixelClassesY pixels
// (x mod 2, j mod 4): one entry per class and colour channel.
LFD_IO_INT(kLensPixelClassesX, 2)
LFD_IO_INT(kLensPixelClassesY, 4)
LFD_IO_INT(kLensSubpixelEntries, kLensPixelClassesX * kLensPixelClassesY * 3)

LFD_IO_END

#endif
