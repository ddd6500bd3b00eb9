#include "bench/gl_quilt_renderer.hpp"

#include "bench/gl_bench_target.hpp"
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_scene.hpp"

namespace lfd::bench {
namespace {

class GlQuiltRenderer : public QuiltRenderer {
 public:
  std::string name() const override { return "gl"; }
  std::string device() const override { return target_.info().summary(); }
  int default_runs() const override { return 10; }

  void set_scene(const render::GaussianScene& scene) override {
    g2lf_.reset();  // they hold the old scene by reference
    per_view_.reset();
    scene_ = std::make_unique<gpu::GlScene>(scene, target_.info());
    per_view_ = std::make_unique<gpu::GlPerViewRenderer>(*scene_);
    g2lf_ = std::make_unique<gpu::GlG2lfRenderer>(*scene_, target_.info());
  }

  void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    per_view_->render_quilt(geometry, layout, {}, target_.quilt(layout));
    glFinish();
  }

  render::G2lfStats render_g2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                const render::G2lfOptions& options) override {
    gpu::GlG2lfOptions o;
    o.g2lf = options;
    g2lf_->render_quilt(geometry, layout, o, {}, target_.quilt(layout));
    glFinish();
    render::G2lfStats stats;
    stats.plane_bytes = g2lf_->stats().plane_bytes;
    stats.planes = options.chunks;  // allocated layers; the used count needs a read-back
    return stats;
  }

  const ImageF& read_quilt() override { return target_.read_quilt(); }
  std::string memory_kind() const override { return GlBenchTarget::memory_kind(); }
  void reset_peak_memory() override { GlBenchTarget::reset_peak_memory(); }
  size_t peak_memory_bytes() const override { return GlBenchTarget::peak_memory_bytes(); }

 private:
  GlBenchTarget target_;  // first: the context outlives the renderers below
  std::unique_ptr<gpu::GlScene> scene_;
  std::unique_ptr<gpu::GlPerViewRenderer> per_view_;
  std::unique_ptr<gpu::GlG2lfRenderer> g2lf_;
};

}  // namespace

std::unique_ptr<QuiltRenderer> make_gl_quilt_renderer() { return std::make_unique<GlQuiltRenderer>(); }

}  // namespace lfd::bench
