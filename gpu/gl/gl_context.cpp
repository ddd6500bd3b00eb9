#include "gpu/gl/gl_context.hpp"

#include "gpu/gl/driver_workarounds.hpp"
#include "gpu/gl/gl_debug.hpp"
#include "gpu/gl/gl_limits.hpp"
#include "gpu/gl/gl_program.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <utility>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

namespace lfd::gpu {
namespace {

std::string egl_error_name(EGLint code) {
  switch (code) {
    case EGL_SUCCESS: return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS: return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT: return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER: return "EGL_BAD_PARAMETER";
    default: return fmt::format("EGL error 0x{:x}", code);
  }
}

// A display of one platform, initialised, or EGL_NO_DISPLAY with `why` set.
struct OpenedDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;
};

bool client_extension(const char* name) {
  // Client extensions are queried on EGL_NO_DISPLAY; null when EGL_EXT_client_extensions is absent.
  const char* list = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

bool initialise(EGLDisplay display, std::string& why, const std::string& platform) {
  EGLint major = 0, minor = 0;
  if (display != EGL_NO_DISPLAY && eglInitialize(display, &major, &minor)) return true;
  why += fmt::format("{}{}: {}", why.empty() ? "" : "; ", platform,
                     display == EGL_NO_DISPLAY ? "no display" : egl_error_name(eglGetError()));
  return false;
}

// What a context of one flavour is asked for: the API, the config's renderable bit and the
// version (docs/arm.md: a Raspberry Pi 5 offers ES 3.1).
struct Flavour {
  EGLenum api;
  EGLint renderable;
  int major, minor;
  const char* name;
};
constexpr Flavour kDesktop{EGL_OPENGL_API, EGL_OPENGL_BIT, 4, 5, "OpenGL 4.5 core"};
constexpr Flavour kEs{EGL_OPENGL_ES_API, 0x40 /* EGL_OPENGL_ES3_BIT */, 3, 1, "OpenGL ES 3.1"};

// A context of `flavour` on `display`, current without a surface; EGL_NO_CONTEXT with `why`
// extended.
EGLContext create_context(EGLDisplay display, const Flavour& flavour, std::string& why, const std::string& platform) {
  const char* sep = why.empty() ? "" : "; ";
  if (!eglBindAPI(flavour.api)) {
    why += fmt::format("{}{}: no {}", sep, platform, flavour.api == EGL_OPENGL_API ? "desktop OpenGL" : "OpenGL ES");
    return EGL_NO_CONTEXT;
  }
  const EGLint config_attributes[] = {EGL_RENDERABLE_TYPE, flavour.renderable, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  const bool no_config = epoxy_has_egl_extension(display, "EGL_KHR_no_config_context");
  if (!no_config && (!eglChooseConfig(display, config_attributes, &config, 1, &configs) || configs < 1)) {
    why += fmt::format("{}{}: no {} config", sep, platform, flavour.name);
    return EGL_NO_CONTEXT;
  }
  // A debug context under strict checks (the tests), so the driver reports misuse (gl_debug.hpp).
  // EGL_CONTEXT_OPENGL_DEBUG is EGL 1.5; an EGL 1.4 display (Mesa's softpipe: docs/arm.md
  // "Under qemu-user") refuses the whole context over it (EGL_BAD_ATTRIBUTE), so there the debug
  // bit goes through EGL_KHR_create_context's flags.
  std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, flavour.major, EGL_CONTEXT_MINOR_VERSION, flavour.minor};
  if (flavour.api == EGL_OPENGL_API)
    attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
  if (strict_gl_checks()) {
    const char* version = eglQueryString(display, EGL_VERSION);
    int major = 0, minor = 0;
    if (version) std::sscanf(version, "%d.%d", &major, &minor);
    if (major > 1 || (major == 1 && minor >= 5))
      attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    else if (epoxy_has_egl_extension(display, "EGL_KHR_create_context"))
      attributes.insert(attributes.end(), {EGL_CONTEXT_FLAGS_KHR, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR});
  }
  attributes.push_back(EGL_NONE);
  EGLContext context =
      eglCreateContext(display, no_config ? EGL_NO_CONFIG_KHR : config, EGL_NO_CONTEXT, attributes.data());
  if (context == EGL_NO_CONTEXT) {
    why += fmt::format("{}{}: no {} context ({})", sep, platform, flavour.name, egl_error_name(eglGetError()));
    return EGL_NO_CONTEXT;
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
    why += fmt::format("{}{}: cannot make the context current ({})", sep, platform, egl_error_name(eglGetError()));
    eglDestroyContext(display, context);
    return EGL_NO_CONTEXT;
  }
  enable_gl_debug_output();
  return context;
}

}  // namespace

std::string GlInfo::summary() const {
  // GL_VERSION of OpenGL ES names the API itself ("OpenGL ES 3.2 Mesa 22.3.6").
  return fmt::format("{} ({}{}, {})", renderer, version.rfind("OpenGL ES", 0) == 0 ? "" : "OpenGL ", version, platform);
}

GlInfo query_gl_info(const std::string& platform) {
  GlInfo info;
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "");
  };
  info.vendor = text(GL_VENDOR);
  info.renderer = text(GL_RENDERER);
  info.version = text(GL_VERSION);
  info.platform = platform;
  info.software = info.renderer.find("llvmpipe") != std::string::npos ||
                  info.renderer.find("softpipe") != std::string::npos;
  const GlLimits limits = gl_limits();
  info.max_ssbo_bytes = limits.storage_block_bytes;
  info.max_texture_size = limits.texture_size;
  info.max_array_layers = limits.array_layers;
  // GL_NVX_gpu_memory_info / GL_ATI_meminfo report kilobytes.
  if (epoxy_has_gl_extension("GL_NVX_gpu_memory_info")) {
    GLint kb = 0;
    glGetIntegerv(0x9049 /* GPU_MEMORY_INFO_CURRENT_AVAILABLE_VIDMEM_NVX */, &kb);
    info.free_memory_bytes = static_cast<long long>(kb) * 1024;
  } else if (epoxy_has_gl_extension("GL_ATI_meminfo")) {
    GLint kb[4] = {0, 0, 0, 0};
    glGetIntegerv(0x87FC /* TEXTURE_FREE_MEMORY_ATI */, kb);
    info.free_memory_bytes = static_cast<long long>(kb[0]) * 1024;
  }
  while (glGetError() != GL_NO_ERROR) {
  }
  return info;
}

HeadlessContext::HeadlessContext(GlRequest request) {
  if (!epoxy_has_egl()) throw GlUnavailable("no GL: libEGL could not be loaded");
  apply_driver_workarounds();
  const char* env = std::getenv("EGL_PLATFORM");
  const bool surfaceless_first = env && std::string(env) == "surfaceless";

  std::vector<OpenedDisplay> candidates;
  auto add_surfaceless = [&] {
    if (client_extension("EGL_MESA_platform_surfaceless"))
      candidates.push_back({eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA,
                                                     EGL_DEFAULT_DISPLAY, nullptr),
                            "EGL surfaceless"});
  };
  auto add_devices = [&] {
    if (!client_extension("EGL_EXT_platform_device") || !client_extension("EGL_EXT_device_enumeration"))
      return;
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (!eglQueryDevicesEXT(16, devices, &count)) return;
    for (EGLint i = 0; i < count; ++i)
      candidates.push_back({eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr),
                            fmt::format("EGL device {}", i)});
  };
  if (surfaceless_first) {
    add_surfaceless();
    add_devices();
  } else {
    add_devices();
    add_surfaceless();
  }
  if (candidates.empty())
    throw GlUnavailable(
        "no GL: this EGL has neither the device nor the surfaceless platform (install "
        "libegl-mesa0, or an NVIDIA driver with libEGL_nvidia)");
  // Each flavour asked for, in order, on every display (auto: desktop first, then ES).
  std::vector<const Flavour*> flavours;
  if (request != GlRequest::kEs) flavours.push_back(&kDesktop);
  if (request != GlRequest::kDesktop) flavours.push_back(&kEs);
  std::string why, desktop_why;
  for (const Flavour* flavour : flavours) {
    for (const OpenedDisplay& c : candidates) {
      if (!initialise(c.display, why, c.platform)) continue;
      EGLContext context = create_context(c.display, *flavour, why, c.platform);
      if (context == EGL_NO_CONTEXT) continue;  // displays are refcounted per process: leave it
      display_ = c.display;
      context_ = context;
      const std::string platform = c.platform.rfind("EGL device", 0) == 0 ? "EGL device" : c.platform;
      info_ = query_gl_info(platform);
      info_.es = flavour == &kEs;
      if (info_.es && request == GlRequest::kAuto) info_.desktop_unavailable = desktop_why;
      return;
    }
    if (flavour == &kDesktop) desktop_why = std::exchange(why, std::string());
  }
  if (request == GlRequest::kAuto)
    throw GlUnavailable(fmt::format("no GL: neither OpenGL 4.5 core ({}) nor OpenGL ES 3.1 ({})", desktop_why, why));
  throw GlUnavailable(fmt::format("no GL: no {} context ({})", request == GlRequest::kEs ? kEs.name : kDesktop.name,
                                  request == GlRequest::kEs ? why : desktop_why.empty() ? why : desktop_why));
}

HeadlessContext::~HeadlessContext() {
  if (context_) {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(static_cast<EGLDisplay>(display_), static_cast<EGLContext>(context_));
  }
}

void HeadlessContext::make_current() const {
  eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                 static_cast<EGLContext>(context_));
}

}  // namespace lfd::gpu
