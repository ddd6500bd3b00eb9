#pragma once
// Headless OpenGL 4.5 core contexts through EGL (docs/gpu.md): the EGL device platform
// (EGL_EXT_platform_device; NVIDIA's driver without an X server) or Mesa's surfaceless platform
// (llvmpipe on machines without a GPU). Rendering goes to framebuffer objects only, so no
// surface is needed. Windows (GLFW) make their own context and use the same renderer code.
// The display side may ask for OpenGL ES 3.1 instead (EGL_OPENGL_ES_API; gl_flavour.hpp,
// docs/arm.md).
#include <cstddef>
#include <optional>
#include <string>

#include "gpu/gl/gl_flavour.hpp"
#include "util/error.hpp"

namespace lfd::gpu {

// No usable OpenGL 4.5 core context: an input error (exit 2) with the reason on one line.
class GlUnavailable : public InputError {
 public:
  using InputError::InputError;
};

// What the current context is (for notices, reports and memory checks).
struct GlInfo {
  std::string vendor, renderer, version;
  std::string platform;          // "EGL device", "EGL surfaceless", "GLFW window"
  bool es = false;               // OpenGL ES (the display side only; gl_flavour.hpp)
  // Why desktop OpenGL 4.5 was not made when auto fell back to ES ("" otherwise): the notice.
  std::string desktop_unavailable;
  bool software = false;         // llvmpipe/softpipe: report ratios only
  long long max_ssbo_bytes = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  int max_texture_size = 0;
  int max_array_layers = 0;
  // Free GPU memory when the driver says (NVX/ATI meminfo); none on llvmpipe.
  std::optional<long long> free_memory_bytes;
  std::string summary() const;  // "NVIDIA H100 (OpenGL 4.5.0 NVIDIA ..., EGL device)"
};

// Reads GlInfo from the context current on this thread.
GlInfo query_gl_info(const std::string& platform);

class HeadlessContext {
 public:
  // Tries the EGL device platform, then the surfaceless platform (EGL_PLATFORM=surfaceless
  // tries it first). Throws GlUnavailable naming what each try gave. `request`: desktop (the
  // renderers: OpenGL 4.5 core), es (OpenGL ES 3.1) or auto (desktop, else ES; info().es and
  // info().desktop_unavailable say which and why; the caller prints es_fallback_notice).
  explicit HeadlessContext(GlRequest request = GlRequest::kDesktop);
  ~HeadlessContext();
  HeadlessContext(const HeadlessContext&) = delete;
  HeadlessContext& operator=(const HeadlessContext&) = delete;

  void make_current() const;
  const GlInfo& info() const { return info_; }

 private:
  void* display_ = nullptr;  // EGLDisplay
  void* context_ = nullptr;  // EGLContext
  GlInfo info_;
};

}  // namespace lfd::gpu
