#include "lightfield/cpu_renderers.hpp"

#include <omp.h>

#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "interlace/direct_panel.hpp"
#include "util/process_memory.hpp"
#include "lightfield/renderer_checks.hpp"
#include "render/g2lf.hpp"
#include "render/per_view_quilt.hpp"
#include "voxel/v2lf.hpp"
#include "voxel/voxel_quilt.hpp"

namespace lfd::lightfield {
namespace {

// What the four CPU renderers share: the scene by reference, the quilt in memory, peak RSS.
class CpuRenderer : public LightFieldRenderer {
 public:
  CpuRenderer(const RendererOptions& options, scene::SceneKind kind) : options_(options), kind_(kind) {}

  std::string name() const override { return "cpu"; }
  std::string device() const override { return fmt::format("CPU, {} OpenMP threads", omp_get_max_threads()); }
  int default_runs() const override { return 3; }
  const RendererOptions& options() const override { return options_; }
  void set_options(const RendererOptions& options) override {
    check_same_renderer(options_, options);
    options_ = options;
  }
  void set_scene(const scene::Scene& scene) override {
    check_scene_kind(kind_, scene);
    scene_ = &scene;
  }
  const ImageF& read_quilt() override { return quilt_; }
  const ImageF& read_panel() override { return panel_; }
  ImageF take_quilt() override { return std::move(quilt_); }
  std::string memory_kind() const override { return "process RSS"; }
  void reset_peak_memory() override { reset_peak_rss(); }
  size_t peak_memory_bytes() const override { return peak_rss_bytes(); }

 protected:
  const scene::Scene& scene() const {
    if (!scene_) throw std::logic_error("LightFieldRenderer: set_scene before rendering");
    return *scene_;
  }

  // The direct pass's consumer of the planes: the panel into panel_ (interlace/direct_panel.hpp).
  render::PlaneConsumer direct_pass(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                                    const PanelOptions& panel, const glm::vec3& background) {
    interlace::DirectPanelOptions o;
    o.filter = options_.direct_filter;
    o.background = background;
    o.overscan = panel.overscan;
    o.invert_views = panel.invert_views;
    o.kernel = options_.direct_kernel;
    return [this, &geometry, &lens, o](const render::SweepingPlanes& planes, const render::ReferenceCamera& ref) {
      panel_ = interlace::render_direct_panel(planes, geometry, ref, lens, o);
    };
  }

  RendererOptions options_;
  ImageF quilt_;
  ImageF panel_;

 private:
  scene::SceneKind kind_;
  const scene::Scene* scene_ = nullptr;
};

class CpuGaussianRenderer : public CpuRenderer {
 public:
  explicit CpuGaussianRenderer(const RendererOptions& options) : CpuRenderer(options, scene::SceneKind::kGaussians) {}
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    return rgb_image(render::render_view(scene().gaussians(), geometry, view, options_.raster_settings()));
  }
};

class CpuGaussianViews final : public CpuGaussianRenderer {
 public:
  using CpuGaussianRenderer::CpuGaussianRenderer;
  QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    quilt_ = render::render_quilt_per_view(scene().gaussians(), geometry, layout, options_.raster_settings());
    return {};
  }
};

class CpuG2lf final : public CpuGaussianRenderer {
 public:
  using CpuGaussianRenderer::CpuGaussianRenderer;
  QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    render::G2lfStats s;
    quilt_ = render::render_quilt_g2lf(scene().gaussians(), geometry, layout, options_.planes,
                                       options_.raster_settings(), &s);
    return {.planes = s.planes, .plane_bytes = s.plane_bytes, .binned = s.gaussians_in_frustum,
            .seconds_binning = s.seconds_binning, .seconds_planes = s.seconds_planes,
            .seconds_swizzle = s.seconds_swizzle};
  }
  QuiltStats render_panel(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                          const PanelOptions& panel) override {
    render::G2lfStats s;
    const render::RasterSettings settings = options_.raster_settings();
    render::render_planes_g2lf(scene().gaussians(), geometry, options_.planes, settings,
                               direct_pass(geometry, lens, panel, settings.background), &s);
    return {.planes = s.planes, .plane_bytes = s.plane_bytes, .binned = s.gaussians_in_frustum,
            .seconds_binning = s.seconds_binning, .seconds_planes = s.seconds_planes,
            .seconds_swizzle = s.seconds_swizzle};
  }
};

class CpuVoxelRenderer : public CpuRenderer {
 public:
  explicit CpuVoxelRenderer(const RendererOptions& options) : CpuRenderer(options, scene::SceneKind::kVoxels) {}
  ImageF render_view(const render::QuiltGeometry& geometry, int view) override {
    return rgb_image(voxel::render_voxel_view(scene().voxels(), geometry, view, options_.voxel_settings()));
  }
};

class CpuVoxelViews final : public CpuVoxelRenderer {
 public:
  using CpuVoxelRenderer::CpuVoxelRenderer;
  QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    quilt_ = voxel::render_voxel_quilt_per_view(scene().voxels(), geometry, layout, options_.voxel_settings());
    return {};
  }
};

class CpuV2lf final : public CpuVoxelRenderer {
 public:
  using CpuVoxelRenderer::CpuVoxelRenderer;
  QuiltStats render_quilt(const render::QuiltGeometry& geometry, const render::QuiltLayout& layout) override {
    const scene::VoxelScene& voxels = scene().voxels();
    voxel::V2lfStats s;
    quilt_ = voxel::render_quilt_v2lf(voxels, geometry, layout, options_.v2lf(),
                                      options_.background.value_or(voxels.background), &s);
    return {.planes = s.planes, .plane_bytes = s.plane_bytes, .binned = s.voxels_binned,
            .voxels_split = s.voxels_split, .seconds_binning = s.seconds_binning,
            .seconds_planes = s.seconds_planes, .seconds_swizzle = s.seconds_swizzle};
  }
  QuiltStats render_panel(const render::QuiltGeometry& geometry, const display::LensModel& lens,
                          const PanelOptions& panel) override {
    const scene::VoxelScene& voxels = scene().voxels();
    voxel::V2lfStats s;
    voxel::render_planes_v2lf(voxels, geometry, options_.v2lf(),
                              direct_pass(geometry, lens, panel, options_.background.value_or(voxels.background)), &s);
    return {.planes = s.planes, .plane_bytes = s.plane_bytes, .binned = s.voxels_binned,
            .voxels_split = s.voxels_split, .seconds_binning = s.seconds_binning,
            .seconds_planes = s.seconds_planes, .seconds_swizzle = s.seconds_swizzle};
  }
};

}  // namespace

std::unique_ptr<LightFieldRenderer> make_cpu_gaussian_views(const RendererOptions& options) {
  return std::make_unique<CpuGaussianViews>(options);
}
std::unique_ptr<LightFieldRenderer> make_cpu_g2lf(const RendererOptions& options) {
  return std::make_unique<CpuG2lf>(options);
}
std::unique_ptr<LightFieldRenderer> make_cpu_voxel_views(const RendererOptions& options) {
  return std::make_unique<CpuVoxelViews>(options);
}
std::unique_ptr<LightFieldRenderer> make_cpu_v2lf(const RendererOptions& options) {
  return std::make_unique<CpuV2lf>(options);
}

}  // namespace lfd::lightfield
