// The throughput probe's contract (gpu/probes/gl_throughput_probe.hpp; probe_fma.comp.glsl,
// probe_copy.comp.glsl): the work-group size both dispatches use and the storage buffers they
// read and write. Read by C++ and GLSL (gpu/gl/shaders/shader_io.h).
#ifndef LFD_GPU_SHADERS_PROBE_IO_H
#define LFD_GPU_SHADERS_PROBE_IO_H
#include "gpu/gl/shaders/shader_io.h"

LFD_IO_BEGIN(gpu)

LFD_IO_UINT(kProbeGroupSize, 256u)
LFD_IO_INT(kProbeSourceBinding, 0)  // probe_copy's source
LFD_IO_INT(kProbeTargetBinding, 1)  // probe_copy's target, probe_fma's result

LFD_IO_END

#endif
