#include "lightfield/gl_device.hpp"

#include "gpu/splats/gl_per_view_renderer.hpp"
#include "gpu/planes/gl_swizzle.hpp"

namespace lfd::lightfield {

GlDevice::GlDevice(std::unique_ptr<gpu::HeadlessContext> context, const gpu::GlInfo& info)
    : context_(std::move(context)), info_(info) {}

GlDevice::~GlDevice() = default;

std::shared_ptr<GlDevice> GlDevice::open_headless() { return adopt(std::make_unique<gpu::HeadlessContext>()); }

std::shared_ptr<GlDevice> GlDevice::adopt(std::unique_ptr<gpu::HeadlessContext> context) {
  if (!context) return nullptr;
  const gpu::GlInfo info = context->info();
  return std::shared_ptr<GlDevice>(new GlDevice(std::move(context), info));
}

std::shared_ptr<GlDevice> GlDevice::on_current_context(const gpu::GlInfo& info) {
  return std::shared_ptr<GlDevice>(new GlDevice(nullptr, info));
}

void GlDevice::drop_scene() {
  gaussians_.reset();
  voxels_.reset();
  uploaded_id_ = 0;
  ++generation_;
}

void GlDevice::upload(const scene::Scene& scene) {
  if (scene.id() == uploaded_id_) return;
  if (scene.kind() == scene::SceneKind::kVoxels)
    upload(scene.voxels());
  else
    upload(scene.gaussians(), {});
  uploaded_id_ = scene.id();
}

void GlDevice::upload(const scene::GaussianScene& scene, const gpu::GlSceneOptions& options) {
  drop_scene();
  gaussians_ = std::make_shared<const gpu::GlScene>(scene, info_, options);
}

void GlDevice::upload(const scene::VoxelScene& scene) {
  drop_scene();
  voxels_ = std::make_shared<const gpu::GlVoxelScene>(scene, info_);
}

gpu::Texture& GlDevice::quilt(const render::QuiltLayout& layout, GLenum format) {
  if (quilt_.width() != layout.width || quilt_.height() != layout.height || quilt_.internal_format() != format)
    quilt_ = gpu::make_quilt_texture(layout, format);
  return quilt_;
}

const ImageF& GlDevice::read_quilt() {
  image_ = gpu::read_image_top_down(quilt_, 3);
  return image_;
}

void GlDevice::reset_peak_memory() { gpu::reset_gpu_peak(); }
size_t GlDevice::peak_memory_bytes() { return gpu::gpu_bytes_peak(); }

}  // namespace lfd::lightfield
