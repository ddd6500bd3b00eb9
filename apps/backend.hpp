#pragma once
// `--backend cpu|gl|auto` for the commands that render or interlace: the flag and the context it
// opens. The rule (gl without a context: exit 2; auto: the CPU, saying why) is
// lightfield/backend_choice.hpp's, which Python follows too.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "gpu/gl/gl_context.hpp"
#include "gpu/probes/gl_raster_probe.hpp"
#include "gpu/gl/raster_path.hpp"
#include "lightfield/backend_choice.hpp"

namespace lfd::apps {

// Adds `--backend` (choices cpu, gl, auto) to `app`, bound to `name`.
CLI::Option* add_backend_option(CLI::App& app, std::string& name, const std::string& help);

// Adds `--raster` (choices compute, hardware, auto) to `app`, bound to `name`: how the GL
// backend draws Gaussians (gpu/gl/raster_path.hpp).
CLI::Option* add_raster_option(CLI::App& app, std::string& name);

// A benchmark's `--raster` (bench render, bench voxels): paths comma-separated, each run in turn
// on the same scenes; `what` says what the paths draw.
CLI::Option* add_bench_raster_option(CLI::App& app, std::vector<std::string>& names, const std::string& what);
// Runs `run` once per path of `names` (a heading per path when there are several) and returns its
// figures: one path, its result alone; several, {"rasters": [{"raster", "result"}, ...]}.
// `--raster` given with `backend` cpu is an InputError (the CPU has no raster paths).
nlohmann::ordered_json run_per_raster(const CLI::App& app, const std::vector<std::string>& names,
                                      const std::string& backend,
                                      const std::function<nlohmann::ordered_json(gpu::RasterPath)>& run);

// `path`, or for auto the measured choice for `subject` (gpu::resolve_raster_path; a GL context
// must be current), printing "raster: auto chose compute for voxels (probe quilt: compute 12.3 ms,
// hardware 45.6 ms)".
gpu::RasterPath resolve_raster(gpu::RasterPath path, gpu::RasterSubject subject);

// What `--backend NAME` runs on (lightfield::open_backend_context): a headless context for gl
// (GlUnavailable propagates: exit 2), for auto a context or, when none can be made, null with the
// notice "notice: --backend auto: running on the CPU (reason)" on stderr; null for cpu. With a
// context and `verbose`, prints "backend: gl on <GlInfo::summary()>" to stdout (a command that
// reports the renderer itself, such as a benchmark table, passes false).
// `gl`: the OpenGL asked for (lightfield::open_backend_context); when auto took OpenGL ES, the
// one notice line on stderr (gpu::es_fallback_notice).
std::unique_ptr<gpu::HeadlessContext> open_backend(lightfield::BackendChoice backend, bool verbose = true,
                                                   gpu::GlRequest gl = gpu::GlRequest::kDesktop);
// The same for the flag's text (InputError for a name that is not cpu, gl or auto).
std::unique_ptr<gpu::HeadlessContext> open_backend(const std::string& name, bool verbose = true,
                                                   gpu::GlRequest gl = gpu::GlRequest::kDesktop);

// Adds `--gl` (choices auto, desktop, es; the default from LFD_GL, else auto) to a command of the
// display side (play, serve, interlace), bound to `name` (docs/arm.md).
CLI::Option* add_gl_option(CLI::App& app, std::string& name);
// The request of `--gl`'s text.
gpu::GlRequest gl_request(const std::string& name);
// Whether the flag's text is cpu (InputError for a name that is not cpu, gl or auto).
bool backend_is_cpu(const std::string& name);

}  // namespace lfd::apps
