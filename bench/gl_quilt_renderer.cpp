#include "bench/gl_quilt_renderer.hpp"

#include "gpu/gl_context.hpp"
#include "gpu/gl_g2lf.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_scene.hpp"

namespace lfd::bench {
namespace {

class GlQuiltRenderer : public QuiltRenderer {
 public:
  std::string name() const override { return "gl"; }
  std::string device() const override { return context_.info().summary(); }
  int default_runs() const override { return 10; }

  void set_scene(const render::GaussianScene& scene) override {
    g2lf_.reset();  // they hold the old scene by reference
    per_view_.reset();
    scene_ = std::make_unique<gpu::GlScene>(scene, context_.info());
    per_view_ = std::make_unique<gpu::GlPerViewRenderer>(*scene_);
    g2lf_ = std::make_unique<gpu::GlG2lfRenderer>(*scene_, context_.info());
  }

  void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    ensure_quilt(layout);
    per_view_->render_quilt(geometry, layout, {}, quilt_);
    glFinish();
  }

  render::G2lfStats render_g2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                                const render::G2lfOptions& options) override {
    ensure_quilt(layout);
    gpu::GlG2lfOptions o;
    o.g2lf = options;
    g2lf_->render_quilt(geometry, layout, o, {}, quilt_);
    glFinish();
    render::G2lfStats stats;
    stats.plane_bytes = g2lf_->stats().plane_bytes;
    stats.planes = options.chunks;  // allocated layers; the used count needs a read-back
    return stats;
  }

  const ImageF& read_quilt() override {
    image_ = gpu::read_image_top_down(quilt_, 3);
    return image_;
  }

  std::string memory_kind() const override { return "GPU memory (lfd's buffers and textures)"; }
  void reset_peak_memory() override { gpu::reset_gpu_peak(); }
  size_t peak_memory_bytes() const override { return gpu::gpu_bytes_peak(); }

 private:
  // The quilt as displayed: 8 bits per channel.
  void ensure_quilt(const render::QuiltLayout& layout) {
    if (quilt_.width() != layout.width || quilt_.height() != layout.height)
      quilt_ = gpu::Texture(GL_RGBA8, layout.width, layout.height);
  }

  gpu::HeadlessContext context_;
  std::unique_ptr<gpu::GlScene> scene_;
  std::unique_ptr<gpu::GlPerViewRenderer> per_view_;
  std::unique_ptr<gpu::GlG2lfRenderer> g2lf_;
  gpu::Texture quilt_;
  ImageF image_;
};

}  // namespace

std::unique_ptr<QuiltRenderer> make_gl_quilt_renderer() { return std::make_unique<GlQuiltRenderer>(); }

}  // namespace lfd::bench
