#include "viewer/viewer_scene.hpp"

#include <fmt/format.h>

#include "render/default_camera.hpp"
#include "render/scene_io.hpp"
#include "voxel/voxel_generator.hpp"
#include "voxel/voxel_io.hpp"

namespace lfd::viewer {

size_t ViewerScene::size() const { return voxels() ? voxel_scene().size() : gaussians().size(); }

std::string ViewerScene::describe() const {
  return fmt::format("{} {}", size(), voxels() ? "voxels" : "Gaussians");
}

render::CameraSpec ViewerScene::framing() const {
  return voxels() ? voxel::frame_voxel_scene(voxel_scene()) : render::frame_scene(gaussians());
}

ViewerScene load_viewer_scene(const std::string& path) {
  ViewerScene scene;
  if (voxel::is_voxel_scene_file(path))
    scene.content = voxel::load_voxel_scene(path);
  else
    scene.content = render::load_scene(path);
  return scene;
}

}  // namespace lfd::viewer
