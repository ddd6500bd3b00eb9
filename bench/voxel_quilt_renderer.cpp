#include "bench/voxel_quilt_renderer.hpp"

#include <omp.h>

#include <fmt/format.h>

#include "bench/process_memory.hpp"
#include "gpu/gl_context.hpp"
#include "gpu/gl_objects.hpp"
#include "gpu/gl_per_view_renderer.hpp"
#include "gpu/gl_v2lf.hpp"
#include "gpu/gl_voxel_scene.hpp"
#include "gpu/gl_voxel_views.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::bench {
namespace {

class CpuVoxelRenderer : public VoxelQuiltRenderer {
 public:
  std::string name() const override { return "cpu"; }
  std::string device() const override { return fmt::format("CPU, {} OpenMP threads", omp_get_max_threads()); }
  int default_runs() const override { return 3; }
  void set_scene(const voxel::VoxelScene& scene) override { scene_ = &scene; }
  void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    quilt_ = voxel::render_voxel_quilt_per_view(*scene_, geometry, layout);
  }
  voxel::V2lfStats render_v2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               const voxel::V2lfOptions& options) override {
    voxel::V2lfStats stats;
    quilt_ = voxel::render_quilt_v2lf(*scene_, geometry, layout, options, scene_->background, &stats);
    return stats;
  }
  const ImageF& read_quilt() override { return quilt_; }
  std::string memory_kind() const override { return "process RSS"; }
  void reset_peak_memory() override { reset_peak_rss(); }
  size_t peak_memory_bytes() const override { return peak_rss_bytes(); }

 private:
  const voxel::VoxelScene* scene_ = nullptr;
  ImageF quilt_;
};

class GlVoxelRenderer : public VoxelQuiltRenderer {
 public:
  std::string name() const override { return "gl"; }
  std::string device() const override { return context_.info().summary(); }
  int default_runs() const override { return 10; }
  void set_scene(const voxel::VoxelScene& scene) override {
    v2lf_.reset();  // they hold the old scene by reference
    views_.reset();
    scene_ = std::make_unique<gpu::GlVoxelScene>(scene, context_.info());
    views_ = std::make_unique<gpu::GlVoxelViews>(*scene_);
    v2lf_ = std::make_unique<gpu::GlV2lfRenderer>(*scene_, context_.info());
  }
  void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    ensure_quilt(layout);
    views_->render_quilt(geometry, layout, {}, quilt_);
    glFinish();
  }
  voxel::V2lfStats render_v2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               const voxel::V2lfOptions& options) override {
    ensure_quilt(layout);
    gpu::GlV2lfOptions o;
    o.v2lf = options;
    v2lf_->render_quilt(geometry, layout, o, scene_->scene().background, quilt_);
    glFinish();
    voxel::V2lfStats stats;
    stats.planes = v2lf_->stats().planes;
    stats.plane_bytes = v2lf_->stats().plane_bytes;
    stats.voxels_binned = v2lf_->stats().voxels_binned;
    stats.voxels_split = v2lf_->stats().voxels_split;
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
  std::unique_ptr<gpu::GlVoxelScene> scene_;
  std::unique_ptr<gpu::GlVoxelViews> views_;
  std::unique_ptr<gpu::GlV2lfRenderer> v2lf_;
  gpu::Texture quilt_;
  ImageF image_;
};

}  // namespace

std::unique_ptr<VoxelQuiltRenderer> make_cpu_voxel_renderer() { return std::make_unique<CpuVoxelRenderer>(); }
std::unique_ptr<VoxelQuiltRenderer> make_gl_voxel_renderer() { return std::make_unique<GlVoxelRenderer>(); }

}  // namespace lfd::bench
