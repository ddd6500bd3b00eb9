#pragma once
// The baseline: every quilt view rendered on its own with the reference rasterizer through its
// off-axis camera (paper: "conventional" quilt rendering, the ground truth of Table 1).
#include <cstdint>
#include <vector>

#include "scene/gaussian_scene.hpp"
#include "render/quilt_geometry.hpp"
#include "render/quilt_layout.hpp"
#include "render/rasterizer_cpu.hpp"
#include "util/image.hpp"

namespace lfd::render {

// A quilt layout of `cols` x `rows` tiles of the base camera's size for `geometry.views` views.
QuiltLayout make_quilt_layout(const QuiltGeometry& geometry, int cols, int rows);

// Copies an RGB raster (row 0 = top) into view `view`'s tile of a top-down quilt image.
void place_view(ImageF& quilt, const QuiltLayout& layout, int view, const RasterImage& image);

// Cuts view `view` out of a quilt image.
ImageF extract_view(const ImageF& quilt, const QuiltLayout& layout, int view);

// Renders view `view` alone (what `lfd render --view J` writes).
RasterImage render_view(const scene::GaussianScene& scene, const QuiltGeometry& geometry, int view,
                        const RasterSettings& settings = {});

ImageF render_quilt_per_view(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                             const QuiltLayout& layout, const RasterSettings& settings = {});

// The same with view j blended only where `pixel_masks[j]` (the view's size, row 0 = top) is
// non-zero (interlace/view_masks.hpp: the pixels the panel shows); the rest of each tile holds
// the background. Throws InputError when the masks do not match the views.
ImageF render_quilt_per_view_masked(const scene::GaussianScene& scene, const QuiltGeometry& geometry,
                                    const QuiltLayout& layout,
                                    const std::vector<std::vector<uint8_t>>& pixel_masks,
                                    const RasterSettings& settings = {});

}  // namespace lfd::render
