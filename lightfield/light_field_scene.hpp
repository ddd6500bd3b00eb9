#pragma once
// What a light-field renderer renders: a scene of 3D Gaussians (3DGS; render/gaussian_scene.hpp)
// or of sparse voxels (SVRaster; voxel/voxel_scene.hpp), chosen by the file
// (voxel::is_voxel_scene_file). The kind decides the renderers (G2LF or V2LF for the sweeping
// planes; lightfield/renderer_factory.hpp) and the default framing. Immutable once made, so a
// GL device can tell by id() whether it already holds a scene's upload.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>

#include "render/camera_json.hpp"
#include "render/gaussian_scene.hpp"
#include "voxel/voxel_scene.hpp"

namespace lfd::lightfield {

enum class SceneKind { kGaussians, kVoxels };

class LightFieldScene {
 public:
  explicit LightFieldScene(render::GaussianScene gaussians);
  explicit LightFieldScene(voxel::VoxelScene voxels);

  SceneKind kind() const;
  // The content; std::logic_error for the other kind.
  const render::GaussianScene& gaussians() const;
  const voxel::VoxelScene& voxels() const;

  size_t size() const;             // Gaussians or voxels
  const char* primitives() const;  // "Gaussians" | "voxels"
  // The default camera: render::frame_scene or voxel::frame_voxel_scene.
  // `aspect` (view width / height) is used by the Gaussian framing.
  render::CameraSpec framing(float fov_y_deg, float orbit_deg = 0.0f, float aspect = 1.0f) const;
  // Distinct for every scene made (copies share it: the content is the same).
  uint64_t id() const { return id_; }

 private:
  std::variant<render::GaussianScene, voxel::VoxelScene> content_;
  uint64_t id_;
};

// The kind a scene file holds, by voxel::is_voxel_scene_file (reads only its first bytes).
SceneKind scene_kind_of_file(const std::filesystem::path& path);
// Reads either kind (render::load_scene, voxel::load_voxel_scene); InputError for a bad file.
LightFieldScene load_light_field_scene(const std::filesystem::path& path);

}  // namespace lfd::lightfield
