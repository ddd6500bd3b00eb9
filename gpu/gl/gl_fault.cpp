#include "gpu/gl/gl_fault.hpp"

#include <cstdlib>
#include <string>

namespace lfd::gpu {
namespace {

const char* fault_name(GlFault fault) { return fault == GlFault::kComputeRaster ? "compute" : "oom"; }

}  // namespace

bool gl_fault(GlFault fault) {
  static const std::string switched = [] {
    const char* v = std::getenv("LFD_GL_FAULT");
    return std::string(v ? v : "");
  }();
  return switched == fault_name(fault);
}

void fail_if_faulted(GlFault fault, std::string_view pass) {
  if (!gl_fault(fault)) return;
  if (fault == GlFault::kComputeRaster)
    throw GlPathFailed(fmt::format("{}: the compute raster path cannot be built on this device (LFD_GL_FAULT=compute)",
                                   pass));
  throw GlPathFailed(fmt::format("{}: GPU out of memory (LFD_GL_FAULT=oom)", pass));
}

}  // namespace lfd::gpu
