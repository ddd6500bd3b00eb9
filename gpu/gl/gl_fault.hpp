#pragma once
// What a user's driver may do to a GL path, and the switch that makes it happen here
// (docs/gpu.md "Drivers and limits"). A path that cannot be built (a compile or link error), hits
// a GL error or runs out of memory throws GlPathFailed naming the pass; `--raster auto` then draws
// with the other path after a one-line notice (gpu/probes/gl_raster_probe.hpp), and a path asked
// for by name exits 2 with that line (an InputError: the device cannot do what was asked).
// LFD_GL_FAULT, for the tests, makes the failures happen on a driver where they would not:
//   compute  the compute raster path's passes fail to build
//   oom      every GPU allocation fails, as on a device whose memory is full
#include <string_view>

#include "util/error.hpp"

namespace lfd::gpu {

class GlPathFailed : public InputError {
 public:
  using InputError::InputError;
};

enum class GlFault { kComputeRaster, kOutOfMemory };

// Whether LFD_GL_FAULT names `fault` (read once).
bool gl_fault(GlFault fault);
// Throws GlPathFailed "<pass>: ... (LFD_GL_FAULT=...)" when `fault` is switched on.
void fail_if_faulted(GlFault fault, std::string_view pass);

}  // namespace lfd::gpu
