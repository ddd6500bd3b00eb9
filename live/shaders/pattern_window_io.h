// The pattern window's contract (live/pattern_window.cpp; live/shaders/pattern_window.frag.glsl):
// the texture unit of the pattern. Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_LIVE_SHADERS_PATTERN_WINDOW_IO_H
#define LFD_LIVE_SHADERS_PATTERN_WINDOW_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(live)

LFD_IO_INT(kPatternUnit, 0)  // the pattern, RGBA8, read with texelFetch

LFD_IO_END

#endif
