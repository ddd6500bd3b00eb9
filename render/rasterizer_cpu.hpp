#pragma once
// The CPU reference rasterizer: the exact 3DGS forward pass of diff-gaussian-rasterization
// (docs/rendering.md "The CPU reference rasterizer"), in its three stages:
//   preprocess (per Gaussian) -> bin and sort (per 16x16 tile, by view-space depth) ->
//   blend (per pixel, front to back).
// All thresholds are the reference's: near cull z <= 0.2, 1.3 tan(fov/2) Jacobian clamp,
// +0.3 px^2 dilation, radius ceil(3 sqrt(lambda_max)), alpha = min(0.99, o exp(power)),
// skip power > 0 and alpha < 1/255, stop before T < 1e-4. Multithreaded with OpenMP.
// It is the oracle for every other renderer. Each stage has its own header (preprocess.hpp,
// tile_binning.hpp, blend.hpp) so a GPU pass can be compared with it stage by stage.
#include <cstdint>
#include <span>

#include "render/blend.hpp"
#include "render/camera.hpp"
#include "scene/gaussian_scene.hpp"
#include "render/preprocess.hpp"
#include "render/tile_binning.hpp"

namespace lfd::render {

// All three stages: preprocess -> bin_and_sort -> blend.
RasterImage rasterize(const scene::GaussianScene& scene, const Camera& camera,
                      const RasterSettings& settings = {}, std::span<const uint32_t> subset = {});

// The same with blend()'s pixel mask (width x height, row 0 = top): only the pixels it marks
// are blended, bit-identical to rasterize()'s; the others hold the background.
RasterImage rasterize_masked(const scene::GaussianScene& scene, const Camera& camera, std::span<const uint8_t> pixel_mask,
                             const RasterSettings& settings = {});

}  // namespace lfd::render
