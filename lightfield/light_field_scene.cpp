#include "lightfield/light_field_scene.hpp"

#include <atomic>
#include <stdexcept>

#include "render/default_camera.hpp"
#include "render/scene_io.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_io.hpp"

namespace lfd::lightfield {
namespace {

uint64_t next_scene_id() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

}  // namespace

LightFieldScene::LightFieldScene(render::GaussianScene gaussians)
    : content_(std::move(gaussians)), id_(next_scene_id()) {}
LightFieldScene::LightFieldScene(voxel::VoxelScene voxels) : content_(std::move(voxels)), id_(next_scene_id()) {}

SceneKind LightFieldScene::kind() const {
  return std::holds_alternative<voxel::VoxelScene>(content_) ? SceneKind::kVoxels : SceneKind::kGaussians;
}

const render::GaussianScene& LightFieldScene::gaussians() const {
  if (kind() != SceneKind::kGaussians) throw std::logic_error("LightFieldScene: a voxel scene has no Gaussians");
  return std::get<render::GaussianScene>(content_);
}

const voxel::VoxelScene& LightFieldScene::voxels() const {
  if (kind() != SceneKind::kVoxels) throw std::logic_error("LightFieldScene: a Gaussian scene has no voxels");
  return std::get<voxel::VoxelScene>(content_);
}

size_t LightFieldScene::size() const {
  return kind() == SceneKind::kVoxels ? voxels().size() : gaussians().size();
}

const char* LightFieldScene::primitives() const { return kind() == SceneKind::kVoxels ? "voxels" : "Gaussians"; }

render::CameraSpec LightFieldScene::framing(float fov_y_deg, float orbit_deg, float aspect) const {
  return kind() == SceneKind::kVoxels ? voxel::frame_voxel_scene(voxels(), fov_y_deg, orbit_deg)
                                      : render::frame_scene(gaussians(), fov_y_deg, orbit_deg, aspect);
}

SceneKind scene_kind_of_file(const std::filesystem::path& path) {
  return voxel::is_voxel_scene_file(path) ? SceneKind::kVoxels : SceneKind::kGaussians;
}

LightFieldScene load_light_field_scene(const std::filesystem::path& path) {
  if (scene_kind_of_file(path) == SceneKind::kVoxels) return LightFieldScene(voxel::load_voxel_scene(path));
  return LightFieldScene(render::load_scene(path));
}

}  // namespace lfd::lightfield
