#pragma once
// One row of one sweeping plane as every ray of a panel row reads it (render/plane_rays.hpp,
// docs/performance.md "Where the direct pass's time went"): the rays of a panel row all sample
// a plane at the same vertical coordinate, so the plane's two rows are blended with the
// bilinear weight fy once per row (for nearest: the nearest row alone), not once per ray, into
// float channel arrays padded with empty texels (no bounds test per sample), and the columns
// where the blended row is not empty are listed as runs, so a ray whose sample falls between
// them is not visited at all.
#include <array>
#include <vector>

#include "render/sweeping_planes.hpp"

namespace lfd::render {

struct BlendedPlaneRow {
  // Empty texels (0, 0, 0, T = 1) stored either side of the non-empty columns.
  static constexpr int kPad = 2;
  int first_column = 0;  // plane column of array index 0 (the first non-empty one - kPad)
  int length = 0;        // texels stored per channel, pads included
  int stride = 0;        // floats between two channels' arrays: stride_for(planes), every row
  // The same for every row of the planes, so a ray's channel offset is computed once.
  static int stride_for(const SweepingPlanes& planes) { return (planes.width + 2 * kPad + 15) & ~15; }
  std::vector<float> values;  // R, G, B (premultiplied) and T, `stride` floats each
  // Non-empty plane columns [a, b], increasing; runs closer than kMergeGap texels are merged
  // (a few empty samples cost less than another window of rays).
  static constexpr int kMergeGap = 3;
  std::vector<std::array<int, 2>> runs;

  const float* channel(int c) const { return values.data() + size_t(c) * size_t(stride); }
};

// Row `row0` of plane k blended with row `row1` by weight fy (bilinear) or row0 alone (nearest,
// fy unused), as a sample of the swizzle blend reads them (rows outside the plane are empty).
// Returns false, leaving `out` unspecified, when both rows are empty.
bool blend_plane_row(const SweepingPlanes& planes, int k, int row0, int row1, float fy, bool bilinear,
                     BlendedPlaneRow& out);

}  // namespace lfd::render
