#include "apps/backend.hpp"

#include <cstdio>
#include <iostream>

#include <fmt/format.h>

#include "gpu/probes/gl_raster_probe.hpp"
#include "util/error.hpp"

namespace lfd::apps {

CLI::Option* add_backend_option(CLI::App& app, std::string& name, const std::string& help) {
  return app.add_option("--backend", name, help)->check(CLI::IsMember({"cpu", "gl", "auto"}))->capture_default_str();
}

CLI::Option* add_raster_option(CLI::App& app, std::string& name) {
  return app.add_option("--raster", name,
                        "GL backend, Gaussians and per-view voxels: hardware (the raster pipeline), compute "
                        "(a tile rasterizer in compute shaders) or auto (the faster on this device, measured once "
                        "per run; docs/gpu.md)")
      ->check(CLI::IsMember({"hardware", "compute", "auto"}))
      ->capture_default_str();
}

CLI::Option* add_bench_raster_option(CLI::App& app, std::vector<std::string>& names, const std::string& what) {
  return app.add_option("--raster", names,
                        "--backend gl: how " + what + " are drawn, hardware, compute or auto, comma-separated: each "
                        "in turn in this run, on the same scenes")
      ->delimiter(',')
      ->capture_default_str()
      ->check(CLI::IsMember({"hardware", "compute", "auto"}));
}

nlohmann::ordered_json run_per_raster(const CLI::App& app, const std::vector<std::string>& names,
                                      const std::string& backend,
                                      const std::function<nlohmann::ordered_json(gpu::RasterPath)>& run) {
  if (app.count("--raster") && backend == "cpu")
    throw_input_error("--raster: chooses how the GL backend draws; --backend cpu has no raster paths");
  nlohmann::ordered_json result;
  for (const std::string& name : names) {
    if (names.size() == 1) return run(gpu::parse_raster_path(name));
    std::printf("\n## --raster %s\n\n", name.c_str());
    result["rasters"].push_back({{"raster", name}, {"result", run(gpu::parse_raster_path(name))}});
  }
  return result;
}

gpu::RasterPath resolve_raster(gpu::RasterPath path, gpu::RasterSubject subject) {
  if (path != gpu::RasterPath::kAuto) return path;
  const gpu::RasterPath chosen = gpu::resolve_raster_path(path, subject);
  const gpu::RasterProbe probe = *gpu::last_raster_probe(subject);
  std::cout << fmt::format("raster: auto chose {} for {} (probe quilt: compute {:.1f} ms, hardware {:.1f} ms)\n",
                           gpu::raster_path_name(chosen), gpu::raster_subject_name(subject), 1e3 * probe.compute_s,
                           1e3 * probe.hardware_s);
  return chosen;
}

std::unique_ptr<gpu::HeadlessContext> open_backend(lightfield::BackendChoice backend, bool verbose,
                                                   gpu::GlRequest gl) {
  auto context = lightfield::open_backend_context(backend, lightfield::cpu_fallback_notice_on_stderr("--backend"), gl);
  if (context && !context->info().desktop_unavailable.empty())
    std::cerr << gpu::es_fallback_notice(context->info().desktop_unavailable) << "\n";
  if (context && verbose) std::cout << fmt::format("backend: gl on {}\n", context->info().summary());
  return context;
}

std::unique_ptr<gpu::HeadlessContext> open_backend(const std::string& name, bool verbose, gpu::GlRequest gl) {
  return open_backend(lightfield::parse_backend_choice(name, "--backend"), verbose, gl);
}

CLI::Option* add_gl_option(CLI::App& app, std::string& name) {
  name = std::string(gpu::gl_request_name(gpu::gl_request_from_env()));
  return app
      .add_option("--gl", name,
                  "which OpenGL: desktop (4.5 core), es (OpenGL ES 3.1: a Raspberry Pi 5) or auto (desktop, else ES "
                  "with a notice); default LFD_GL, else auto")
      ->check(CLI::IsMember({"auto", "desktop", "es"}))
      ->capture_default_str();
}

gpu::GlRequest gl_request(const std::string& name) { return gpu::parse_gl_request(name, "--gl"); }

bool backend_is_cpu(const std::string& name) {
  return lightfield::parse_backend_choice(name, "--backend") == lightfield::BackendChoice::kCpu;
}

}  // namespace lfd::apps
