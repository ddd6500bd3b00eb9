#pragma once
// The one rule for `--backend cpu|gl|auto` (the commands) and `backend=` (Python): which
// implementation renders and interlaces. gl needs an OpenGL 4.5 core context (headless EGL);
// without one it is an input error (gpu::GlUnavailable: exit 2, one line). auto takes the GPU
// when a context can be made and otherwise the CPU, saying why, so a machine without a GPU
// still gets its image (docs/architecture.md "One light-field renderer interface").
#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "gpu/gl/gl_context.hpp"
#include "lightfield/renderer_options.hpp"

namespace lfd::lightfield {

enum class BackendChoice { kCpu, kGl, kAuto };

// "cpu", "gl" or "auto"; InputError "`field`: 'name' is not cpu, gl or auto" for another name.
BackendChoice parse_backend_choice(std::string_view name, std::string_view field);

// Told why auto runs on the CPU (the reason GL could not start).
using CpuFallbackNotice = std::function<void(const std::string& reason)>;
// The commands' notice on stderr: "notice: `field` auto: running on the CPU (reason)".
CpuFallbackNotice cpu_fallback_notice_on_stderr(std::string field);

// The context `choice` runs on: null for cpu; a headless context for gl (gpu::GlUnavailable
// propagates); for auto a headless context, or null after `on_cpu_fallback(reason)` when none
// can be made. `gl`: the OpenGL asked for; desktop (OpenGL 4.5 core) for everything that renders
// (LFD_GL=es is then refused: gpu::require_desktop_gl), auto or es for interlacing alone
// (gpu/gl/gl_flavour.hpp; the caller prints the notice when auto took ES).
std::unique_ptr<gpu::HeadlessContext> open_backend_context(BackendChoice choice,
                                                          const CpuFallbackNotice& on_cpu_fallback,
                                                          gpu::GlRequest gl = gpu::GlRequest::kDesktop);
// The backend that runs with what open_backend_context gave: GL with a context, the CPU without.
Backend backend_of(const gpu::HeadlessContext* context);

}  // namespace lfd::lightfield
