#pragma once
// SVRaster renders at ss times the size and downsamples with antialiasing (PyTorch's
// interpolate(mode="bilinear", antialias=True)): a separable triangle filter whose support
// widens with the scale factor, weights normalised per output pixel.
#include <vector>

namespace lfd::voxel {

// `channels` interleaved floats per pixel, row 0 = top; returns out_width x out_height.
std::vector<float> antialias_downsample(const std::vector<float>& in, int width, int height, int channels,
                                        int out_width, int out_height);

}  // namespace lfd::voxel
