#include "scene/scene.hpp"

#include <atomic>
#include <stdexcept>

#include "scene/gaussian_io.hpp"
#include "scene/voxel_io.hpp"

namespace lfd::scene {
namespace {

uint64_t next_scene_id() {
  static std::atomic<uint64_t> next{1};
  return next++;
}

}  // namespace

Scene::Scene(GaussianScene gaussians) : content_(std::move(gaussians)), id_(next_scene_id()) {}
Scene::Scene(VoxelScene voxels) : content_(std::move(voxels)), id_(next_scene_id()) {}

SceneKind Scene::kind() const {
  return std::holds_alternative<VoxelScene>(content_) ? SceneKind::kVoxels : SceneKind::kGaussians;
}

const GaussianScene& Scene::gaussians() const {
  if (kind() != SceneKind::kGaussians) throw std::logic_error("Scene: a voxel scene has no Gaussians");
  return std::get<GaussianScene>(content_);
}

const VoxelScene& Scene::voxels() const {
  if (kind() != SceneKind::kVoxels) throw std::logic_error("Scene: a Gaussian scene has no voxels");
  return std::get<VoxelScene>(content_);
}

size_t Scene::size() const { return kind() == SceneKind::kVoxels ? voxels().size() : gaussians().size(); }

const char* Scene::primitives() const { return kind() == SceneKind::kVoxels ? "voxels" : "Gaussians"; }

SceneKind scene_kind_of_file(const std::filesystem::path& path) {
  return is_voxel_scene_file(path) ? SceneKind::kVoxels : SceneKind::kGaussians;
}

Scene load_scene(const std::filesystem::path& path) {
  if (scene_kind_of_file(path) == SceneKind::kVoxels) return Scene(load_voxel_scene(path));
  return Scene(load_gaussian_scene(path));
}

}  // namespace lfd::scene
