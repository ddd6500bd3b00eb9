#pragma once
// Stage 1 of the 3DGS forward pass, per Gaussian (diff-gaussian-rasterization forward.cu
// preprocessCUDA; docs/rendering.md "The CPU reference rasterizer"): near cull, 3D covariance from
// scale and rotation, EWA projection to a 2D conic with the +0.3 px^2 low-pass dilation, the
// 3-sigma radius and the rectangle of 16x16 tiles it touches, and the SH colour seen from
// the SH origin. Each Gaussian is independent, which is why this stage runs once per Gaussian
// and not once per pixel; tile binning and blending only read its output.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "scene/gaussian_scene.hpp"

namespace lfd::render {

constexpr int kTileSize = 16;  // BLOCK_X = BLOCK_Y (config.h)

// Settings of the whole forward pass (preprocess reads all but the background, blend that).
struct RasterSettings {
  glm::vec3 background{0.0f};
  float dilation_px2 = 0.3f;     // low-pass variance added to the 2D covariance (computeCov2D)
  float scale_modifier = 1.0f;
  int sh_degree = -1;            // -1: the scene's degree
  // World point the SH directions are taken from; default: the camera centre (preprocessCUDA).
  // G2LF bakes the base camera's colours into planes rendered from the reference camera.
  std::optional<glm::vec3> sh_origin;
};

// One Gaussian after preprocessing (forward.cu preprocessCUDA outputs).
struct ProjectedGaussian {
  glm::vec2 mean_px{0.0f};   // points_xy_image
  glm::vec3 conic{0.0f};     // inverse 2D covariance (xx, xy, yy)
  float opacity = 0.0f;
  float depth = 0.0f;        // view-space z
  glm::vec3 color{0.0f};
  int radius_px = 0;         // 0: culled
  glm::ivec2 rect_min{0}, rect_max{0};  // tile rectangle, max exclusive
};

// The 3D covariance R S S^T R^T of a Gaussian (computeCov3D; scale linear, modifier multiplies
// it, quaternion (w, x, y, z)); also what voxelization spreads each Gaussian's mass with.
glm::mat3 covariance_3d(const std::array<float, 3>& scale, float modifier, const std::array<float, 4>& q);

// `subset`: indices into the scene (empty: all). Output has one entry per input index, culled
// Gaussians with radius_px = 0, so indices stay aligned with the input.
std::vector<ProjectedGaussian> preprocess(const scene::GaussianScene& scene, const Camera& camera,
                                          const RasterSettings& settings,
                                          std::span<const uint32_t> subset = {});

}  // namespace lfd::render
