#include "bench/cpu_quilt_renderer.hpp"

#include <omp.h>

#include <fmt/format.h>

#include "bench/process_memory.hpp"
#include "render/per_view_quilt.hpp"
#include "util/error.hpp"

namespace lfd::bench {
namespace {

class CpuQuiltRenderer final : public QuiltRenderer {
 public:
  std::string name() const override { return "cpu"; }
  std::string device() const override {
    return fmt::format("CPU, {} OpenMP threads", omp_get_max_threads());
  }
  int default_runs() const override { return 3; }

  void set_scene(const render::GaussianScene& scene) override { scene_ = &scene; }

  void render_per_view(const render::QuiltGeometry& geometry,
                       const render::QuiltLayout& layout) override {
    quilt_ = render::render_quilt_per_view(scene(), geometry, layout);
  }

  render::G2lfStats render_g2lf(const render::QuiltGeometry& geometry,
                                const render::QuiltLayout& layout,
                                const render::G2lfOptions& options) override {
    render::G2lfStats stats;
    quilt_ = render::render_quilt_g2lf(scene(), geometry, layout, options, {}, &stats);
    return stats;
  }

  const ImageF& read_quilt() override { return quilt_; }

  std::string memory_kind() const override { return "process RSS"; }
  void reset_peak_memory() override { reset_peak_rss(); }
  size_t peak_memory_bytes() const override { return peak_rss_bytes(); }

 private:
  const render::GaussianScene& scene() const {
    if (!scene_) throw std::logic_error("CpuQuiltRenderer: set_scene before rendering");
    return *scene_;
  }

  const render::GaussianScene* scene_ = nullptr;
  ImageF quilt_;
};

}  // namespace

std::unique_ptr<QuiltRenderer> make_cpu_quilt_renderer() {
  return std::make_unique<CpuQuiltRenderer>();
}

}  // namespace lfd::bench
