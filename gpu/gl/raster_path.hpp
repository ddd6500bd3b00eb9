#pragma once
// Which pipeline draws splats on the GPU (docs/gpu.md "Two ways to draw Gaussians"):
//   kHardware  instanced quads through the raster pipeline, blended by the ROPs (GlSplatRaster,
//              GlPlaneRaster): fast where every SM can rasterize (desktop GPUs);
//   kCompute   a tile rasterizer in compute shaders (the reference's forward pass: keys per
//              (image, tile, depth), one sort, per-tile ranges, compositing in shared memory):
//              uses the whole chip where only a few SMs rasterize (H100/H200);
//   kAuto      one of the two, chosen by a measurement on the device (resolve_raster_path).
// `--raster compute|hardware|auto` on the commands that render Gaussians on the GPU.
#include <string>
#include <string_view>

namespace lfd::gpu {

enum class RasterPath { kHardware, kCompute, kAuto };

// "hardware" | "compute" | "auto".
const char* raster_path_name(RasterPath path);
// InputError "--raster: 'x' is not compute, hardware or auto" for another name.
RasterPath parse_raster_path(std::string_view name);

}  // namespace lfd::gpu
