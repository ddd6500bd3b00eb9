// The player's quilt conversion contract (play/quilt_texture.hpp; play/shaders/
// quilt_convert.frag.glsl): the texture units of a decoded video frame's planes. Read by C++ and
// GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_PLAY_SHADERS_QUILT_CONVERT_IO_H
#define LFD_PLAY_SHADERS_QUILT_CONVERT_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(play)

LFD_IO_INT(kQuiltPlane0Unit, 0)  // Y
LFD_IO_INT(kQuiltPlane1Unit, 1)  // U (Cb)
LFD_IO_INT(kQuiltPlane2Unit, 2)  // V (Cr)

LFD_IO_END

#endif
