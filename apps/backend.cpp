#include "apps/backend.hpp"

#include <iostream>

#include <fmt/format.h>

#include "util/error.hpp"

namespace lfd::apps {

Backend parse_backend(const std::string& name) {
  if (name == "cpu") return Backend::kCpu;
  if (name == "gl") return Backend::kGl;
  if (name == "auto") return Backend::kAuto;
  throw_input_error("--backend: '{}' is not cpu, gl or auto", name);
}

CLI::Option* add_backend_option(CLI::App& app, std::string& name, const std::string& help) {
  return app.add_option("--backend", name, help)->check(CLI::IsMember({"cpu", "gl", "auto"}))->capture_default_str();
}

CLI::Option* add_raster_option(CLI::App& app, std::string& name) {
  return app.add_option("--raster", name,
                        "GL backend, Gaussians: hardware (instanced quads through the raster pipeline), compute "
                        "(a tile rasterizer in compute shaders) or auto (the faster on this device, measured once "
                        "per run; docs/gpu.md)")
      ->check(CLI::IsMember({"hardware", "compute", "auto"}))
      ->capture_default_str();
}

std::unique_ptr<gpu::HeadlessContext> open_backend(Backend backend, bool verbose) {
  if (backend == Backend::kCpu) return nullptr;
  std::unique_ptr<gpu::HeadlessContext> context;
  try {
    context = std::make_unique<gpu::HeadlessContext>();
  } catch (const gpu::GlUnavailable& e) {
    if (backend == Backend::kGl) throw;
    std::cerr << fmt::format("notice: --backend auto: running on the CPU ({})\n", e.what());
    return nullptr;
  }
  if (verbose) std::cout << fmt::format("backend: gl on {}\n", context->info().summary());
  return context;
}

}  // namespace lfd::apps
