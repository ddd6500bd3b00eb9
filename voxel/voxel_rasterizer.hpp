#pragma once
// The exact CPU sparse-voxel rasterizer: SVRaster's forward pass (docs/voxels.md, "The forward
// pass"), the oracle for V2LF and any GPU port. Per pixel, the voxels its tile overlaps in the
// order of the ray's sign octant (ray_order.hpp); per voxel a ray-box slab test, K samples of the
// scene::trilinear raw density through scene::exp_linear_11, tau = sum 100 dt sigma, alpha =
// min(0.99999, 1 - exp(-tau)), skip alpha < 1e-5, stop once T < 1e-4; colour = SH from the camera
// to the voxel centre (+0.5, clamped at 0); out = C + T background. Rendered at ss times the size
// and downsampled with antialiasing. Stages: preprocess (colour and screen rectangle per voxel),
// tile binning, per-tile order and per-pixel compositing. Multithreaded over tiles with OpenMP.
#include <optional>
#include <vector>

#include "render/blend.hpp"
#include "render/camera.hpp"
#include "voxel/ray_order.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

// SVRaster's constants.
inline constexpr float kStepScale = 100.0f;        // tau = sum 100 dt sigma
inline constexpr float kMaxAlpha = 0.99999f;
inline constexpr float kMinAlpha = 1e-5f;          // lighter voxels are skipped
inline constexpr float kMinTransmittance = 1e-4f;  // the ray stops below this

struct VoxelRenderSettings {
  std::optional<glm::vec3> background;    // default: the scene's
  std::optional<float> supersampling;     // default: the scene's ss; 1 = no supersampling
};

// The unit world direction of pixel (x, y)'s ray (centre at integer coordinates, row 0 = top,
// the principal-point shift applied); the GL raster's fragment shader computes the same.
glm::vec3 pixel_ray(const render::Camera& camera, int x, int y);

// One voxel's colour and sampled opacity along a ray, for tests and the GPU port: the
// transmittance factor of a box is exp(-tau), alpha as above (before the skip test).
float voxel_alpha(const scene::VoxelScene& scene, size_t voxel, const glm::vec3& origin, const glm::vec3& unit_direction);

// The image at the camera's size: rgb = C + T background, transmittance = T, both after the
// antialiased downsampling when ss > 1.
render::RasterImage rasterize_voxels(const scene::VoxelScene& scene, const render::Camera& camera,
                                     const VoxelRenderSettings& settings = {});

// The pass at the camera's own resolution (no supersampling) over only `subset` of the voxels
// (all if empty), SH evaluated from `sh_origin` (default the camera centre): with a zero
// background and the base camera as SH origin, what V2LF's sweeping planes are made of.
render::RasterImage rasterize_voxels_exact(const scene::VoxelScene& scene, const render::Camera& camera,
                                           const glm::vec3& background, const std::vector<uint32_t>& subset = {},
                                           std::optional<glm::vec3> sh_origin = std::nullopt);
// The same with the scene's front-to-back orders built once (`order` = RayOrder(scene)): V2LF
// renders a plane per chunk and would otherwise rebuild them for every one.
render::RasterImage rasterize_voxels_exact(const scene::VoxelScene& scene, const RayOrder& order, const render::Camera& camera,
                                           const glm::vec3& background, const std::vector<uint32_t>& subset = {},
                                           std::optional<glm::vec3> sh_origin = std::nullopt);

}  // namespace lfd::voxel
