#include "gpu/gl/gl_flavour.hpp"

#include <cstdlib>

#include <epoxy/gl.h>
#include <fmt/format.h>

#include "gpu/gl/gl_context.hpp"
#include "util/error.hpp"

namespace lfd::gpu {

GlRequest parse_gl_request(std::string_view name, std::string_view field) {
  if (name == "auto") return GlRequest::kAuto;
  if (name == "desktop") return GlRequest::kDesktop;
  if (name == "es") return GlRequest::kEs;
  throw_input_error("{}: '{}' is not auto, desktop or es", field, name);
}

std::string_view gl_request_name(GlRequest request) {
  switch (request) {
    case GlRequest::kDesktop: return "desktop";
    case GlRequest::kEs: return "es";
    default: return "auto";
  }
}

GlRequest gl_request_from_env() {
  const char* value = std::getenv("LFD_GL");
  if (!value || !*value) return GlRequest::kAuto;
  return parse_gl_request(value, "LFD_GL");
}

bool current_gl_is_es() {
  // libepoxy reads GL_VERSION ("OpenGL ES 3.2 Mesa ...") of the current context.
  return !epoxy_is_desktop_gl();
}

std::string es_fallback_notice(const std::string& why) {
  return fmt::format("notice: no desktop OpenGL 4.5 ({}); running on OpenGL ES 3.1 (the display side only)", why);
}

void require_desktop_gl(std::string_view what) {
  if (gl_request_from_env() == GlRequest::kEs)
    throw GlUnavailable(fmt::format("{} needs desktop OpenGL 4.5 (Gaussian and voxel rendering); LFD_GL=es asks "
                                    "for OpenGL ES, which only shows quilts (docs/arm.md)",
                                    what));
}

}  // namespace lfd::gpu
