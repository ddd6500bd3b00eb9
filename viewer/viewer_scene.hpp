#pragma once
// What `lfd view` shows: a Gaussian scene (3DGS: G2LF or per view) or a sparse-voxel scene
// (SVRaster: V2LF or per view), chosen by the file (voxel::is_voxel_scene_file), so one window
// and one drop target take both.
#include <string>
#include <variant>

#include "render/camera_json.hpp"
#include "render/gaussian_scene.hpp"
#include "voxel/voxel_scene.hpp"

namespace lfd::viewer {

struct ViewerScene {
  std::variant<render::GaussianScene, voxel::VoxelScene> content;

  bool voxels() const { return std::holds_alternative<voxel::VoxelScene>(content); }
  const render::GaussianScene& gaussians() const { return std::get<render::GaussianScene>(content); }
  const voxel::VoxelScene& voxel_scene() const { return std::get<voxel::VoxelScene>(content); }
  size_t size() const;
  std::string describe() const;  // "152000 Gaussians" | "63437 voxels"
  // The default camera: render::frame_scene or voxel::frame_voxel_scene.
  render::CameraSpec framing() const;
};

// Reads either kind; InputError (one line naming the file) for anything else or a bad file.
ViewerScene load_viewer_scene(const std::string& path);

}  // namespace lfd::viewer
