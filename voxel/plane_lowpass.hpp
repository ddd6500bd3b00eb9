#pragma once
// V2LF's low-pass filter on the sweeping planes (paper section "V2LF": SVR antialiases by
// supersampling, which is too costly for N_chunk planes, so the planes are rendered without it
// and low-pass filtered with a Gaussian instead). The filter stands in for the supersampled
// view's downsampling filter: SVRaster's antialiased downsampling (voxel/antialias_downsample.hpp)
// weights with a triangle one output pixel wide each side, variance 1/6 px^2. That variance is
// taken at the focal plane and carried into plane texels as G2LF's Eq. gs_prefilter_fix carries
// 3DGS's 0.3 px^2 dilation (render::adaptive_filter_variance). A scene without supersampling
// (ss = 1) has no filter to match, so its planes are not filtered.
#include <vector>

#include "render/blend.hpp"
#include "render/quilt_geometry.hpp"
#include "scene/voxel_scene.hpp"

namespace lfd::voxel {

// Variance of the supersampled view's downsampling filter, in view pixels^2 (0 for ss = 1).
float view_antialias_variance(const scene::VoxelScene& scene);

// The Gaussian's variance in reference-camera texels^2 for planes at scale `plane_scale`.
float plane_lowpass_variance(const scene::VoxelScene& scene, const render::QuiltGeometry& geometry,
                             const render::ReferenceCamera& ref, int plane_scale);

// Separable Gaussian (cut at 3 sigma, edges clamped) on the premultiplied colour and the
// transmittance alike, which keeps the pair a consistent blend of the chunk; in place.
// Variances below 0.01 texel^2 leave the image as it is.
void gaussian_lowpass(render::RasterImage& image, float variance_px2);

// The filter's normalised 1D kernel (2 radius + 1 taps, radius = max(1, ceil(3 sigma))); empty
// below 0.01 texel^2. The GL planes' pass uses the same weights (gpu/voxels/gl_v2lf.cpp).
std::vector<float> gaussian_lowpass_kernel(float variance_px2);

}  // namespace lfd::voxel
