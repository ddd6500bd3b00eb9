#include "bench/voxel_quilt_renderer.hpp"

#include <omp.h>

#include <fmt/format.h>

#include "bench/process_memory.hpp"
#include "bench/gl_bench_target.hpp"
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
  std::string device() const override { return target_.info().summary(); }
  int default_runs() const override { return 10; }
  void set_scene(const voxel::VoxelScene& scene) override {
    v2lf_.reset();  // they hold the old scene by reference
    views_.reset();
    scene_ = std::make_unique<gpu::GlVoxelScene>(scene, target_.info());
    views_ = std::make_unique<gpu::GlVoxelViews>(*scene_);
    v2lf_ = std::make_unique<gpu::GlV2lfRenderer>(*scene_, target_.info());
  }
  void render_per_view(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    views_->render_quilt(geometry, layout, {}, target_.quilt(layout));
    glFinish();
  }
  voxel::V2lfStats render_v2lf(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout,
                               const voxel::V2lfOptions& options) override {
    gpu::GlV2lfOptions o;
    o.v2lf = options;
    v2lf_->render_quilt(geometry, layout, o, scene_->scene().background, target_.quilt(layout));
    glFinish();
    voxel::V2lfStats stats;
    stats.planes = v2lf_->stats().planes;
    stats.plane_bytes = v2lf_->stats().plane_bytes;
    stats.voxels_binned = v2lf_->stats().voxels_binned;
    stats.voxels_split = v2lf_->stats().voxels_split;
    return stats;
  }
  const ImageF& read_quilt() override { return target_.read_quilt(); }
  std::string memory_kind() const override { return GlBenchTarget::memory_kind(); }
  void reset_peak_memory() override { GlBenchTarget::reset_peak_memory(); }
  size_t peak_memory_bytes() const override { return GlBenchTarget::peak_memory_bytes(); }

 private:
  GlBenchTarget target_;  // first: the context outlives the renderers below
  std::unique_ptr<gpu::GlVoxelScene> scene_;
  std::unique_ptr<gpu::GlVoxelViews> views_;
  std::unique_ptr<gpu::GlV2lfRenderer> v2lf_;
};

}  // namespace

std::unique_ptr<VoxelQuiltRenderer> make_cpu_voxel_renderer() { return std::make_unique<CpuVoxelRenderer>(); }
std::unique_ptr<VoxelQuiltRenderer> make_gl_voxel_renderer() { return std::make_unique<GlVoxelRenderer>(); }

}  // namespace lfd::bench
