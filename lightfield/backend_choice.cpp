#include "lightfield/backend_choice.hpp"

#include <iostream>
#include <utility>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::lightfield {

BackendChoice parse_backend_choice(std::string_view name, std::string_view field) {
  if (name == "cpu") return BackendChoice::kCpu;
  if (name == "gl") return BackendChoice::kGl;
  if (name == "auto") return BackendChoice::kAuto;
  throw_input_error("{}: '{}' is not cpu, gl or auto", field, name);
}

CpuFallbackNotice cpu_fallback_notice_on_stderr(std::string field) {
  return [field = std::move(field)](const std::string& reason) {
    std::cerr << fmt::format("notice: {} auto: running on the CPU ({})\n", field, reason);
  };
}

std::unique_ptr<gpu::HeadlessContext> open_backend_context(BackendChoice choice,
                                                          const CpuFallbackNotice& on_cpu_fallback,
                                                          gpu::GlRequest gl) {
  if (choice == BackendChoice::kCpu) return nullptr;
  try {
    if (gl == gpu::GlRequest::kDesktop) gpu::require_desktop_gl("rendering on the GPU");
    return std::make_unique<gpu::HeadlessContext>(gl);
  } catch (const gpu::GlUnavailable& e) {
    if (choice == BackendChoice::kGl) throw;
    on_cpu_fallback(e.what());
    return nullptr;
  }
}

Backend backend_of(const gpu::HeadlessContext* context) { return context ? Backend::kGl : Backend::kCpu; }

}  // namespace lfd::lightfield
