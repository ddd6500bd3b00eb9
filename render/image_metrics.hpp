#pragma once
// Image quality metrics without OpenCV (the benchmark and `lfd compare` share them).
// Images are float RGB (or any channel count) with values in [0, 1]; peak value 1.
#include "util/image.hpp"

namespace lfd::render {

// 10 log10(1 / MSE) over all pixels and channels; +inf for identical images.
// Throws InputError when the sizes or channel counts differ.
double psnr(const ImageF& a, const ImageF& b);

// Mean SSIM (Wang et al. 2004): Gaussian window 11x11, sigma 1.5, K1 = 0.01, K2 = 0.03,
// L = 1, computed per channel over the 'valid' window positions (as the reference MATLAB
// ssim_index) and averaged over channels. Images smaller than 11x11 use their full size
// as the window bound. 1 for identical images.
double ssim(const ImageF& a, const ImageF& b);

}  // namespace lfd::render
