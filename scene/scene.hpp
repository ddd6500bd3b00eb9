#pragma once
// A scene of either kind lfd renders: 3D Gaussians (3DGS; scene/gaussian_scene.hpp) or sparse
// voxels (SVRaster; scene/voxel_scene.hpp), chosen by the file (scene::is_voxel_scene_file).
// The kind decides the renderers (G2LF or V2LF for the sweeping planes;
// lightfield/renderer_factory.hpp) and the default framing (lightfield/scene_framing.hpp).
// Immutable once made, so a GL device can tell by id() whether it already holds a scene's upload.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <variant>

#include "scene/gaussian_scene.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::scene {

enum class SceneKind { kGaussians, kVoxels };

class Scene {
 public:
  explicit Scene(GaussianScene gaussians);
  explicit Scene(VoxelScene voxels);

  SceneKind kind() const;
  // The content; std::logic_error for the other kind.
  const GaussianScene& gaussians() const;
  const VoxelScene& voxels() const;

  size_t size() const;             // Gaussians or voxels
  const char* primitives() const;  // "Gaussians" | "voxels"
  // Distinct for every scene made (copies share it: the content is the same).
  uint64_t id() const { return id_; }

 private:
  std::variant<GaussianScene, VoxelScene> content_;
  uint64_t id_;
};

// The kind a scene file holds, by is_voxel_scene_file (reads only its first bytes).
SceneKind scene_kind_of_file(const std::filesystem::path& path);
// Reads either kind (load_gaussian_scene, load_voxel_scene); InputError for a bad file.
Scene load_scene(const std::filesystem::path& path);

}  // namespace lfd::scene
