#pragma once
// The two renderers a benchmark table compares on one backend, made by the library's factory
// (lightfield/renderer_factory.hpp): every view alone (the ground truth) and the sweeping planes
// (G2LF or V2LF; the benchmark sets each configuration's plane options). On the GL backend they
// share one headless device: one scene upload, one RGBA8 quilt (the quilt as displayed), GPU
// memory as the memory figure.
#include <memory>
#include <string>

#include "gpu/gl/raster_path.hpp"
#include "lightfield/light_field_renderer.hpp"

namespace lfd::bench {

struct BenchRenderers {
  std::unique_ptr<lightfield::LightFieldRenderer> per_view, sweeping;
};

// `backend`: "cpu" or "gl" (InputError for another; gpu::GlUnavailable, exit 2, without GL);
// `raster`: how the GL renderers draw Gaussians (auto: measured once per process).
BenchRenderers make_bench_renderers(const std::string& backend, scene::SceneKind kind,
                                    gpu::RasterPath raster = gpu::RasterPath::kHardware);

}  // namespace lfd::bench
