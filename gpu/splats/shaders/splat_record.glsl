// The shaders' way in to SplatRecord, which gpu/splats/shaders/splat_record_io.h declares for
// C++ and GLSL alike.
#include "gpu/splats/shaders/splat_record_io.h"
