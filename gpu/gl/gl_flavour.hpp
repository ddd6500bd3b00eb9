#pragma once
// Which OpenGL a context speaks (docs/arm.md, docs/gpu.md "OpenGL ES 3.1"): desktop OpenGL 4.5
// core (everything lfd draws) or OpenGL ES 3.1 (the display side only: the interlacer, the
// player's quilt conversion and RGB-D views, the windows of `lfd play`, `lfd serve` and
// `lfd interlace --backend gl`; a Raspberry Pi 5 offers ES 3.1 and desktop GL 3.1). What the user
// asks for is a GlRequest (`--gl auto|desktop|es`, or LFD_GL): auto tries desktop 4.5, then ES
// 3.1 with one notice line. The GL object wrappers (gl_objects.hpp) and the shader assembly
// (gl_program.hpp, shader_source.hpp) ask the current context which it is and take the form it
// has; the passes above them are written once.
#include <string>
#include <string_view>

namespace lfd::gpu {

enum class GlRequest { kAuto, kDesktop, kEs };

// "auto", "desktop" or "es"; InputError "`field`: 'name' is not auto, desktop or es".
GlRequest parse_gl_request(std::string_view name, std::string_view field);
std::string_view gl_request_name(GlRequest request);
// LFD_GL from the environment (kAuto when unset or empty; InputError naming LFD_GL otherwise).
GlRequest gl_request_from_env();

// Whether the context current on this thread is OpenGL ES (false without a context).
bool current_gl_is_es();

// The one notice auto prints when it falls back: "notice: no desktop OpenGL 4.5 (why); running
// on OpenGL ES 3.1 (the display side only)".
std::string es_fallback_notice(const std::string& why);

// For a command that needs desktop OpenGL 4.5 (Gaussian and voxel rendering, `lfd view`): throws
// GlUnavailable "`what` needs desktop OpenGL 4.5 ...; LFD_GL=es asks for OpenGL ES" when LFD_GL
// says es. Nothing otherwise (the context's own creation then says whether 4.5 is there).
void require_desktop_gl(std::string_view what);

}  // namespace lfd::gpu
