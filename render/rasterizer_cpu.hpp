#pragma once
// The CPU reference rasterizer: the exact 3DGS forward pass of diff-gaussian-rasterization
// (reference/gaussian-splatting.md sections 2-6), in its three stages:
//   preprocess (per Gaussian) -> bin and sort (per 16x16 tile, by view-space depth) ->
//   blend (per pixel, front to back).
// All thresholds are the reference's: near cull z <= 0.2, 1.3 tan(fov/2) Jacobian clamp,
// +0.3 px^2 dilation, radius ceil(3 sqrt(lambda_max)), alpha = min(0.99, o exp(power)),
// skip power > 0 and alpha < 1/255, stop before T < 1e-4. Multithreaded with OpenMP.
// It is the oracle for every other renderer.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.hpp"
#include "render/gaussian_scene.hpp"

namespace lfd::render {

constexpr int kTileSize = 16;  // BLOCK_X = BLOCK_Y (config.h)

struct RasterSettings {
  glm::vec3 background{0.0f};
  float dilation_px2 = 0.3f;     // low-pass variance added to the 2D covariance (section 3.3)
  float scale_modifier = 1.0f;
  int sh_degree = -1;            // -1: the scene's degree
  // World point the SH directions are taken from; default: the camera centre (section 3.6).
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

// Stage 1. `subset`: indices into the scene (empty: all). Output has one entry per input index.
std::vector<ProjectedGaussian> preprocess(const GaussianScene& scene, const Camera& camera,
                                          const RasterSettings& settings,
                                          std::span<const uint32_t> subset = {});

// Stage 2: per tile (row-major over the tile grid), the indices into `projected` front to back.
struct TileBins {
  int tiles_x = 0, tiles_y = 0;
  std::vector<uint32_t> range_begin;  // tiles_x * tiles_y + 1 offsets into `ids`
  std::vector<uint32_t> ids;
};
TileBins bin_and_sort(const std::vector<ProjectedGaussian>& projected, int width, int height);

// Stage 3 output: colour (row 0 = top, RGB interleaved, not clamped: out = C + T bg) and the
// final transmittance T per pixel.
struct RasterImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<float> transmittance;
};
RasterImage blend(const std::vector<ProjectedGaussian>& projected, const TileBins& bins, int width,
                  int height, const glm::vec3& background);

// All three stages.
RasterImage rasterize(const GaussianScene& scene, const Camera& camera,
                      const RasterSettings& settings = {}, std::span<const uint32_t> subset = {});

}  // namespace lfd::render
