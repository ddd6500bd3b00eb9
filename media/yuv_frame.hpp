#pragma once
// A decoded video frame as YUV planes (docs/play.md "Video"): 8-bit 4:2:0 (Y full size, U and V
// half size rounded up), with the matrix and range the stream declares, handed to the player
// without a conversion so the GPU turns it into RGB (play/shaders/yuv_to_rgb.frag.glsl). The
// conversion's coefficients have one definition here, used by that shader (as uniforms) and by
// the CPU reference yuv_to_rgb below (tests, `lfd interlace`-style references).
#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "util/image.hpp"

namespace lfd::media {

enum class YuvMatrix { kBt601, kBt709, kBt2020 };
enum class YuvRange { kLimited, kFull };  // limited: Y in [16, 235], U/V in [16, 240]

// rgb = matrix * (yuv - offset), with yuv the 8-bit samples divided by 255 and rgb in [0, 1]
// before clamping; column-major 3x3 (GL's mat3 order: matrix[col * 3 + row]).
struct YuvToRgb {
  std::array<float, 9> matrix{};
  std::array<float, 3> offset{};
};
// The Kr/Kb of BT.601, BT.709 and BT.2020 (non-constant luminance) and the range's scaling.
YuvToRgb yuv_to_rgb_coefficients(YuvMatrix matrix, YuvRange range);

struct YuvPlane {
  const uint8_t* data = nullptr;
  int stride = 0;  // bytes per row
  int width = 0, height = 0;
};

struct YuvFrame {
  int width = 0, height = 0;     // of the picture (the Y plane)
  std::array<YuvPlane, 3> planes;  // Y, U (Cb), V (Cr)
  YuvMatrix matrix = YuvMatrix::kBt709;
  YuvRange range = YuvRange::kLimited;
  double pts_s = 0;              // presentation time from the stream's start
  int64_t index = 0;             // round(pts_s * frame rate)
  std::shared_ptr<const void> storage;  // keeps the planes alive (the decoder's frame)
};

// The CPU reference: RGB, rows top-down. Chroma is sampled bilinearly at each luma pixel's
// centre with clamped edges, as the GPU's linear filter samples the half-size U and V textures.
Image8 yuv_to_rgb(const YuvFrame& frame);

}  // namespace lfd::media
